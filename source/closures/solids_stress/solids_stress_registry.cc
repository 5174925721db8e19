#include <wetbed/closures/solids_stress/constant_viscosity.h>
#include <wetbed/closures/solids_stress/kinetic_theory_rheology.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/parameters.h>

namespace wetbed::closures
{
std::unique_ptr<SolidsStressModel>
create_solids_stress_model (const SolidsStressParameters  &p,
                            const PhysicalProperties      &physical,
                            const KineticTheoryParameters &kinetic,
                            const WetParticleParameters   &wet)
{
  const JohnsonJacksonPressureCoefficients friction{p.frictional_coefficient,
                                                    p.frictional_exponent_n,
                                                    p.frictional_exponent_p,
                                                    p.frictional_onset,
                                                    physical.maximum_packing,
                                                    p.minimum_packing_distance};
  if (p.model == ConstantViscosityRheology::model_name)
    return std::make_unique<ConstantViscosityRheology> (p.shear_viscosity, friction);
  if (p.model == KineticTheoryRheology::model_name)
    return std::make_unique<KineticTheoryRheology> (
        std::make_shared<const KineticTheory> (kinetic, physical, wet),
        friction,
        kinetic.internal_friction_angle,
        kinetic.maximum_frictional_viscosity,
        kinetic.strain_rate_regularisation,
        kinetic.minimum_shear_viscosity,
        wet.pressure_in_solids_pressure);
  throw InputError ("solids stress/model", "unknown model '" + p.model + "'");
}

std::string solids_stress_model_names ()
{
  return std::string (ConstantViscosityRheology::model_name) + "|" +
         KineticTheoryRheology::model_name;
}
} // namespace wetbed::closures
