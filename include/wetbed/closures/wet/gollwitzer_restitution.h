#pragma once

#include <wetbed/closures/wet/wet_restitution.h>

namespace wetbed::closures
{
/**
 * Gollwitzer et al. (2012) fit for a collision through a liquid film of thickness
 * delta_f (seed 003 Eq. 26):
 *   e = (e_dry - 3/2 (rho_L/rho_s) (delta_f/d) / e_dry) (1 - 14/St),
 * clipped to [0, e_dry]. A film, not a bridge: not gated by the gap window.
 */
struct GollwitzerRestitution
{
  static constexpr const char *name = "Gollwitzer";
  template <class Number>
  static Number value (const WetContact<Number>     &contact,
                       const LiquidBridgeProperties &liquid,
                       const WetParticleMaterial    &particle)
  {
    const double e         = particle.dry_restitution;
    const double film_loss = 1.5 * liquid.liquid_density / particle.particle_density *
                             liquid.film_thickness / e;
    const Number value = (e - film_loss) * (1.0 - 14.0 / contact.stokes);
    return select_less (
        value, 0.0, Number (0.0), select_greater (value, e, Number (e), value));
  }
};
} // namespace wetbed::closures
