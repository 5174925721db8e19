#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/drag/wen_yu.h>
#include <wetbed/closures/number_traits.h>

namespace wetbed::closures
{
/**
 * Gidaspow (1994): Ergun, beta = 150 alpha_s^2 mu_g/(alpha_g d^2) + 1.75 alpha_s rho_g
 * |du|/d, for alpha_g <= 0.8 (MFIX convention), Wen-Yu above.
 */
struct Gidaspow
{
  static constexpr const char *name = "Gidaspow";

  template <typename Number>
  static Number
  ergun (const Number &alpha_s, const Number &slip, const GasParticleProperties &p)
  {
    const double d       = p.particle_diameter;
    const Number alpha_g = 1.0 - alpha_s;
    return 150.0 * alpha_s * alpha_s * p.gas_viscosity / (alpha_g * d * d) +
           1.75 * alpha_s * p.gas_density * slip / d;
  }

  template <typename Number>
  static Number
  beta (const Number &alpha_s, const Number &slip, const GasParticleProperties &p)
  {
    const Number alpha_g = 1.0 - alpha_s;
    return select_less_equal (
        alpha_g, 0.8, ergun (alpha_s, slip, p), WenYu::beta (alpha_s, slip, p));
  }
};
} // namespace wetbed::closures
