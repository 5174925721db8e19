#pragma once

#include <wetbed/boundary_conditions/wall_condition.h>
#include <wetbed/core/input_error.h>

namespace wetbed
{
/** No penetration and the Robin traction -C P_t (u - u_w) with a constant C > 0
 * (`boundary conditions/<phase> wall friction`). */
class PartialSlipCondition : public WallCondition
{
public:
  static constexpr const char          *model_name = "partial-slip";
  static std::unique_ptr<WallCondition> create (const WallConditionSettings &settings)
  {
    require (settings.friction > 0,
             "boundary conditions/" + to_string (settings.phase) + " wall friction",
             "must be > 0 for a partial-slip wall");
    return std::make_unique<PartialSlipCondition> (settings.friction);
  }
  explicit PartialSlipCondition (const double coefficient) : coefficient (coefficient) {}
  std::string name () const override { return model_name; }
  bool        has_friction () const override { return true; }
  double      friction (const WallPoint &) const override { return coefficient; }

private:
  double coefficient;
};
} // namespace wetbed
