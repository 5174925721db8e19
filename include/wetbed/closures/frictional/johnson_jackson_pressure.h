#pragma once

#include <cmath>

namespace wetbed::closures
{
/** Coefficients of the Johnson-Jackson frictional pressure. */
struct JohnsonJacksonPressureCoefficients
{
  double coefficient;      // Fr (Pa)
  double exponent_n;       // n
  double exponent_p;       // p
  double onset;            // alpha_fr,min
  double maximum_packing;  // alpha_max
  double minimum_distance; // floor delta_min of (alpha_max - alpha)
};

/**
 * Johnson-Jackson (1987) frictional pressure
 *   P_fr = Fr (alpha - alpha_fr,min)^n / max(alpha_max - alpha, delta_min)^p
 * for alpha > alpha_fr,min, else 0 (OpenFOAM's alphaDeltaMin floor).
 */
template <typename Number>
Number johnson_jackson_pressure (const Number                             &alpha,
                                 const JohnsonJacksonPressureCoefficients &c)
{
  using std::max;
  using std::pow;
  if (alpha <= c.onset)
    return Number (0.0);
  const Number gap =
      max (Number (c.maximum_packing - alpha), Number (c.minimum_distance));
  return c.coefficient * pow (alpha - c.onset, c.exponent_n) / pow (gap, c.exponent_p);
}

/** dP_fr/dalpha of johnson_jackson_pressure (exact, including the floored branch). */
template <typename Number>
Number johnson_jackson_pressure_derivative (const Number &alpha,
                                            const JohnsonJacksonPressureCoefficients &c)
{
  using std::pow;
  if (alpha <= c.onset)
    return Number (0.0);
  const Number excess = alpha - c.onset;
  if (c.maximum_packing - alpha <= c.minimum_distance)
    return c.coefficient * c.exponent_n * pow (excess, c.exponent_n - 1.0) /
           pow (c.minimum_distance, c.exponent_p);
  const Number gap = c.maximum_packing - alpha;
  return c.coefficient *
         (c.exponent_n * pow (excess, c.exponent_n - 1.0) * gap +
          c.exponent_p * pow (excess, c.exponent_n)) /
         pow (gap, c.exponent_p + 1.0);
}
} // namespace wetbed::closures
