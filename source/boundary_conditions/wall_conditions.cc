#include <wetbed/boundary_conditions/wall_condition_list.h>
#include <wetbed/boundary_conditions/wall_conditions.h>
#include <wetbed/core/input_error.h>

#include <deal.II/base/utilities.h>

namespace wetbed
{
const WallConditionRegistry &wall_condition_registry ()
{
  static const WallConditionRegistry registry =
      closures::make_model_registry<WallCondition, WallConditionSettings> (
          WallConditionList ());
  return registry;
}

WallConditionChoice WallConditionChoice::parse (const std::string &text,
                                                const std::string &parameter)
{
  const auto         &registry = wall_condition_registry ();
  const std::string   known    = closures::registered_names (registry);
  WallConditionChoice choice;
  auto                check_name = [&] (const std::string &name)
  {
    require (registry.count (name) > 0,
             parameter,
             "'" + name + "' is not a wall condition (" + known + ")");
  };
  for (const std::string &raw : dealii::Utilities::split_string_list (text, ';'))
  {
    const std::string entry = dealii::Utilities::trim (raw);
    require (!entry.empty (), parameter, "has an empty entry in '" + text + "'");
    const auto colon = entry.find (':');
    if (colon == std::string::npos)
    {
      require (choice.default_condition.empty (),
               parameter,
               "names more than one condition for the walls not listed");
      check_name (entry);
      choice.default_condition = entry;
      continue;
    }
    const std::string group     = dealii::Utilities::trim (entry.substr (0, colon));
    const std::string condition = dealii::Utilities::trim (entry.substr (colon + 1));
    require (!group.empty (), parameter, "'" + entry + "' names no wall group");
    check_name (condition);
    for (const auto &[named, c] : choice.by_group)
      require (named != group, parameter, "names the wall group '" + group + "' twice");
    choice.by_group.emplace_back (group, condition);
  }
  require (!choice.default_condition.empty () || !choice.by_group.empty (),
           parameter,
           "is empty");
  return choice;
}

const std::string &WallConditionChoice::of (const std::string &name) const
{
  for (const auto &[group, condition] : by_group)
    if (group == name)
      return condition;
  return default_condition;
}

std::vector<std::string> WallConditionChoice::names () const
{
  std::vector<std::string> all;
  if (!default_condition.empty ())
    all.push_back (default_condition);
  for (const auto &entry : by_group)
    all.push_back (entry.second);
  return all;
}

WallConditions::WallConditions (const Boundaries                           &boundaries,
                                const std::array<WallConditionChoice, 2>   &choices,
                                const std::array<WallConditionSettings, 2> &settings)
{
  for (unsigned int k = 0; k < 2; ++k)
  {
    const std::string parameter =
        "boundary conditions/" + to_string (settings[k].phase) + " wall condition";
    for (const auto &[group, condition] : choices[k].by_group)
    {
      const Boundary *wall = nullptr;
      for (const Boundary &b : boundaries.all ())
        if (b.name == group)
          wall = &b;
      require (wall != nullptr && boundaries.is_wall (wall->id),
               parameter,
               "'" + group +
                   "' is not a wall group of the mesh (mesh/wall or the "
                   "moving wall)");
    }
    for (const Boundary &b : boundaries.all ())
    {
      if (!boundaries.is_wall (b.id))
        continue;
      const std::string &name = choices[k].of (b.name);
      require (!name.empty (),
               parameter,
               "gives no condition for the wall group '" + b.name + "'");
      conditions[b.id][k] = wall_condition_registry ().at (name) (settings[k]);
    }
  }
}

const WallCondition &WallConditions::at (const dealii::types::boundary_id id,
                                         const Phase                      phase) const
{
  return *conditions.at (id)[static_cast<unsigned int> (phase)];
}

std::set<dealii::types::boundary_id>
WallConditions::walls (const Phase phase, const Predicate &predicate) const
{
  std::set<dealii::types::boundary_id> ids;
  for (const auto &[id, both] : conditions)
    if (predicate (*both[static_cast<unsigned int> (phase)]))
      ids.insert (id);
  return ids;
}

bool WallConditions::any (const Phase phase, const Predicate &predicate) const
{
  return !walls (phase, predicate).empty ();
}
} // namespace wetbed
