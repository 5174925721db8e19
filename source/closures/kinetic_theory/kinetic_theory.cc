#include <wetbed/closures/kinetic_theory/collisional_terms.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/core/kinetic_theory_parameters.h>
#include <wetbed/core/physical_properties.h>
#include <wetbed/core/wet_particle_parameters.h>

#include <algorithm>

namespace wetbed::closures
{
KineticTheory::KineticTheory (const KineticTheoryParameters &p,
                              const PhysicalProperties      &physical,
                              const WetParticleParameters   &wet)
    : granular{physical.particle_density,
               physical.particle_diameter,
               p.restitution,
               physical.maximum_packing},
      cap (p.radial_distribution_cap),
      g0_law (create_radial_distribution (p.radial_distribution)),
      viscosity_law (create_kinetic_viscosity (p.kinetic_viscosity)),
      conductivity_law (create_granular_conductivity (p.conductivity)),
      jj_wall{p.specularity,
              p.wall_restitution,
              physical.maximum_packing,
              physical.particle_density}
{
  if (wet.enabled ())
    wet_particles = std::make_unique<WetParticles> (
        wet.liquid,
        WetParticleMaterial{
            physical.particle_density, physical.particle_diameter, p.restitution},
        wet.rupture_distance,
        wet.restitution);
}

KineticTheory::~KineticTheory () = default;

double KineticTheory::radial_distribution (const double alpha_s) const
{
  return g0_law->value (std::clamp (alpha_s, 0.0, cap), granular.maximum_packing);
}

KineticTheory::Coefficients KineticTheory::evaluate (const double alpha_s,
                                                     const double theta) const
{
  const double a  = std::max (alpha_s, 0.0);
  const double t  = std::max (theta, 0.0);
  const double g0 = radial_distribution (a);
  Coefficients c;
  c.g0                    = g0;
  c.pressure_factor       = CollisionalTerms::solids_pressure (a, 1.0, g0, granular);
  c.collisional_viscosity = CollisionalTerms::shear_viscosity (a, t, g0, granular);
  c.shear_viscosity = c.collisional_viscosity + viscosity_law->value (a, t, g0, granular);
  c.bulk_viscosity  = CollisionalTerms::bulk_viscosity (a, t, g0, granular);
  c.conductivity    = conductivity_law->value (a, t, g0, granular);
  c.restitution =
      wet_particles ? wet_particles->restitution (a, t) : granular.restitution;
  c.dissipation_factor =
      CollisionalTerms::dissipation (a, 1.0, g0, granular, c.restitution);
  return c;
}

double KineticTheory::algebraic_temperature (const double alpha_s,
                                             const double trace_d,
                                             const double d_ddot_d,
                                             const double beta) const
{
  if (!(alpha_s > 0))
    return 0.0;
  return equilibrium.value (
      alpha_s, radial_distribution (alpha_s), trace_d, d_ddot_d, beta, granular);
}
} // namespace wetbed::closures
