#pragma once

#include <wetbed/assembly/flow/flow_term.h>

namespace wetbed
{
/** The shared pressure in both momentum equations, -(p', div(alpha_k v_k)), and its
 * transpose, the mixture continuity -(q, div(alpha_g u_g + alpha_s u_s)) = 0. */
template <int dim>
class PressureCouplingTerm : public FlowTerm<dim>
{
public:
  PressureCouplingTerm () = default;
  std::string name () const override { return "pressure coupling"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;

  bool has_coefficients () const override { return true; }
  void coefficients (const FlowCellScratch<dim>   &scratch,
                     const FlowAssemblyState<dim> &state,
                     unsigned int                  q,
                     FlowPointCoefficients<dim>   &coefficients) const override;

private:
  // no data
};
} // namespace wetbed
