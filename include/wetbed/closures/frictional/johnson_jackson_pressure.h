#pragma once

#include <wetbed/closures/number_traits.h>

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
  double minimum_distance; // delta_min: where the C1 linear continuation starts
};

namespace internal
{
/** max(alpha_max - alpha, delta_min), the gap in the denominator. */
template <typename Number>
Number johnson_jackson_gap (const Number                             &alpha,
                            const JohnsonJacksonPressureCoefficients &c)
{
  using std::max;
  return max (Number (c.maximum_packing - alpha), Number (c.minimum_distance));
}

/** Fr (alpha - alpha_fr,min)^n / gap^p, without the onset and the continuation. */
template <typename Number>
Number johnson_jackson_power_law (const Number                             &alpha,
                                  const JohnsonJacksonPressureCoefficients &c)
{
  using std::pow;
  return c.coefficient * pow (alpha - c.onset, c.exponent_n) /
         pow (johnson_jackson_gap (alpha, c), c.exponent_p);
}
} // namespace internal

/** dP_fr/dalpha of johnson_jackson_pressure (exact; constant on the continuation). */
template <typename Number>
Number johnson_jackson_pressure_derivative (const Number &alpha,
                                            const JohnsonJacksonPressureCoefficients &c)
{
  using std::pow;
  const double alpha_c = c.maximum_packing - c.minimum_distance;
  Number       excess  = alpha - c.onset;
  if (alpha_c > c.onset) // the continuation exists (parameters only)
    excess = select_greater (alpha, alpha_c, Number (alpha_c - c.onset), excess);
  const Number gap        = internal::johnson_jackson_gap (alpha, c);
  const Number derivative = c.coefficient *
                            (c.exponent_n * pow (excess, c.exponent_n - 1.0) * gap +
                             c.exponent_p * pow (excess, c.exponent_n)) /
                            pow (gap, c.exponent_p + 1.0);
  return select_less_equal (alpha, c.onset, Number (0.0), derivative);
}

/**
 * Johnson-Jackson (1987) frictional pressure for alpha > alpha_fr,min (else 0)
 *   P_fr = Fr (alpha - alpha_fr,min)^n / (alpha_max - alpha)^p    alpha <= alpha_c,
 *   P_fr = P_fr(alpha_c) + P_fr'(alpha_c) (alpha - alpha_c)        alpha >  alpha_c,
 * alpha_c = alpha_max - delta_min. The regularisation is the C1 (tangent) continuation,
 * not OpenFOAM's floor max(alpha_max - alpha, delta_min): the floor makes P_fr' drop by
 * a factor ~ p (alpha - alpha_min)/(n delta_min) (30 with the seed values) at alpha_c,
 * and an implicit compaction correction linearised there under-estimates the stiffness
 * the momentum equation sees; that was measured to be unstable in a packed bed (see
 * doc/theory.md).
 */
template <typename Number>
Number johnson_jackson_pressure (const Number                             &alpha,
                                 const JohnsonJacksonPressureCoefficients &c)
{
  const double alpha_c  = c.maximum_packing - c.minimum_distance;
  Number       pressure = internal::johnson_jackson_power_law (alpha, c);
  if (alpha_c > c.onset) // the continuation exists (parameters only)
  {
    const double pressure_c   = internal::johnson_jackson_power_law (alpha_c, c);
    const double derivative_c = johnson_jackson_pressure_derivative (alpha_c, c);
    pressure                  = select_greater (
        alpha, alpha_c, Number (pressure_c + derivative_c * (alpha - alpha_c)), pressure);
  }
  return select_less_equal (alpha, c.onset, Number (0.0), pressure);
}
} // namespace wetbed::closures
