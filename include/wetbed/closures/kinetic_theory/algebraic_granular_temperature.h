#pragma once

#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Local-equilibrium (algebraic) granular temperature (doc/theory.md, "Granular energy"):
 * the granular-energy balance without convection and conduction,
 *   sigma_s : grad u_s - gamma - 3 beta Theta = 0,
 * with the Syamlal-Rogers-O'Brien closures written as P = p_hat Theta,
 * mu = K3 alpha sqrt(Theta), lambda - 2/3 mu = K2 alpha sqrt(Theta),
 * gamma = K4 alpha^2 Theta^(3/2). For x = sqrt(Theta):
 *   K4 alpha^2 x^2 + (p_hat tr D + 3 beta) x - alpha (2 K3 D:D + K2 (tr D)^2) = 0,
 * the positive root (0 without shear). kinetic_pressure = true and leading = 1 is
 * OpenFOAM's 'equilibrium on' branch; false and (3e+1)/2 reproduce MFIX gt_algebraic.
 */
struct AlgebraicGranularTemperature
{
  bool   kinetic_pressure = true;
  double leading          = 1.0;

  template <typename Number>
  Number value (const Number           &alpha,
                const Number           &g0,
                const Number           &trace_d,
                const Number           &d_ddot_d,
                const Number           &beta,
                const GranularMaterial &m) const
  {
    using std::sqrt;
    const double e     = m.restitution;
    const double rho   = m.particle_density;
    const double d     = m.particle_diameter;
    const double pi    = M_PI;
    const Number k1    = 2.0 * (1.0 + e) * rho * g0;
    const Number p_hat = kinetic_pressure ? Number (alpha * (rho + k1 * alpha))
                                          : Number (k1 * alpha * alpha);
    const Number k3    = 0.5 * d * rho *
                      (sqrt (pi) / (3.0 * (3.0 - e)) *
                           (leading + 0.4 * (1.0 + e) * (3.0 * e - 1.0) * alpha * g0) +
                       1.6 * alpha * g0 * (1.0 + e) / sqrt (pi));
    const Number k2 =
        4.0 * d * rho * (1.0 + e) * alpha * g0 / (3.0 * sqrt (pi)) - 2.0 / 3.0 * k3;
    const Number k4 = 12.0 * (1.0 - e * e) * rho * g0 / (d * sqrt (pi));
    const Number a  = k4 * alpha * alpha;
    const Number b  = p_hat * trace_d + 3.0 * beta;
    const Number c  = alpha * (2.0 * k3 * d_ddot_d + k2 * trace_d * trace_d);
    // the positive root, written without cancellation for either sign of b
    const Number root = sqrt (b * b + 4.0 * a * c);
    const Number x    = select_greater_equal (
        b, 0.0, Number (2.0 * c / (b + root)), Number ((root - b) / (2.0 * a)));
    // 0 unless c > 0 and a > 0 (also where either is NaN)
    const Number zero (0.0);
    return select_greater (c, 0.0, select_greater (a, 0.0, Number (x * x), zero), zero);
  }
};
} // namespace wetbed::closures
