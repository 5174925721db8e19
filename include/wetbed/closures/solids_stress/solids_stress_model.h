#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/frictional/johnson_jackson_pressure.h>

#include <memory>
#include <string>

namespace wetbed
{
struct SolidsStressParameters;
struct PhysicalProperties;
struct KineticTheoryParameters;
struct WetParticleParameters;
} // namespace wetbed

namespace wetbed::closures
{
/** The local state the solids stress depends on. */
struct SolidsState
{
  double alpha_s;
  double granular_temperature;    // Theta (m^2/s^2); 0 without kinetic theory
  double shear_rate;              // sqrt(2 D_dev : D_dev) (1/s)
  double velocity_divergence = 0; // div u_s (1/s)
};

/** Solids pressure and viscosities at one quadrature point. */
struct SolidsStress
{
  double pressure;             // compaction P_s(alpha_s) (Pa), interpolated from nodes
  double pressure_derivative;  // dP_s/dalpha_s (Pa)
  double shear_viscosity;      // mu_s (Pa s), MFIX convention (no alpha_s in front)
  double bulk_viscosity;       // lambda_s (Pa s)
  double kinetic_pressure = 0; // P_kin+col(alpha_s, Theta) (Pa), at the point
  // parts of mu_s and of the pressure, for reports (wetbed closures)
  double frictional_viscosity = 0; // mu_fr (Pa s), Schaeffer
  double wet_viscosity        = 0; // mu_wet (Pa s), liquid bridges
  double wet_pressure         = 0; // P_wet (Pa) (in kinetic_pressure only if chosen)
};

class KineticTheory;

/**
 * Rheology of the particle phase: tau_s = 2 mu_s D + (lambda_s - 2/3 mu_s) div u_s I and
 * the solids pressure P_s. The kinetic theory plugs in here.
 */
class SolidsStressModel
{
public:
  virtual ~SolidsStressModel ()                                  = default;
  virtual std::string  name () const                             = 0;
  virtual SolidsStress evaluate (const SolidsState &state) const = 0;
  /** The kinetic theory behind the model, if any (then Theta is solved for). */
  virtual const KineticTheory *kinetic_theory () const { return nullptr; }
};

/** What a rheology is built from: the parameter sections it reads. */
struct SolidsStressSettings
{
  const SolidsStressParameters  &stress;
  const PhysicalProperties      &physical;
  const KineticTheoryParameters &kinetic;
  const WetParticleParameters   &wet;
};

/** The rheology registered under `solids stress/model` (solids_stress_laws.h). */
std::unique_ptr<SolidsStressModel>
create_solids_stress_model (const SolidsStressParameters  &parameters,
                            const PhysicalProperties      &physical,
                            const KineticTheoryParameters &kinetic,
                            const WetParticleParameters   &wet);

std::string solids_stress_model_names ();

/** The Johnson-Jackson frictional pressure's coefficients of `solids stress`. */
JohnsonJacksonPressureCoefficients
johnson_jackson_coefficients (const SolidsStressParameters &stress,
                              const PhysicalProperties     &physical);
} // namespace wetbed::closures
