#pragma once

#include <wetbed/closures/wet/lian_rupture_distance.h>

#include <cmath>

namespace wetbed::closures
{
/** Pitois et al. (2001): Lian's h_c times (1 + Ca^(1/2)), Ca = mu_L u_dot / sigma the
 * capillary number of the approach (seed 002 Eq. 35); equal to Lian as Ca -> 0. */
struct PitoisRuptureDistance
{
  static constexpr const char *name = "Pitois";
  template <class Number>
  static Number value (const Number                 &approach_velocity,
                       const LiquidBridgeProperties &liquid,
                       const WetParticleMaterial    &particle)
  {
    using std::sqrt;
    const Number capillary =
        liquid.liquid_viscosity * approach_velocity / liquid.surface_tension;
    return (1.0 + sqrt (capillary)) *
           LianRuptureDistance::value (approach_velocity, liquid, particle);
  }
};
} // namespace wetbed::closures
