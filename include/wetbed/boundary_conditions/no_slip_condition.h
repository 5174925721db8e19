#pragma once

#include <wetbed/boundary_conditions/wall_condition.h>

namespace wetbed
{
/** The phase takes the wall's velocity (zero, or a moving wall's). */
class NoSlipCondition : public WallCondition
{
public:
  static constexpr const char          *model_name = "no-slip";
  static std::unique_ptr<WallCondition> create (const WallConditionSettings &)
  {
    return std::make_unique<NoSlipCondition> ();
  }
  std::string name () const override { return model_name; }
  bool        prescribes_velocity () const override { return true; }
};
} // namespace wetbed
