#pragma once

#include <wetbed/closures/wet/wet_restitution.h>

namespace wetbed::closures
{
/**
 * Seed 000 Eq. 11, bridge-gated reading (the default; doc/theory.md, "Wet closures"): a
 * collision feels the liquid only where a bridge exists, h_a < h <= h_c:
 *   e = e_dry max(0, 1 - St^* / St)  inside the window,
 *   e = e_dry                     for h > h_c (bridges ruptured) or h <= h_a (dry
 *                                 frictional contact),
 * with the window edges smoothed (WetContact::above_asperity, ::bridged).
 */
struct BridgeGatedRestitution
{
  static constexpr const char *name = "bridge-gated";
  template <class Number>
  static Number value (const WetContact<Number> &contact,
                       const LiquidBridgeProperties & /*liquid*/,
                       const WetParticleMaterial &particle)
  {
    const double e      = particle.dry_restitution;
    const Number window = contact.above_asperity * contact.bridged;
    return (1.0 - window) * e + window * bridged_restitution (contact, e);
  }
};
} // namespace wetbed::closures
