#pragma once

#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Schaeffer (1987) frictional viscosity mu_fr = P_fr sin(phi) / (2 sqrt(I_2D + eps^2)),
 * capped at mu_max (MFIX caps at 100 Pa s). I_2D is the second invariant of the
 * deviatoric strain rate, 1/6[(D11-D22)^2 + (D22-D33)^2 + (D33-D11)^2] + D12^2 + D23^2 +
 * D31^2; eps regularises a vanishing strain rate (doc/theory.md,
 * "Kinetic-theory closures"). In simple shear the stress is P_fr sin(phi), Mohr-Coulomb.
 */
template <typename Number>
Number schaeffer_viscosity (const Number &frictional_pressure,
                            const Number &second_invariant,
                            const double  internal_friction_angle,
                            const double  regularisation,
                            const double  maximum_viscosity)
{
  using std::sin;
  using std::sqrt;
  const Number mu = frictional_pressure * sin (internal_friction_angle) /
                    (2.0 * sqrt (second_invariant + regularisation * regularisation));
  return select_less (mu, maximum_viscosity, mu, Number (maximum_viscosity));
}
} // namespace wetbed::closures
