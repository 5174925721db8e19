#pragma once

#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Radial distribution functions at contact g0(alpha_s) (doc/theory.md,
 * "Kinetic-theory closures").
 * The caller caps alpha_s (GranularTemperature evaluates g0 at min(alpha_s, cap)) so that
 * the forms that diverge at alpha_max stay finite.
 */

/** Ogawa/Lun (seed 000, Fluent): [1 - (alpha/alpha_max)^(1/3)]^-1. */
struct OgawaRadialDistribution
{
  static constexpr const char *name = "Ogawa";
  template <typename Number>
  static Number value (const Number &alpha, const double alpha_max)
  {
    return 1.0 / (1.0 - math::cbrt (Number (alpha / alpha_max)));
  }
};

/** Carnahan-Starling: (1 - alpha/2)/(1 - alpha)^3 (finite at packing). */
struct CarnahanStarlingRadialDistribution
{
  static constexpr const char *name = "Carnahan-Starling";
  template <typename Number>
  static Number value (const Number &alpha, const double /*alpha_max*/)
  {
    const Number gap = 1.0 - alpha;
    return (1.0 - 0.5 * alpha) / (gap * gap * gap);
  }
};

/** Lun-Savage: (1 - alpha/alpha_max)^(-2.5 alpha_max). */
struct LunSavageRadialDistribution
{
  static constexpr const char *name = "Lun-Savage";
  template <typename Number>
  static Number value (const Number &alpha, const double alpha_max)
  {
    using std::pow;
    return pow (1.0 - alpha / alpha_max, -2.5 * alpha_max);
  }
};
} // namespace wetbed::closures
