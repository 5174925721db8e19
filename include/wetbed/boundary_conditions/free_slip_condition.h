#pragma once

#include <wetbed/boundary_conditions/wall_condition.h>

namespace wetbed
{
/** No penetration, no tangential traction. */
class FreeSlipCondition : public WallCondition
{
public:
  static constexpr const char          *model_name = "free-slip";
  static std::unique_ptr<WallCondition> create (const WallConditionSettings &)
  {
    return std::make_unique<FreeSlipCondition> ();
  }
  std::string name () const override { return model_name; }
};
} // namespace wetbed
