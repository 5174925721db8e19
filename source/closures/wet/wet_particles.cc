#include <wetbed/closures/wet/wet_particles.h>

#include <algorithm>
#include <cmath>

namespace wetbed::closures
{
WetParticles::WetParticles (const LiquidBridgeProperties &liquid,
                            const WetParticleMaterial    &particle,
                            const std::string            &rupture_distance_law,
                            const std::string            &restitution_law)
    : liquid_properties (liquid), particle (particle),
      rupture (create_rupture_distance (rupture_distance_law)),
      wet_restitution (create_wet_restitution (restitution_law))
{
}

WetParticles::~WetParticles () = default;

template <typename Number>
WetContact<Number> WetParticles::contact (const Number &alpha_s,
                                          const Number &theta) const
{
  const auto &l = liquid_properties;
  // floors: no solids -> an infinite gap; Theta -> 0 -> St -> 0; the gap above
  // Woodcock's packing (h <= 0) is floored at h_a/100 for h_c - h, St* and P (the window
  // is then closed: dry contact)
  const Number       a     = alpha_s > 1e-12 ? alpha_s : Number (1e-12);
  const Number       t     = theta > 1e-14 ? theta : Number (1e-14);
  const Number       gap   = woodcock_gap (a, particle.particle_diameter);
  const Number       h     = gap > 0.01 * l.asperity ? gap : Number (0.01 * l.asperity);
  const Number       u_dot = approach_velocity (t, l.approach_factor);
  const Number       h_c   = rupture->value (u_dot, l, particle);
  WetContact<Number> c;
  c.gap              = gap;
  c.rupture_distance = h_c;
  c.above_asperity = smooth_step (Number ((h - l.asperity) / l.asperity), l.switch_width);
  c.bridged        = smooth_step (Number ((h_c - h) / h_c), l.switch_width);
  c.stokes         = stokes_number (u_dot, particle, l.liquid_viscosity);
  c.critical_stokes = critical_stokes_number (h, l.asperity, particle.dry_restitution);
  return c;
}

WetClosures
WetParticles::evaluate (const double alpha_s, const double theta, const double i2d) const
{
  const auto              &l = liquid_properties;
  const WetContact<double> c = contact (alpha_s, theta);
  WetClosures              w;
  w.gap               = c.gap;
  w.rupture_distance  = c.rupture_distance;
  w.approach_velocity = approach_velocity (std::max (theta, 1e-14), l.approach_factor);
  w.window            = c.above_asperity * c.bridged;
  const double h      = std::max (c.gap, 0.01 * l.asperity);
  w.pressure          = alpha_s > 0 ? w.window * bridge_pressure (alpha_s,
                                                         h,
                                                         w.approach_velocity,
                                                         l.liquid_viscosity,
                                                         particle.particle_diameter)
                                    : 0.0;
  w.viscosity         = wet_viscosity (w.pressure,
                               std::max (i2d, 0.0),
                               l.stability_angle,
                               l.strain_rate_regularisation,
                               l.maximum_viscosity);
  w.stokes            = c.stokes;
  w.critical_stokes   = c.critical_stokes;
  w.restitution       = wet_restitution->value (c, l, particle);
  return w;
}

double WetParticles::restitution (const double alpha_s, const double theta) const
{
  return wet_restitution->value (contact (alpha_s, theta), liquid_properties, particle);
}

std::string WetClosures::regime (const double asperity) const
{
  if (gap <= asperity)
    return "contact";
  return gap <= rupture_distance ? "bridged" : "ruptured";
}

template WetContact<double> WetParticles::contact (const double &, const double &) const;
template WetContact<ADNumber> WetParticles::contact (const ADNumber &,
                                                     const ADNumber &) const;
} // namespace wetbed::closures
