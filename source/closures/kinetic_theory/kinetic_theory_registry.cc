#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory_laws.h>
#include <wetbed/closures/law_registry.h>

namespace wetbed::closures
{
namespace
{
const LawRegistry<RadialDistribution> &radial_distributions ()
{
  static const auto registry =
      make_law_registry<RadialDistributionFromLaw, RadialDistribution> (
          RadialDistributionLaws{});
  return registry;
}

const LawRegistry<KineticTheoryCoefficient> &kinetic_viscosities ()
{
  static const auto registry =
      make_law_registry<KineticTheoryCoefficientFromLaw, KineticTheoryCoefficient> (
          KineticViscosityLaws{});
  return registry;
}

const LawRegistry<KineticTheoryCoefficient> &granular_conductivities ()
{
  static const auto registry =
      make_law_registry<KineticTheoryCoefficientFromLaw, KineticTheoryCoefficient> (
          GranularConductivityLaws{});
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
