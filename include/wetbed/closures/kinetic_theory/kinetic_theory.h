#pragma once

#include <wetbed/closures/kinetic_theory/algebraic_granular_temperature.h>
#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/closures/walls/johnson_jackson_wall.h>

#include <memory>

namespace wetbed
{
struct KineticTheoryParameters;
struct PhysicalProperties;
} // namespace wetbed

namespace wetbed::closures
{
/**
 * The kinetic theory of granular flow at one point: the laws chosen in the .prm (g0,
 * kinetic viscosity, conductivity) and the single-form terms (Lun pressure, collisional
 * and bulk viscosity, dissipation), evaluated together from (alpha_s, Theta). g0 is
 * evaluated at min(alpha_s, cap).
 */
class KineticTheory
{
public:
  KineticTheory (const KineticTheoryParameters &parameters,
                 const PhysicalProperties      &physical);
  ~KineticTheory ();

  struct Coefficients
  {
    double g0;
    double pressure_factor;    // P_kin+col / Theta = alpha rho [1 + 2(1+e) alpha g0]
    double shear_viscosity;    // mu_col + mu_kin (Pa s)
    double bulk_viscosity;     // lambda_s (Pa s)
    double conductivity;       // kappa (kg m^-1 s^-1)
    double dissipation_factor; // gamma / Theta^(3/2)
  };
  Coefficients evaluate (double alpha_s, double theta) const;

  double radial_distribution (double alpha_s) const;

  /** Local-equilibrium Theta for the strain rate D of u_s and the drag beta. */
  double algebraic_temperature (double alpha_s,
                                double trace_d,
                                double d_ddot_d,
                                double beta) const;

  const GranularMaterial   &material () const { return granular; }
  const JohnsonJacksonWall &wall () const { return jj_wall; }

private:
  GranularMaterial                          granular;
  double                                    cap;
  std::unique_ptr<RadialDistribution>       g0_law;
  std::unique_ptr<KineticTheoryCoefficient> viscosity_law, conductivity_law;
  AlgebraicGranularTemperature              equilibrium;
  JohnsonJacksonWall                        jj_wall;
};
} // namespace wetbed::closures
