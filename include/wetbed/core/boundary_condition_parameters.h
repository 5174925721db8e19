#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace wetbed
{
enum class WallCondition
{
  no_slip,
  free_slip,
  partial_slip,
  johnson_jackson
};

/** `subsection boundary conditions`. */
struct BoundaryConditionParameters
{
  std::string   inlet_superficial_velocity; // function of t (m/s)
  WallCondition gas_wall, solids_wall;
  double        solids_wall_friction; // Robin coefficient, kg m^-2 s^-1 (partial slip)
  bool          nitsche;              // weak no-penetration on slip walls (else strong)
  double        nitsche_penalty;      // gamma_0
  bool          hold_solids;          // u_s held everywhere (fixed bed, frozen shear)
  std::string   held_solids_velocity; // u_s(x, y, z, t) where held, ';'-separated
  std::string   moving_wall_name; // a wall group that slides tangentially; empty: none
  dealii::Tensor<1, 3> moving_wall_velocity; // its velocity (m/s), tangential

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
  /** The inlet velocity finite at 400 times over [0, end_time]; InputError if not. */
  void check_time_span (double end_time) const;
};
} // namespace wetbed
