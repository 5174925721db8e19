#pragma once

#include <wetbed/closures/frictional/johnson_jackson_pressure.h>
#include <wetbed/closures/frictional/schaeffer_viscosity.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>

#include <algorithm>

namespace wetbed::closures
{
/**
 * Kinetic theory of granular flow with friction (doc/theory.md,
 * "Kinetic-theory closures"):
 *   P_s = P_fr(alpha_s) [Johnson-Jackson, the compaction pressure] + alpha rho Theta
 *         [1 + 2(1+e) alpha g0] [Lun, the kinetic pressure],
 *   mu_s = mu_col + mu_kin + mu_fr + mu_wet, mu_fr = Schaeffer with P_fr (capped),
 *   mu_wet the liquid-bridge viscosity of a wet scene (P_wet optionally added to P_s),
 *   lambda_s = Lun bulk viscosity,
 * mu_s floored where alpha_s or Theta vanish (the solids block stays regular).
 */
class KineticTheoryRheology : public SolidsStressModel
{
public:
  static constexpr const char *model_name = "kinetic theory";

  KineticTheoryRheology (std::shared_ptr<const KineticTheory> theory,
                         JohnsonJacksonPressureCoefficients   friction,
                         double                               friction_angle,
                         double maximum_frictional_viscosity,
                         double strain_regularisation,
                         double minimum_viscosity,
                         bool   wet_pressure_in_solids_pressure)
      : theory (std::move (theory)), friction (friction), friction_angle (friction_angle),
        maximum_frictional_viscosity (maximum_frictional_viscosity),
        strain_regularisation (strain_regularisation),
        minimum_viscosity (minimum_viscosity),
        wet_pressure_in_solids_pressure (wet_pressure_in_solids_pressure)
  {
  }

  /** From `solids stress` (frictional pressure), `kinetic theory` and `wet particles`. */
  static std::unique_ptr<SolidsStressModel> create (const SolidsStressSettings &settings);

  std::string name () const override { return model_name; }

  SolidsStress evaluate (const SolidsState &state) const override
  {
    const double pressure = johnson_jackson_pressure (state.alpha_s, friction);
    const auto   c        = theory->evaluate (state.alpha_s, state.granular_temperature);
    // I_2D = 1/2 D_dev : D_dev = shear_rate^2 / 4
    const double frictional_viscosity =
        pressure > 0 ? schaeffer_viscosity (pressure,
                                            0.25 * state.shear_rate * state.shear_rate,
                                            friction_angle,
                                            strain_regularisation,
                                            maximum_frictional_viscosity)
                     : 0.0;
    SolidsStress s;
    s.pressure            = pressure;
    s.pressure_derivative = johnson_jackson_pressure_derivative (state.alpha_s, friction);
    s.kinetic_pressure = c.pressure_factor * std::max (state.granular_temperature, 0.0);
    s.frictional_viscosity = frictional_viscosity;
    if (const WetParticles *wet = theory->wet ())
    {
      const WetClosures w = wet->evaluate (state.alpha_s,
                                           state.granular_temperature,
                                           0.25 * state.shear_rate * state.shear_rate,
                                           state.velocity_divergence);
      s.wet_viscosity     = w.viscosity;
      s.wet_pressure      = w.pressure;
      if (wet_pressure_in_solids_pressure)
        s.kinetic_pressure += w.pressure;
    }
    s.shear_viscosity = std::max (
        c.shear_viscosity + frictional_viscosity + s.wet_viscosity, minimum_viscosity);
    s.bulk_viscosity = c.bulk_viscosity;
    return s;
  }

  const KineticTheory *kinetic_theory () const override { return theory.get (); }

private:
  std::shared_ptr<const KineticTheory> theory;
  JohnsonJacksonPressureCoefficients   friction;
  double friction_angle, maximum_frictional_viscosity, strain_regularisation,
      minimum_viscosity;
  bool wet_pressure_in_solids_pressure;
};
} // namespace wetbed::closures
