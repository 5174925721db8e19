#pragma once

#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Johnson-Jackson (1987) partial-slip wall for the solids (doc/theory.md,
 * "Johnson-Jackson walls"), n the outward normal of the solids domain:
 *   tangential traction (sigma_s n)_t = -C_JJ u_slip,
 *   C_JJ = sqrt(3) pi phi' (alpha_s/alpha_max) rho_s g0 sqrt(Theta) / 6,
 *   granular-energy flux kappa dTheta/dn = G_w - D_w, G_w = C_JJ |u_slip|^2,
 *   D_w = sqrt(3) pi (1 - e_w^2) (alpha_s/alpha_max) rho_s g0 Theta^(3/2) / 4.
 * (OpenFOAM's JohnsonJacksonParticleTheta drops rho_s in D_w; this keeps it.)
 */
struct JohnsonJacksonWall
{
  double specularity;      // phi'
  double wall_restitution; // e_w
  double maximum_packing;  // alpha_max
  double particle_density; // rho_s

  template <typename Number>
  Number
  shear_coefficient (const Number &alpha, const Number &g0, const Number &theta) const
  {
    using std::sqrt;
    return M_PI * sqrt (3.0) * specularity * alpha * particle_density * g0 *
           sqrt (theta) / (6.0 * maximum_packing);
  }

  template <typename Number>
  Number energy_generation (const Number &alpha,
                            const Number &g0,
                            const Number &theta,
                            const Number &slip_speed) const
  {
    return shear_coefficient (alpha, g0, theta) * slip_speed * slip_speed;
  }

  template <typename Number>
  Number
  energy_dissipation (const Number &alpha, const Number &g0, const Number &theta) const
  {
    using std::sqrt;
    return M_PI * sqrt (3.0) * (1.0 - wall_restitution * wall_restitution) * alpha *
           particle_density * g0 * theta * sqrt (theta) / (4.0 * maximum_packing);
  }
};
} // namespace wetbed::closures
