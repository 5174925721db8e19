#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Syamlal-O'Brien (1989): beta = 3/4 mu_g alpha_s alpha_g (0.63 sqrt(Re/v_r) + 4.8)^2
 * / (v_r d^2), with Re = rho_g d |u_g - u_s| / mu_g (no alpha_g) and the
 * terminal-velocity ratio v_r (A = alpha_g^4.14, B = 0.8 alpha_g^1.28 for
 * alpha_g <= 0.85, else alpha_g^2.65). The same law as 3 alpha_s alpha_g rho_g |du|
 * C_D(Re/v_r)/(4 v_r^2 d), written to stay finite at zero slip.
 */
struct SyamlalOBrien
{
  static constexpr const char *name = "Syamlal-O'Brien";

  template <typename Number>
  static Number terminal_velocity_ratio (const Number &alpha_g, const Number &reynolds)
  {
    using std::pow;
    using std::sqrt;
    const Number a = pow (alpha_g, 4.14);
    const Number b = select_less_equal (
        alpha_g, 0.85, Number (0.8 * pow (alpha_g, 1.28)), Number (pow (alpha_g, 2.65)));
    const Number r = 0.06 * reynolds;
    return 0.5 * (a - r + sqrt (r * r + 0.12 * reynolds * (2.0 * b - a) + a * a));
  }

  template <typename Number>
  static Number
  beta (const Number &alpha_s, const Number &slip, const GasParticleProperties &p)
  {
    using std::sqrt;
    const Number alpha_g  = 1.0 - alpha_s;
    const Number reynolds = p.gas_density * p.particle_diameter * slip / p.gas_viscosity;
    const Number v_r      = terminal_velocity_ratio (alpha_g, reynolds);
    const Number factor   = 0.63 * sqrt (reynolds / v_r) + 4.8;
    return 0.75 * p.gas_viscosity * alpha_s * alpha_g * factor * factor /
           (v_r * p.particle_diameter * p.particle_diameter);
  }
};
} // namespace wetbed::closures
