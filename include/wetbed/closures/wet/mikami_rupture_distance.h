#pragma once

#include <wetbed/closures/wet/rupture_distance.h>

#include <cmath>

namespace wetbed::closures
{
/** Mikami et al. (1998) regression, particle-particle: h_c / R = (0.62 gamma_c + 0.99)
 * (V*)^0.34 (seed 002 Eq. 36). */
struct MikamiRuptureDistance
{
  static constexpr const char *name = "Mikami";
  template <class Number>
  static Number value (const Number & /*approach_velocity*/,
                       const LiquidBridgeProperties &liquid,
                       const WetParticleMaterial    &particle)
  {
    return Number (0.5 * particle.particle_diameter *
                   (0.62 * liquid.contact_angle + 0.99) *
                   std::pow (bridge_volume (liquid, particle), 0.34));
  }
};
} // namespace wetbed::closures
