#pragma once

#include <wetbed/solvers/solver_state.h>

namespace wetbed
{
/** The pressure drop across the bed and the fluidization index. */
struct PressureDrop
{
  double pressure_drop   = 0; // mean p' over the inlet minus the mean over the outlet, Pa
  double inlet_area      = 0; // m^2 (m in 2D)
  double outlet_pressure = 0; // mean p' over the outlet, Pa
  double fluidization    = 0; // dP A / buoyant bed weight; 0 without inlet or outlet
};

/** The pressure drop of the state (p' excludes the gas hydrostatic part, so the bed
 * weight is taken net of buoyancy) and FI = dP A / ((M_s (1 - rho_g/rho_s)) |g|) with
 * the solids mass of `solids_mass` (kg, per metre depth in 2D); a closed or periodic
 * domain has no inlet or outlet: no pressure drop, no FI
 * (source/postprocess/pressure_drop.cc); collective. */
template <int dim>
PressureDrop evaluate_pressure_drop (const SolverState<dim> &state, double solids_mass);
} // namespace wetbed
