#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Wen-Yu (1966): beta = 3/4 C_D alpha_s alpha_g rho_g |du| alpha_g^-2.65 / d,
 * C_D = 24/(alpha_g Re)[1 + 0.15 (alpha_g Re)^0.687] for alpha_g Re < 1000, else 0.44.
 * The Stokes part is written as 18 mu_g alpha_s alpha_g^-2.65 (1 + ...)/d^2 so that it
 * stays finite at zero slip.
 */
struct WenYu
{
  static constexpr const char *name = "Wen-Yu";

  template <typename Number>
  static Number
  beta (const Number &alpha_s, const Number &slip, const GasParticleProperties &p)
  {
    using std::pow;
    const Number alpha_g = 1.0 - alpha_s;
    const Number reynolds =
        alpha_g * p.gas_density * p.particle_diameter * slip / p.gas_viscosity;
    const double d         = p.particle_diameter;
    const Number hindrance = pow (alpha_g, -2.65);
    const Number stokes    = 18.0 * p.gas_viscosity * alpha_s * hindrance *
                          (1.0 + 0.15 * pow (reynolds, 0.687)) / (d * d);
    const Number newton =
        0.75 * 0.44 * alpha_s * alpha_g * p.gas_density * slip * hindrance / d;
    return select_less (reynolds, 1000.0, stokes, newton);
  }
};
} // namespace wetbed::closures
