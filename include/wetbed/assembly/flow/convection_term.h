#pragma once

#include <wetbed/assembly/flow/flow_term.h>

namespace wetbed
{
/**
 * Oseen convection alpha_k rho_k (u_k*.grad) u_k and, where stabilized, streamline
 * diffusion: the convective part of the SUPG residual weighted by tau_k alpha_k rho_k
 * (u_k*.grad v). tau_k includes the time, convection, viscous and drag rates, so it
 * vanishes where drag dominates (the bed) and acts like upwinding in the freeboard.
 * Symmetric, so the AMG keeps working (the full SUPG residual with its pressure and
 * drag terms did not).
 */
template <int dim>
class ConvectionTerm : public FlowTerm<dim>
{
public:
  explicit ConvectionTerm (bool streamline_diffusion)
      : streamline_diffusion (streamline_diffusion)
  {
  }
  std::string name () const override { return "convection"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;

  bool has_coefficients () const override { return true; }
  void coefficients (const FlowCellScratch<dim>   &scratch,
                     const FlowAssemblyState<dim> &state,
                     unsigned int                  q,
                     FlowPointCoefficients<dim>   &coefficients) const override;
  /** tau_k alpha_k^2 rho_k^2, the streamline-diffusion weight of phase k at point q
   * (0 without stabilization). */
  double supg (const FlowCellScratch<dim>   &scratch,
               const FlowAssemblyState<dim> &state,
               unsigned int                  q,
               unsigned int                  k) const;

private:
  bool streamline_diffusion;
};
} // namespace wetbed
