#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/number_traits.h>

namespace wetbed::closures
{
/**
 * No interphase momentum exchange, beta = 0: the phases only share the pressure. For
 * verification of the granular phase alone (Haff's homogeneous cooling, frozen shear),
 * where the gas must not damp the particle fluctuations.
 */
struct NoDrag
{
  static constexpr const char *name = "none";

  template <typename Number>
  static Number
  beta (const Number &alpha_s, const Number & /*slip*/, const GasParticleProperties &)
  {
    return 0.0 * alpha_s;
  }
};
} // namespace wetbed::closures
