#include <wetbed/mesh/boundaries.h>

#include <algorithm>
#include <stdexcept>

namespace wetbed
{
std::string to_string (const BoundaryType type)
{
  switch (type)
  {
  case BoundaryType::inlet:
    return "inlet";
  case BoundaryType::outlet:
    return "outlet";
  case BoundaryType::wall:
    return "wall";
  case BoundaryType::moving_wall:
    return "moving wall";
  case BoundaryType::periodic_low:
    return "periodic low";
  case BoundaryType::periodic_high:
    return "periodic high";
  }
  return "unknown";
}

void Boundaries::add (const std::string               &name,
                      const BoundaryType               type,
                      const dealii::types::boundary_id id)
{
  if (id == none)
    throw std::invalid_argument ("boundary group '" + name + "' has no valid id");
  if (const Boundary *other = find (id))
    throw std::invalid_argument ("boundary id " + std::to_string (id) + " of '" + name +
                                 "' is already the " + to_string (other->type) + " '" +
                                 other->name + "'");
  groups.push_back ({name, type, id});
}

std::set<dealii::types::boundary_id> Boundaries::ids (const BoundaryType type) const
{
  std::set<dealii::types::boundary_id> result;
  for (const auto &group : groups)
    if (group.type == type)
      result.insert (group.id);
  return result;
}

std::set<dealii::types::boundary_id>
Boundaries::ids (const std::initializer_list<BoundaryType> types) const
{
  std::set<dealii::types::boundary_id> result;
  for (const auto type : types)
  {
    const auto some = ids (type);
    result.insert (some.begin (), some.end ());
  }
  return result;
}

dealii::types::boundary_id Boundaries::id_of (const BoundaryType type) const
{
  const auto of_type = ids (type);
  if (of_type.size () > 1)
    throw std::logic_error ("more than one " + to_string (type) + " group");
  return of_type.empty () ? none : *of_type.begin ();
}

bool Boundaries::has (const BoundaryType type) const
{
  return std::any_of (groups.begin (),
                      groups.end (),
                      [type] (const Boundary &group) { return group.type == type; });
}

bool Boundaries::is (const dealii::types::boundary_id id, const BoundaryType type) const
{
  const Boundary *group = find (id);
  return group != nullptr && group->type == type;
}

bool Boundaries::is_wall (const dealii::types::boundary_id id) const
{
  const Boundary *group = find (id);
  return group != nullptr &&
         (group->type == BoundaryType::wall || group->type == BoundaryType::moving_wall);
}

std::set<dealii::types::boundary_id> Boundaries::walls () const
{
  return ids ({BoundaryType::wall, BoundaryType::moving_wall});
}

const Boundary *Boundaries::find (const dealii::types::boundary_id id) const
{
  for (const auto &group : groups)
    if (group.id == id)
      return &group;
  return nullptr;
}

BoundaryType Boundaries::type_of (const dealii::types::boundary_id id) const
{
  if (const Boundary *group = find (id))
    return group->type;
  throw std::out_of_range ("boundary id " + std::to_string (id) + " is in no group");
}
} // namespace wetbed
