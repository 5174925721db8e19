#include <wetbed/closures/solids_stress/solids_stress_laws.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/kinetic_theory_parameters.h>
#include <wetbed/core/physical_properties.h>
#include <wetbed/core/solids_stress_parameters.h>
#include <wetbed/core/wet_particle_parameters.h>

namespace wetbed::closures
{
JohnsonJacksonPressureCoefficients
johnson_jackson_coefficients (const SolidsStressParameters &p,
                              const PhysicalProperties     &physical)
{
  return {p.frictional_coefficient,
          p.frictional_exponent_n,
          p.frictional_exponent_p,
          p.frictional_onset,
          physical.maximum_packing,
          p.minimum_packing_distance};
}

namespace
{
/** Adding a rheology: its class and one name in SolidsStressModels. */
const ModelRegistry<SolidsStressModel, SolidsStressSettings> &registry ()
{
  static const auto models =
      make_model_registry<SolidsStressModel, SolidsStressSettings> (SolidsStressModels{});
  return models;
}
} // namespace

std::unique_ptr<SolidsStressModel>
create_solids_stress_model (const SolidsStressParameters  &p,
                            const PhysicalProperties      &physical,
                            const KineticTheoryParameters &kinetic,
                            const WetParticleParameters   &wet)
{
  const auto it = registry ().find (p.model);
  if (it == registry ().end ())
    throw InputError ("solids stress/model", "unknown model '" + p.model + "'");
  return it->second (SolidsStressSettings{p, physical, kinetic, wet});
}

std::string solids_stress_model_names ()
{
  return registered_names (registry ());
}
} // namespace wetbed::closures
