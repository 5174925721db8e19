#pragma once

#include <wetbed/closures/wet/rupture_distance.h>

#include <cmath>

namespace wetbed::closures
{
/** Lian et al. (1993): h_c = 1/2 (1 + gamma_c/2) d (V*)^(1/3) (seed 000 Eq. 8, seed 002
 * Eq. 34); the default. */
struct LianRuptureDistance
{
  static constexpr const char *name = "Lian";
  template <class Number>
  static Number value (const Number & /*approach_velocity*/,
                       const LiquidBridgeProperties &liquid,
                       const WetParticleMaterial    &particle)
  {
    return Number (0.5 * (1.0 + 0.5 * liquid.contact_angle) * particle.particle_diameter *
                   std::cbrt (bridge_volume (liquid, particle)));
  }
};
} // namespace wetbed::closures
