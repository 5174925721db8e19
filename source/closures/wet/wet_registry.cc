#include <wetbed/closures/law_registry.h>
#include <wetbed/closures/wet/rupture_distance.h>
#include <wetbed/closures/wet/wet_laws.h>
#include <wetbed/closures/wet/wet_restitution.h>

namespace wetbed::closures
{
namespace
{
const LawRegistry<RuptureDistance> &rupture_distances ()
{
  static const auto registry =
      make_law_registry<RuptureDistanceFromLaw, RuptureDistance> (RuptureDistanceLaws{});
  return registry;
}

const LawRegistry<WetRestitution> &wet_restitutions ()
{
  static const auto registry =
      make_law_registry<WetRestitutionFromLaw, WetRestitution> (WetRestitutionLaws{});
  return registry;
}

} // namespace

std::unique_ptr<RuptureDistance> create_rupture_distance (const std::string &name)
{
  return create_law (rupture_distances (), name, "rupture distance");
}
std::string rupture_distance_names ()
{
  return law_names (rupture_distances ());
}

std::unique_ptr<WetRestitution> create_wet_restitution (const std::string &name)
{
  return create_law (wet_restitutions (), name, "wet restitution");
}
std::string wet_restitution_names ()
{
  return law_names (wet_restitutions ());
}
} // namespace wetbed::closures
