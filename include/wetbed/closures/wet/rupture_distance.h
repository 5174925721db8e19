#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/wet/liquid_bridge.h>

#include <memory>
#include <string>

namespace wetbed::closures
{
/**
 * Rupture distance h_c of a liquid bridge, a function of the approach velocity (Pitois
 * depends on it), for double and ADNumber. The bridge volume per R^3 is read as seed 000
 * Eq. 8 does: V* = delta rho_s / rho_L. Laws are structs with `template <class Number>
 * static Number value(u_dot, liquid, particle)` in their own file
 * (lian_rupture_distance.h, ...), registered in source/closures/wet/wet_registry.cc.
 */
class RuptureDistance
{
public:
  virtual ~RuptureDistance ()                                           = default;
  virtual std::string name () const                                     = 0;
  virtual double      value (double                        approach_velocity,
                             const LiquidBridgeProperties &liquid,
                             const WetParticleMaterial    &particle) const = 0;
  virtual ADNumber    value (const ADNumber               &approach_velocity,
                             const LiquidBridgeProperties &liquid,
                             const WetParticleMaterial    &particle) const = 0;
};

template <class Law>
class RuptureDistanceFromLaw : public RuptureDistance
{
public:
  std::string name () const override { return Law::name; }
  double      value (double                        approach_velocity,
                     const LiquidBridgeProperties &liquid,
                     const WetParticleMaterial    &particle) const override
  {
    return Law::template value<double> (approach_velocity, liquid, particle);
  }
  ADNumber value (const ADNumber               &approach_velocity,
                  const LiquidBridgeProperties &liquid,
                  const WetParticleMaterial    &particle) const override
  {
    return Law::template value<ADNumber> (approach_velocity, liquid, particle);
  }
};

/** V* = delta rho_s / rho_L, the bridge volume per R^3 of seed 000 Eq. 8. */
inline double bridge_volume (const LiquidBridgeProperties &liquid,
                             const WetParticleMaterial    &particle)
{
  return liquid.liquid_loading * particle.particle_density / liquid.liquid_density;
}

std::unique_ptr<RuptureDistance> create_rupture_distance (const std::string &name);
std::string                      rupture_distance_names ();
} // namespace wetbed::closures
