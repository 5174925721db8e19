#pragma once

#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * The terms of the kinetic theory with a single accepted form (Lun et al. 1984;
 * doc/theory.md, "Kinetic-theory closures"), MFIX stress convention.
 */
struct CollisionalTerms
{
  /** P_s = alpha rho Theta [1 + 2 (1+e) alpha g0] (kinetic + collisional), Pa. */
  template <typename Number>
  static Number solids_pressure (const Number           &alpha,
                                 const Number           &theta,
                                 const Number           &g0,
                                 const GranularMaterial &m)
  {
    return alpha * m.particle_density * theta *
           (1.0 + 2.0 * (1.0 + m.restitution) * alpha * g0);
  }

  /** mu_col = 4/5 alpha^2 rho d g0 (1+e) sqrt(Theta/pi), Pa s. */
  template <typename Number>
  static Number shear_viscosity (const Number           &alpha,
                                 const Number           &theta,
                                 const Number           &g0,
                                 const GranularMaterial &m)
  {
    using std::sqrt;
    return 0.8 * alpha * alpha * m.particle_density * m.particle_diameter * g0 *
           (1.0 + m.restitution) * sqrt (theta / M_PI);
  }

  /** lambda_s = 4/3 alpha^2 rho d g0 (1+e) sqrt(Theta/pi), Pa s. */
  template <typename Number>
  static Number bulk_viscosity (const Number           &alpha,
                                const Number           &theta,
                                const Number           &g0,
                                const GranularMaterial &m)
  {
    using std::sqrt;
    return 4.0 / 3.0 * alpha * alpha * m.particle_density * m.particle_diameter * g0 *
           (1.0 + m.restitution) * sqrt (theta / M_PI);
  }

  /**
   * gamma = 12 (1 - e^2) g0 rho alpha^2 Theta^(3/2) / (d sqrt(pi)), W/m^3; e is the
   * restitution of the dissipation (the wet one where liquid bridges form).
   */
  template <typename Number>
  static Number dissipation (const Number           &alpha,
                             const Number           &theta,
                             const Number           &g0,
                             const GranularMaterial &m,
                             const double            restitution)
  {
    using std::sqrt;
    return 12.0 * (1.0 - restitution * restitution) * g0 * m.particle_density * alpha *
           alpha * theta * sqrt (theta) / (m.particle_diameter * sqrt (M_PI));
  }
};
} // namespace wetbed::closures
