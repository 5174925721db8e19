#pragma once

// The number types a closure law is instantiated with, and the branch-free helpers the
// laws use so that one template compiles for all of them:
//   double,
//   ADNumber = Sacado::Fad::DFad<double> (the Jacobians),
//   dealii::VectorizedArray<double, width> (matrix-free evaluation, one state per lane).
// A law must not branch on the state with `if`/`?:` (VectorizedArray has no bool
// comparisons, so such a law does not compile for it): it computes every branch and
// picks one per lane with select_less(...) & co. Conditions on parameters (not the
// state) stay scalar.
//
// Elementary functions: this header includes <deal.II/base/vectorization.h> before any
// law, so that `using std::sqrt; sqrt(x)` (and pow(x, double), pow(x, x), exp, log,
// sin, cos, tan, abs, max(x, x), min(x, x)) find deal.II's std:: overloads for
// VectorizedArray, and ADL finds Sacado's for ADNumber. What deal.II 9.4 does not
// provide (cbrt, tanh) and the mixed max/min(x, double) are in namespace math below;
// call them qualified, math::cbrt(x).

#include <deal.II/base/vectorization.h>

#include <cmath>
#include <cstddef>

namespace wetbed::closures
{
/** Keeps a parameter out of template argument deduction (Number comes from the first
 * argument; the others convert to it, e.g. a double literal). */
template <typename T>
struct NonDeduced
{
  using type = T;
};
template <typename T>
using non_deduced_t = typename NonDeduced<T>::type;

/** Lanes of a number type: VectorizedArray<double, w>::size(), else 1. */
template <typename Number>
struct NumberTraits
{
  static constexpr bool        is_vectorized = false;
  static constexpr std::size_t n_lanes       = 1;
};

template <typename Scalar, std::size_t width>
struct NumberTraits<dealii::VectorizedArray<Scalar, width>>
{
  static constexpr bool        is_vectorized = true;
  static constexpr std::size_t n_lanes       = width;
};

template <typename Number>
inline constexpr bool is_vectorized_v = NumberTraits<Number>::is_vectorized;

/**
 * Branch-free selection, lane by lane: `a OP b ? if_true : if_false`. A ternary for
 * double and ADNumber (the derivatives of the chosen value), compare_and_apply_mask for
 * VectorizedArray. Both values are computed by the caller: a value that is not finite
 * in the lanes it is not chosen for is harmless (no floating-point traps). Number is
 * the type of `a`: pass a Number, not a Sacado expression.
 */
/** `a OP b ? if_true : if_false` for double and ADNumber (OP a SIMDComparison). */
template <dealii::SIMDComparison op, typename Number>
Number select (const Number                &a,
               const non_deduced_t<Number> &b,
               const non_deduced_t<Number> &if_true,
               const non_deduced_t<Number> &if_false)
{
  bool holds = false;
  switch (op)
  {
  case dealii::SIMDComparison::less_than:
    holds = a < b;
    break;
  case dealii::SIMDComparison::less_than_or_equal:
    holds = a <= b;
    break;
  case dealii::SIMDComparison::greater_than:
    holds = a > b;
    break;
  case dealii::SIMDComparison::greater_than_or_equal:
    holds = a >= b;
    break;
  case dealii::SIMDComparison::equal:
    holds = a == b;
    break;
  case dealii::SIMDComparison::not_equal:
    holds = a != b;
    break;
  }
  return holds ? if_true : if_false;
}

/** The same lane by lane for VectorizedArray (compare_and_apply_mask). */
template <dealii::SIMDComparison op, typename Scalar, std::size_t width>
dealii::VectorizedArray<Scalar, width>
select (const dealii::VectorizedArray<Scalar, width>                &a,
        const non_deduced_t<dealii::VectorizedArray<Scalar, width>> &b,
        const non_deduced_t<dealii::VectorizedArray<Scalar, width>> &if_true,
        const non_deduced_t<dealii::VectorizedArray<Scalar, width>> &if_false)
{
  return dealii::compare_and_apply_mask<op> (a, b, if_true, if_false);
}

template <typename Number>
Number select_less (const Number                &a,
                    const non_deduced_t<Number> &b,
                    const non_deduced_t<Number> &if_true,
                    const non_deduced_t<Number> &if_false)
{
  return select<dealii::SIMDComparison::less_than> (a, b, if_true, if_false);
}

template <typename Number>
Number select_less_equal (const Number                &a,
                          const non_deduced_t<Number> &b,
                          const non_deduced_t<Number> &if_true,
                          const non_deduced_t<Number> &if_false)
{
  return select<dealii::SIMDComparison::less_than_or_equal> (a, b, if_true, if_false);
}

template <typename Number>
Number select_greater (const Number                &a,
                       const non_deduced_t<Number> &b,
                       const non_deduced_t<Number> &if_true,
                       const non_deduced_t<Number> &if_false)
{
  return select<dealii::SIMDComparison::greater_than> (a, b, if_true, if_false);
}

template <typename Number>
Number select_greater_equal (const Number                &a,
                             const non_deduced_t<Number> &b,
                             const non_deduced_t<Number> &if_true,
                             const non_deduced_t<Number> &if_false)
{
  return select<dealii::SIMDComparison::greater_than_or_equal> (a, b, if_true, if_false);
}

/**
 * Elementary functions for the three number types, called qualified (math::cbrt(x)):
 * std:: for double, Sacado's (by ADL) for ADNumber, deal.II's std:: overloads for
 * VectorizedArray, lane by lane with the double function where deal.II has none (the
 * same bits as the double evaluation).
 */
namespace math
{
template <typename Number>
Number sqrt (const Number &x)
{
  using std::sqrt;
  return sqrt (x);
}

template <typename Number>
Number exp (const Number &x)
{
  using std::exp;
  return exp (x);
}

template <typename Number>
Number log (const Number &x)
{
  using std::log;
  return log (x);
}

template <typename Number>
Number abs (const Number &x)
{
  using std::abs;
  return abs (x);
}

/** x^p with a double exponent. */
template <typename Number>
Number pow (const Number &x, const double p)
{
  using std::pow;
  return pow (x, p);
}

template <typename Number>
Number max (const Number &x, const non_deduced_t<Number> &y)
{
  using std::max;
  return max (x, y);
}

template <typename Number>
Number min (const Number &x, const non_deduced_t<Number> &y)
{
  using std::min;
  return min (x, y);
}

template <typename Number>
Number cbrt (const Number &x)
{
  using std::cbrt;
  return cbrt (x);
}

template <typename Number>
Number tanh (const Number &x)
{
  using std::tanh;
  return tanh (x);
}

template <typename Scalar, std::size_t width>
dealii::VectorizedArray<Scalar, width>
cbrt (const dealii::VectorizedArray<Scalar, width> &x)
{
  dealii::VectorizedArray<Scalar, width> result;
  for (std::size_t lane = 0; lane < width; ++lane)
    result[lane] = std::cbrt (x[lane]);
  return result;
}

template <typename Scalar, std::size_t width>
dealii::VectorizedArray<Scalar, width>
tanh (const dealii::VectorizedArray<Scalar, width> &x)
{
  dealii::VectorizedArray<Scalar, width> result;
  for (std::size_t lane = 0; lane < width; ++lane)
    result[lane] = std::tanh (x[lane]);
  return result;
}
} // namespace math
} // namespace wetbed::closures
