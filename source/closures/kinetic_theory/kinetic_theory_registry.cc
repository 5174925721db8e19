#include <wetbed/closures/kinetic_theory/granular_conductivity.h>
#include <wetbed/closures/kinetic_theory/kinetic_viscosity.h>
#include <wetbed/closures/kinetic_theory/radial_distribution.h>

#include <wetbed/closures/law_registry.h>

namespace wetbed::closures
{
namespace
{
const LawRegistry<RadialDistribution> &radial_distributions ()
{
  static const auto registry = make_law_registry<RadialDistributionFromLaw,
                                                 RadialDistribution,
                                                 OgawaRadialDistribution,
                                                 CarnahanStarlingRadialDistribution,
                                                 LunSavageRadialDistribution> ();
  return registry;
}

const LawRegistry<KineticTheoryCoefficient> &kinetic_viscosities ()
{
  static const auto registry = make_law_registry<KineticTheoryCoefficientFromLaw,
                                                 KineticTheoryCoefficient,
                                                 GidaspowKineticViscosity,
                                                 SyamlalKineticViscosity> ();
  return registry;
}

const LawRegistry<KineticTheoryCoefficient> &granular_conductivities ()
{
  static const auto registry = make_law_registry<KineticTheoryCoefficientFromLaw,
                                                 KineticTheoryCoefficient,
                                                 GidaspowConductivity,
                                                 SyamlalConductivity> ();
  return registry;
}

} // namespace

std::unique_ptr<RadialDistribution> create_radial_distribution (const std::string &name)
{
  return create_law (radial_distributions (), name, "radial distribution");
}
std::unique_ptr<KineticTheoryCoefficient>
create_kinetic_viscosity (const std::string &name)
{
  return create_law (kinetic_viscosities (), name, "kinetic viscosity");
}
std::unique_ptr<KineticTheoryCoefficient>
create_granular_conductivity (const std::string &name)
{
  return create_law (granular_conductivities (), name, "granular conductivity");
}
std::string radial_distribution_names ()
{
  return law_names (radial_distributions ());
}
std::string kinetic_viscosity_names ()
{
  return law_names (kinetic_viscosities ());
}
std::string granular_conductivity_names ()
{
  return law_names (granular_conductivities ());
}
} // namespace wetbed::closures
