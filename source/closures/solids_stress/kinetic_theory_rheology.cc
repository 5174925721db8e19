#include <wetbed/closures/solids_stress/kinetic_theory_rheology.h>
#include <wetbed/core/kinetic_theory_parameters.h>
#include <wetbed/core/physical_properties.h>
#include <wetbed/core/solids_stress_parameters.h>
#include <wetbed/core/wet_particle_parameters.h>

namespace wetbed::closures
{
std::unique_ptr<SolidsStressModel>
KineticTheoryRheology::create (const SolidsStressSettings &settings)
{
  const auto &kinetic = settings.kinetic;
  return std::make_unique<KineticTheoryRheology> (
      std::make_shared<const KineticTheory> (kinetic, settings.physical, settings.wet),
      johnson_jackson_coefficients (settings.stress, settings.physical),
      kinetic.internal_friction_angle,
      kinetic.maximum_frictional_viscosity,
      kinetic.strain_rate_regularisation,
      kinetic.minimum_shear_viscosity,
      settings.wet.pressure_in_solids_pressure);
}
} // namespace wetbed::closures
