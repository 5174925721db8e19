#pragma once

#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/** Conductivity kappa of granular energy (kg m^-1 s^-1; doc/theory.md,
 * "Kinetic-theory closures"). */

/**
 * Gidaspow: 150 rho d sqrt(pi Theta) / (384 (1+e) g0) [1 + 6/5 alpha g0 (1+e)]^2
 *           + 2 alpha^2 rho d g0 (1+e) sqrt(Theta/pi).
 */
struct GidaspowConductivity
{
  static constexpr const char *name = "Gidaspow";
  template <typename Number>
  static Number value (const Number           &alpha,
                       const Number           &theta,
                       const Number           &g0,
                       const GranularMaterial &m)
  {
    using std::sqrt;
    const double e      = m.restitution;
    const double rho_d  = m.particle_density * m.particle_diameter;
    const Number factor = 1.0 + 1.2 * alpha * g0 * (1.0 + e);
    return 150.0 * rho_d * sqrt (M_PI * theta) / (384.0 * (1.0 + e) * g0) * factor *
               factor +
           2.0 * alpha * alpha * rho_d * g0 * (1.0 + e) * sqrt (theta / M_PI);
  }
};

/**
 * Syamlal: 15 d rho alpha sqrt(pi Theta) / (4 (41 - 33 eta)) [1 + 12/5 eta^2 (4 eta - 3)
 * alpha g0 + 16/(15 pi) (41 - 33 eta) eta alpha g0], eta = (1+e)/2.
 */
struct SyamlalConductivity
{
  static constexpr const char *name = "Syamlal";
  template <typename Number>
  static Number value (const Number           &alpha,
                       const Number           &theta,
                       const Number           &g0,
                       const GranularMaterial &m)
  {
    using std::sqrt;
    const double eta = 0.5 * (1.0 + m.restitution);
    return 15.0 * m.particle_diameter * m.particle_density * alpha * sqrt (M_PI * theta) /
           (4.0 * (41.0 - 33.0 * eta)) *
           (1.0 + 2.4 * eta * eta * (4.0 * eta - 3.0) * alpha * g0 +
            16.0 / (15.0 * M_PI) * (41.0 - 33.0 * eta) * eta * alpha * g0);
  }
};
} // namespace wetbed::closures
