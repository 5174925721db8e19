#pragma once

#include <wetbed/boundary_conditions/wall_condition.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/core/input_error.h>

#include <algorithm>

namespace wetbed
{
/** The solids' Johnson-Jackson wall (doc/theory.md, "Johnson-Jackson walls"): the
 * friction C_JJ(alpha_s, g0, Theta) of the specularity coefficient and the granular
 * energy flux of the wall; needs the kinetic theory. */
class JohnsonJacksonCondition : public WallCondition
{
public:
  static constexpr const char          *model_name = "Johnson-Jackson";
  static std::unique_ptr<WallCondition> create (const WallConditionSettings &settings)
  {
    const std::string parameter =
        "boundary conditions/" + to_string (settings.phase) + " wall condition";
    require (settings.phase == Phase::solids,
             parameter,
             "Johnson-Jackson is a condition of the solids phase");
    require (settings.has_kinetic_theory,
             parameter,
             "Johnson-Jackson walls need solids stress/model = kinetic theory (they "
             "depend on the granular temperature)");
    return std::make_unique<JohnsonJacksonCondition> (settings.kinetic_theory);
  }
  /** kinetic_theory may be null only for a condition that is never evaluated (the
   * parameter check). */
  explicit JohnsonJacksonCondition (const closures::KineticTheory *kinetic_theory)
      : kinetic_theory (kinetic_theory)
  {
  }
  std::string name () const override { return model_name; }
  bool        has_friction () const override { return true; }
  bool        has_granular_energy_flux () const override { return true; }
  double      friction (const WallPoint &point) const override
  {
    const double a = std::max (point.alpha_s, 0.0);
    return kinetic_theory->wall ().shear_coefficient (
        a, kinetic_theory->radial_distribution (a), std::max (point.theta, 0.0));
  }

private:
  const closures::KineticTheory *kinetic_theory;
};
} // namespace wetbed
