#pragma once

#include <wetbed/closures/wet/wet_restitution.h>

namespace wetbed::closures
{
/**
 * Seed 000 Eq. 11 read literally (option): for any h > h_a a collision with St <= St*
 * does not rebound (e = 0), also beyond the rupture distance; with St > St*, e =
 * e_dry(1 - St^* / St) inside the window and e_dry beyond it; e_dry for h <= h_a. The St*
 * switch beyond h_c is a jump, smoothed over the switch width (relative to St*).
 */
struct LiteralRestitution
{
  static constexpr const char *name = "literal";
  template <class Number>
  static Number value (const WetContact<Number>     &contact,
                       const LiquidBridgeProperties &liquid,
                       const WetParticleMaterial    &particle)
  {
    using std::abs;
    const double e = particle.dry_restitution;
    // relative distance to the critical Stokes number, switched over the switch width
    const Number excess = (contact.stokes - contact.critical_stokes) /
                          (abs (contact.critical_stokes) + 1e-300);
    const Number rebound = smooth_step (excess, liquid.switch_width);
    const Number beyond  = e * rebound;
    const Number inside  = bridged_restitution (contact, e);
    return (1.0 - contact.above_asperity) * e +
           contact.above_asperity *
               (contact.bridged * inside + (1.0 - contact.bridged) * beyond);
  }
};
} // namespace wetbed::closures
