#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/number_traits.h>
#include <wetbed/closures/wet/liquid_bridge.h>

#include <memory>
#include <string>

namespace wetbed::closures
{
/**
 * Restitution coefficient of wet collisions e_wet(contact), for double and ADNumber. It
 * enters only the collisional dissipation gamma (seed 000 Eq. 9); every other
 * kinetic-theory term keeps e_dry. Laws are structs with `template <class Number> static
 * Number value(contact, liquid, particle)` in their own file, registered in
 * source/closures/wet/wet_registry.cc.
 */
class WetRestitution
{
public:
  virtual ~WetRestitution ()                                            = default;
  virtual std::string name () const                                     = 0;
  virtual double      value (const WetContact<double>     &contact,
                             const LiquidBridgeProperties &liquid,
                             const WetParticleMaterial    &particle) const = 0;
  virtual ADNumber    value (const WetContact<ADNumber>   &contact,
                             const LiquidBridgeProperties &liquid,
                             const WetParticleMaterial    &particle) const = 0;
};

template <class Law>
class WetRestitutionFromLaw : public WetRestitution
{
public:
  std::string name () const override { return Law::name; }
  double      value (const WetContact<double>     &contact,
                     const LiquidBridgeProperties &liquid,
                     const WetParticleMaterial    &particle) const override
  {
    return Law::template value<double> (contact, liquid, particle);
  }
  ADNumber value (const WetContact<ADNumber>   &contact,
                  const LiquidBridgeProperties &liquid,
                  const WetParticleMaterial    &particle) const override
  {
    return Law::template value<ADNumber> (contact, liquid, particle);
  }
};

/** e_dry max(0, 1 - St^* / St): the Stokes law of a bridged collision (seed 000 Eq. 10),
 * 0 for St <= St* (no rebound), at most e_dry (St* < 0 below the asperity height).
 * Continuous in St. */
template <class Number>
Number bridged_restitution (const WetContact<Number> &contact,
                            const double              dry_restitution)
{
  const Number r = 1.0 - contact.critical_stokes / contact.stokes;
  return select_greater (
      r,
      0.0,
      select_less (r, 1.0, Number (dry_restitution * r), Number (dry_restitution)),
      Number (0.0));
}

std::unique_ptr<WetRestitution> create_wet_restitution (const std::string &name);
std::string                     wet_restitution_names ();
} // namespace wetbed::closures
