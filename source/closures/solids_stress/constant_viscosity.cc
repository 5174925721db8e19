#include <wetbed/closures/solids_stress/constant_viscosity.h>
#include <wetbed/core/physical_properties.h>
#include <wetbed/core/solids_stress_parameters.h>

namespace wetbed::closures
{
std::unique_ptr<SolidsStressModel>
ConstantViscosityRheology::create (const SolidsStressSettings &settings)
{
  return std::make_unique<ConstantViscosityRheology> (
      settings.stress.shear_viscosity,
      johnson_jackson_coefficients (settings.stress, settings.physical));
}
} // namespace wetbed::closures
