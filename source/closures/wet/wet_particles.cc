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
  return wet_contact (alpha_s,
                      theta,
                      liquid_properties,
                      particle,
                      [this] (const Number &u_dot)
                      { return rupture->value (u_dot, liquid_properties, particle); });
}

WetClosures WetParticles::evaluate (const double alpha_s,
                                    const double theta,
                                    const double i2d,
                                    const double velocity_divergence) const
{
  const auto              &l = liquid_properties;
  const WetContact<double> c = contact (alpha_s, theta);
  WetClosures              w;
  w.gap               = c.gap;
  w.rupture_distance  = c.rupture_distance;
  w.approach_velocity = approach_velocity (std::max (theta, 1e-14), l.approach_factor);
  w.window            = c.above_asperity * c.bridged;
  const double h      = std::max (c.gap, 0.01 * l.asperity);
  w.approach_weight   = l.approach_only ? approach_weight (velocity_divergence,
                                                         l.strain_rate_regularisation)
                                        : 1.0;
  w.pressure          = alpha_s > 0 ? w.window * w.approach_weight *
                                 bridge_pressure (alpha_s,
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
