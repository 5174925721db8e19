#pragma once

#include <wetbed/assembly/flow/flow_term.h>

namespace wetbed
{
/** The implicit interphase drag beta (u_g - u_s) in both momentum equations, beta at the
 * inertial fraction (the ClosureEvaluator's coupling drag). */
template <int dim>
class DragCouplingTerm : public FlowTerm<dim>
{
public:
  DragCouplingTerm () = default;
  std::string name () const override { return "drag coupling"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;

  bool has_coefficients () const override { return true; }
  void coefficients (const FlowCellScratch<dim>   &scratch,
                     const FlowAssemblyState<dim> &state,
                     unsigned int                  q,
                     FlowPointCoefficients<dim>   &coefficients) const override;

private:
  // no data: beta comes from the cell's closures
};
} // namespace wetbed
