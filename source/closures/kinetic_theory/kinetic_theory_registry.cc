#include <wetbed/closures/kinetic_theory/granular_conductivity.h>
#include <wetbed/closures/kinetic_theory/kinetic_viscosity.h>
#include <wetbed/closures/kinetic_theory/radial_distribution.h>

#include <functional>
#include <map>
#include <stdexcept>

namespace wetbed::closures
{
namespace
{
/** name -> factory; adding a law is one line here and one header. */
template <class Base>
using Registry = std::map<std::string, std::function<std::unique_ptr<Base> ()>>;

template <template <class> class Wrapper, class Base, class... Laws>
Registry<Base> make_registry ()
{
  return {{Laws::name, [] { return std::unique_ptr<Base> (new Wrapper<Laws> ()); }}...};
}

const Registry<RadialDistribution> &radial_distributions ()
{
  static const auto registry = make_registry<RadialDistributionFromLaw,
                                             RadialDistribution,
                                             OgawaRadialDistribution,
                                             CarnahanStarlingRadialDistribution,
                                             LunSavageRadialDistribution> ();
  return registry;
}

const Registry<KineticTheoryCoefficient> &kinetic_viscosities ()
{
  static const auto registry = make_registry<KineticTheoryCoefficientFromLaw,
                                             KineticTheoryCoefficient,
                                             GidaspowKineticViscosity,
                                             SyamlalKineticViscosity> ();
  return registry;
}

const Registry<KineticTheoryCoefficient> &granular_conductivities ()
{
  static const auto registry = make_registry<KineticTheoryCoefficientFromLaw,
                                             KineticTheoryCoefficient,
                                             GidaspowConductivity,
                                             SyamlalConductivity> ();
  return registry;
}

template <class Base>
std::unique_ptr<Base>
create (const Registry<Base> &registry, const std::string &name, const char *what)
{
  const auto it = registry.find (name);
  if (it == registry.end ())
    throw std::invalid_argument (std::string ("unknown ") + what + " '" + name + "'");
  return it->second ();
}

template <class Base>
std::string names (const Registry<Base> &registry)
{
  std::string joined;
  for (const auto &entry : registry)
    joined += (joined.empty () ? "" : "|") + entry.first;
  return joined;
}
} // namespace

std::unique_ptr<RadialDistribution> create_radial_distribution (const std::string &name)
{
  return create (radial_distributions (), name, "radial distribution");
}
std::unique_ptr<KineticTheoryCoefficient>
create_kinetic_viscosity (const std::string &name)
{
  return create (kinetic_viscosities (), name, "kinetic viscosity");
}
std::unique_ptr<KineticTheoryCoefficient>
create_granular_conductivity (const std::string &name)
{
  return create (granular_conductivities (), name, "granular conductivity");
}
std::string radial_distribution_names ()
{
  return names (radial_distributions ());
}
std::string kinetic_viscosity_names ()
{
  return names (kinetic_viscosities ());
}
std::string granular_conductivity_names ()
{
  return names (granular_conductivities ());
}
} // namespace wetbed::closures
