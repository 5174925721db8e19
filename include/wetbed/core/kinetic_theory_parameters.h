#pragma once

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <string>

namespace wetbed
{
/** `subsection kinetic theory`: closures and model of the granular temperature. */
struct KineticTheoryParameters
{
  std::string radial_distribution;          // g0 law
  std::string kinetic_viscosity;            // mu_kin law
  std::string conductivity;                 // kappa law
  double      restitution;                  // e (particle-particle, dry)
  double      radial_distribution_cap;      // g0 is evaluated at min(alpha_s, cap)
  bool        algebraic;                    // local equilibrium instead of the PDE
  double      internal_friction_angle;      // phi (rad), Schaeffer
  double      maximum_frictional_viscosity; // Pa s
  double      strain_rate_regularisation;   // eps in sqrt(I_2D + eps^2) (1/s)
  double      minimum_shear_viscosity;      // floor of mu_s where there are no solids
  double      minimum_temperature;          // floor of Theta (m^2/s^2)
  double      maximum_temperature;          // cap of Theta (m^2/s^2), dilute regions
  double      dilute_fraction; // below it Theta is not produced (MFIX DIL_EP_S)

  /** min(1, alpha_s/dilute fraction): the weight of Theta production and conduction. */
  double dilute_weight (const double alpha_s) const
  {
    return std::min (1.0, alpha_s / dilute_fraction);
  }
  double initial_temperature; // Theta at t = 0 (m^2/s^2)
  double specularity;         // Johnson-Jackson phi'
  double wall_restitution;    // e_w

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm, double maximum_packing);
};
} // namespace wetbed
