#pragma once

#include <wetbed/closures/kinetic_theory/algebraic_granular_temperature.h>
#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/closures/walls/johnson_jackson_wall.h>
#include <wetbed/closures/wet/wet_particles.h>

#include <memory>

namespace wetbed
{
struct KineticTheoryParameters;
struct PhysicalProperties;
struct WetParticleParameters;
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
  /** With a positive liquid loading in `wet` the wet closures are built and e_wet
   * replaces e in the collisional dissipation (only there). */
  KineticTheory (const KineticTheoryParameters &parameters,
                 const PhysicalProperties      &physical,
                 const WetParticleParameters   &wet);
  ~KineticTheory ();

  struct Coefficients
  {
    double g0;
    double pressure_factor;       // P_kin+col / Theta = alpha rho [1 + 2(1+e) alpha g0]
    double shear_viscosity;       // mu_col + mu_kin (Pa s)
    double collisional_viscosity; // mu_col alone (Pa s), for the stress split
    double bulk_viscosity;        // lambda_s (Pa s)
    double conductivity;          // kappa (kg m^-1 s^-1)
    double dissipation_factor;    // gamma / Theta^(3/2)
    double restitution;           // e in gamma: e_wet in a wet scene, else e_dry
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
  /** The wet closures; null in a dry scene. */
  const WetParticles *wet () const { return wet_particles.get (); }

private:
  GranularMaterial                          granular;
  double                                    cap;
  std::unique_ptr<RadialDistribution>       g0_law;
  std::unique_ptr<KineticTheoryCoefficient> viscosity_law, conductivity_law;
  AlgebraicGranularTemperature              equilibrium;
  JohnsonJacksonWall                        jj_wall;
  std::unique_ptr<WetParticles>             wet_particles;
};
} // namespace wetbed::closures
