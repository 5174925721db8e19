#pragma once

#include <wetbed/closures/wet/liquid_bridge.h>
#include <wetbed/closures/wet/rupture_distance.h>
#include <wetbed/closures/wet/wet_restitution.h>

#include <memory>
#include <string>

namespace wetbed::closures
{
/** Every wet closure at one point, for output and for the solids stress. */
struct WetClosures
{
  double gap;               // h (m), Woodcock (negative above alpha_s = 0.6)
  double rupture_distance;  // h_c (m)
  double approach_velocity; // u_dot (m/s)
  double window;            // bridged-contact weight in [0, 1] (1: h_a < h <= h_c)
  double approach_weight;   // 1, or < 1 where the solids separate (approach only)
  double pressure;          // P_wet (Pa), the window and approach weight applied
  double viscosity;         // mu_wet (Pa s), capped
  double stokes;            // St
  double critical_stokes;   // St*
  double restitution;       // e_wet (dissipation only)

  /** "contact" (h <= h_a), "bridged" (h_a < h <= h_c) or "ruptured" (h > h_c). */
  std::string regime (double asperity) const;
};

/**
 * The wet-particle closures of seed 000 s3 (doc/theory.md, "Wet closures"): gap,
 * rupture distance (law by name), approach velocity, P_wet, mu_wet, St, St*, e_wet (law
 * by name). Constructed only when the liquid loading is positive: a dry scene has no
 * WetParticles object and evaluates none of this.
 */
class WetParticles
{
public:
  WetParticles (const LiquidBridgeProperties &liquid,
                const WetParticleMaterial    &particle,
                const std::string            &rupture_distance_law,
                const std::string            &restitution_law);
  ~WetParticles ();

  /** The contact state (gap, h_c, window indicators, St, St*) at (alpha_s, Theta). */
  template <typename Number>
  WetContact<Number> contact (const Number &alpha_s, const Number &theta) const;

  /** All closures; second_invariant = I_2D of the solids strain rate,
   * velocity_divergence = div u_s (1/s; used by `lubrication stress = approach only`). */
  WetClosures evaluate (double alpha_s,
                        double theta,
                        double second_invariant,
                        double velocity_divergence) const;

  /** e_wet alone (the collisional dissipation). */
  double restitution (double alpha_s, double theta) const;

  const LiquidBridgeProperties &liquid () const { return liquid_properties; }
  const RuptureDistance        &rupture_distance_law () const { return *rupture; }
  const WetRestitution         &restitution_law () const { return *wet_restitution; }

private:
  LiquidBridgeProperties           liquid_properties;
  WetParticleMaterial              particle;
  std::unique_ptr<RuptureDistance> rupture;
  std::unique_ptr<WetRestitution>  wet_restitution;
};
} // namespace wetbed::closures
