#pragma once

#include <wetbed/boundary_conditions/wall_condition.h>
#include <wetbed/closures/law_registry.h>
#include <wetbed/mesh/boundaries.h>

#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace wetbed
{
using WallConditionRegistry =
    closures::ModelRegistry<WallCondition, WallConditionSettings>;

/** name -> factory of every condition of WallConditionList (wall_condition_list.h). */
const WallConditionRegistry &wall_condition_registry ();

/**
 * The value of `boundary conditions/<phase> wall condition`: one condition for every
 * wall group ("free-slip"), or ';'-separated entries of which one may be a bare
 * condition (the default) and the others `group: condition` for named wall groups
 * ("free-slip; side: Johnson-Jackson").
 */
struct WallConditionChoice
{
  std::string                                      default_condition;
  std::vector<std::pair<std::string, std::string>> by_group; // as given

  /** InputError naming `parameter` for a malformed entry, an unknown condition, a
   * group named twice, or no condition for the groups not listed. */
  static WallConditionChoice parse (const std::string &text,
                                    const std::string &parameter);
  /** The condition of the group `name`. */
  const std::string &of (const std::string &name) const;
  /** The default and every per-group condition. */
  std::vector<std::string> names () const;
};

/**
 * The condition of each phase on each wall group (fixed or moving) of a case, built
 * once the mesh's boundaries are known. The constraints, the flow's wall terms, the
 * granular-energy wall flux and the wall forces all ask it.
 */
class WallConditions
{
public:
  using Predicate = std::function<bool (const WallCondition &)>;

  WallConditions () = default;
  /** InputError naming `boundary conditions/<phase> wall condition` if it names a
   * group that is not a wall of the mesh, or a condition that cannot be built. */
  WallConditions (const Boundaries                           &boundaries,
                  const std::array<WallConditionChoice, 2>   &choices,
                  const std::array<WallConditionSettings, 2> &settings);

  /** The condition of `phase` on the wall `id`; std::out_of_range if `id` is not a
   * wall. */
  const WallCondition &at (dealii::types::boundary_id id, Phase phase) const;
  /** The walls where the condition of `phase` satisfies `predicate`. */
  std::set<dealii::types::boundary_id> walls (Phase            phase,
                                              const Predicate &predicate) const;
  /** Whether any wall's condition of `phase` satisfies `predicate`. */
  bool any (Phase phase, const Predicate &predicate) const;

private:
  std::map<dealii::types::boundary_id,
           std::array<std::shared_ptr<const WallCondition>, 2>>
      conditions;
};
} // namespace wetbed
