#pragma once

#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Kinetic (streaming) part of the solids shear viscosity, MFIX convention (a full dynamic
 * viscosity, no alpha_s in front in the stress; doc/theory.md, "Conventions").
 */

/** Gidaspow: 10 rho d sqrt(pi Theta) / (96 (1+e) g0) [1 + 4/5 alpha g0 (1+e)]^2. */
struct GidaspowKineticViscosity
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
    const Number factor = 1.0 + 0.8 * alpha * g0 * (1.0 + e);
    return 10.0 * m.particle_density * m.particle_diameter * sqrt (M_PI * theta) /
           (96.0 * (1.0 + e) * g0) * factor * factor;
  }
};

/**
 * Syamlal-Rogers-O'Brien: alpha rho d sqrt(pi Theta) / (6 (3-e)) [1 + 2/5 (1+e)(3e-1)
 * alpha g0] (leading 1 as OpenFOAM, Fluent and seed 000; MFIX gt_algebraic has (3e+1)/2).
 */
struct SyamlalKineticViscosity
{
  static constexpr const char *name = "Syamlal";
  template <typename Number>
  static Number value (const Number           &alpha,
                       const Number           &theta,
                       const Number           &g0,
                       const GranularMaterial &m)
  {
    using std::sqrt;
    const double e = m.restitution;
    return alpha * m.particle_density * m.particle_diameter * sqrt (M_PI * theta) /
           (6.0 * (3.0 - e)) * (1.0 + 0.4 * (1.0 + e) * (3.0 * e - 1.0) * alpha * g0);
  }
};
} // namespace wetbed::closures
