#pragma once

#include <wetbed/boundary_conditions/wall_conditions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace wetbed
{
/** The inflow of one inlet group (`boundary conditions/inlet velocities`, `inlet mass
 * flow rates`, `inlet directions`, `inlet solids`). */
struct InletGroup
{
  std::string         name;
  std::string         velocity;  // superficial velocity (m/s), function of x, y, (z,) t
  std::string         mass_flow; // kg/s (kg/s per metre depth in 2D), function of t
  std::vector<double> direction; // the inflow's direction; empty: against gravity
  // solids fed through the group: their volume fraction and speed along the direction
  // (m/s); 0, 0: none (the solids velocity is held at zero there)
  double solids_fraction = 0, solids_speed = 0;
  bool   feeds_solids () const { return solids_fraction > 0; }
};

/** `subsection boundary conditions`. */
struct BoundaryConditionParameters
{
  std::string             inlet_superficial_velocity; // function of t (m/s)
  std::vector<InletGroup> inlet_groups;               // the groups with their own inflow
  WallConditionChoice     gas_wall, solids_wall;
  // Robin coefficients of a partial-slip wall, kg m^-2 s^-1
  double      gas_wall_friction, solids_wall_friction;
  bool        nitsche;              // weak no-penetration on slip walls (else strong)
  double      nitsche_penalty;      // gamma_0
  bool        hold_solids;          // u_s held everywhere (fixed bed, frozen shear)
  std::string held_solids_velocity; // u_s(x, y, z, t) where held, ';'-separated
  std::string moving_wall_name;     // a wall group that slides tangentially; empty: none
  dealii::Tensor<1, 3> moving_wall_velocity; // its velocity (m/s), tangential

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);

  /** The wall-condition choices of the gas and the solids, in Phase order. */
  std::array<WallConditionChoice, 2> wall_choices () const
  {
    return {{gas_wall, solids_wall}};
  }
  /** What the wall conditions of each phase are built from. */
  std::array<WallConditionSettings, 2>
  wall_settings (const closures::KineticTheory *kinetic_theory,
                 bool                           has_kinetic_theory) const
  {
    return {{{Phase::gas, gas_wall_friction, kinetic_theory, has_kinetic_theory},
             {Phase::solids, solids_wall_friction, kinetic_theory, has_kinetic_theory}}};
  }
  /** Builds every named condition once: InputError naming the parameter where one
   * cannot be (partial slip without friction, Johnson-Jackson without kinetic theory
   * or for the gas). */
  void check_wall_conditions (bool has_kinetic_theory) const;
  /** The inlet groups name groups of `inlet_names`, each once with a velocity or a
   * mass flow (not both), with expressions muparser reads in the variables of `dim`,
   * directions of `dim` components that are not zero, and a solids feed with a
   * fraction in (0, maximum_packing) and a positive finite speed; InputError naming
   * the parameter and the group if not. */
  void check_inlet_groups (const std::vector<std::string> &inlet_names,
                           unsigned int                    dim,
                           double                          maximum_packing);
  /** Whether any inlet group feeds solids. */
  bool feeds_solids () const;
  /** The inlet velocity finite at 400 times over [0, end_time]; InputError if not. */
  void check_time_span (double end_time) const;
};
} // namespace wetbed
