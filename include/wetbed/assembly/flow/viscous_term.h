#pragma once

#include <wetbed/assembly/flow/flow_term.h>

namespace wetbed
{
/** The phase stresses tau_k = 2 mu_k D(u_k) + b_k (div u_k) I: mu_g alpha_g and
 * b_g = -2/3 alpha_g mu_g for the gas, mu_s and b_s = lambda_s - 2/3 mu_s for the solids
 * (MFIX convention: mu_s and lambda_s carry alpha_s). */
template <int dim>
class ViscousTerm : public FlowTerm<dim>
{
public:
  ViscousTerm () = default;
  std::string name () const override { return "viscous stress"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;

  bool has_coefficients () const override { return true; }
  void coefficients (const FlowCellScratch<dim>   &scratch,
                     const FlowAssemblyState<dim> &state,
                     unsigned int                  q,
                     FlowPointCoefficients<dim>   &coefficients) const override;

private:
  // no data: the viscosities come from the scratch
};
} // namespace wetbed
