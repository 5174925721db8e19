#pragma once

#include <wetbed/closures/frictional/johnson_jackson_pressure.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>

namespace wetbed::closures
{
/**
 * The simple rheology of the core solver: constant shear viscosity, no bulk
 * viscosity, and the Johnson-Jackson frictional (compaction) pressure.
 */
class ConstantViscosityRheology : public SolidsStressModel
{
public:
  static constexpr const char *model_name = "constant viscosity";

  ConstantViscosityRheology (double shear_viscosity, JohnsonJacksonPressureCoefficients c)
      : shear_viscosity (shear_viscosity), coefficients (c)
  {
  }

  /** From `solids stress` (shear viscosity, frictional pressure). */
  static std::unique_ptr<SolidsStressModel> create (const SolidsStressSettings &settings);

  std::string name () const override { return model_name; }

  SolidsStress evaluate (const SolidsState &state) const override
  {
    return {johnson_jackson_pressure (state.alpha_s, coefficients),
            johnson_jackson_pressure_derivative (state.alpha_s, coefficients),
            shear_viscosity,
            0.0};
  }

private:
  double                             shear_viscosity;
  JohnsonJacksonPressureCoefficients coefficients;
};
} // namespace wetbed::closures
