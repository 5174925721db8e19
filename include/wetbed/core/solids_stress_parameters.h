#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace wetbed
{
/** `subsection solids stress`: the rheology of the particle phase. */
struct SolidsStressParameters
{
  std::string model;
  double      shear_viscosity;          // Pa s (constant-viscosity model)
  double      frictional_coefficient;   // Fr, Pa
  double      frictional_exponent_n;    // n
  double      frictional_exponent_p;    // p
  double      frictional_onset;         // alpha_fr,min
  double      minimum_packing_distance; // floor of (alpha_max - alpha)

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm, double maximum_packing);
};
} // namespace wetbed
