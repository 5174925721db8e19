#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/core/momentum_form.h>

#include <utility>

namespace wetbed
{
/**
 * BDF inertia a0 alpha_k rho_k u_k / dt with its history on the right-hand side
 * (doc/theory.md, "Time discretisation" and "Momentum equations"). In the conservative
 * form each history level carries its own volume fraction, and rho_k div(alpha_k* u_k*)
 * u_k is added, implicit where positive (mass added), with the lagged u_k* where
 * negative (the diagonal stays positive). In the skew-symmetric form the time
 * derivative is the mean of the conservative and the advective ones, the latter
 * weighted by the old fraction (rho_k ((alpha* + alpha^n)/2 u^{n+1} - alpha^n u^n)/dt
 * for BDF1), and rho_k div(alpha_k* u_k*) u_k / 2 is implicit: tested with u_k^{n+1}
 * the inertia and convection then change only the kinetic energy, whatever the
 * continuity residual of the discrete volume fractions.
 */
template <int dim>
class InertiaTerm : public FlowTerm<dim>
{
public:
  InertiaTerm (const FlowMaterial<dim> &material, MomentumForm form)
      : material (material), form (form)
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
   * conservative form, rho_k max(div(alpha_k u_k), 0); skew-symmetric: a0 rho_k (alpha_k*
   * + alpha_k^n)/2 / dt + rho_k div(alpha_k u_k)/2, no less than half its first part
   * (the rest lagged). */
  double mass (const FlowCellScratch<dim> &scratch, unsigned int q, unsigned int k) const;

private:
  /** (the whole mass coefficient, its implicit part): they differ where the
   * conservative form's divergence is negative or the skew-symmetric coefficient falls
   * below half its time part; the difference goes to the rhs with the lagged u*. */
  std::pair<double, double> mass_coefficient (const FlowCellScratch<dim> &scratch,
                                              unsigned int                q,
                                              unsigned int                k) const;

  FlowMaterial<dim> material;
  MomentumForm      form;
};
} // namespace wetbed
