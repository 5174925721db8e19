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
  double minimum_distance; // delta_min: where the C1 linear continuation starts
};

template <typename Number>
Number johnson_jackson_pressure_derivative (const Number &alpha,
                                            const JohnsonJacksonPressureCoefficients &c);

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
  using std::pow;
  if (alpha <= c.onset)
    return Number (0.0);
  const double alpha_c = c.maximum_packing - c.minimum_distance;
  if (alpha > alpha_c && alpha_c > c.onset)
    return johnson_jackson_pressure (alpha_c, c) +
           johnson_jackson_pressure_derivative (alpha_c, c) * (alpha - alpha_c);
  using std::max;
  const Number gap =
      max (Number (c.maximum_packing - alpha), Number (c.minimum_distance));
  return c.coefficient * pow (alpha - c.onset, c.exponent_n) / pow (gap, c.exponent_p);
}

/** dP_fr/dalpha of johnson_jackson_pressure (exact; constant on the continuation). */
template <typename Number>
Number johnson_jackson_pressure_derivative (const Number &alpha,
                                            const JohnsonJacksonPressureCoefficients &c)
{
  using std::pow;
  if (alpha <= c.onset)
    return Number (0.0);
  const double alpha_c = c.maximum_packing - c.minimum_distance;
  const Number excess  = alpha > alpha_c && alpha_c > c.onset ? Number (alpha_c - c.onset)
                                                              : Number (alpha - c.onset);
  using std::max;
  const Number gap =
      max (Number (c.maximum_packing - alpha), Number (c.minimum_distance));
  return c.coefficient *
         (c.exponent_n * pow (excess, c.exponent_n - 1.0) * gap +
          c.exponent_p * pow (excess, c.exponent_n)) /
         pow (gap, c.exponent_p + 1.0);
}
} // namespace wetbed::closures
