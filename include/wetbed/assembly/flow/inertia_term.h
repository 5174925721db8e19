#pragma once

#include <wetbed/assembly/flow/flow_term.h>

namespace wetbed
{
/**
 * BDF inertia a0 alpha_k rho_k u_k / dt with its history on the right-hand side
 * (doc/theory.md, "Time discretisation"). In the conservative form each history level
 * carries its own volume fraction, and rho_k div(alpha_k* u_k*) u_k is added, implicit
 * where positive (mass added), with the lagged u_k* where negative (the diagonal stays
 * positive).
 */
template <int dim>
class InertiaTerm : public FlowTerm<dim>
{
public:
  InertiaTerm (const FlowMaterial<dim> &material, bool conservative)
      : material (material), conservative (conservative)
  {
  }
  std::string name () const override { return "inertia"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;

  bool has_coefficients () const override { return true; }
  void coefficients (const FlowCellScratch<dim>   &scratch,
                     const FlowAssemblyState<dim> &state,
                     unsigned int                  q,
                     FlowPointCoefficients<dim>   &coefficients) const override;
  /** The mass coefficient of phase k at point q: a0 alpha_k rho_k / dt and, in the
   * conservative form, rho_k max(div(alpha_k u_k), 0). */
  double mass (const FlowCellScratch<dim> &scratch, unsigned int q, unsigned int k) const;

private:
  FlowMaterial<dim> material;
  bool              conservative;
};
} // namespace wetbed
