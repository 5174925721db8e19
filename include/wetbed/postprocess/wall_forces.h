#pragma once

#include <wetbed/solvers/solver_state.h>

namespace wetbed
{
/** Vertical forces (N, per metre depth in 2D) of the boundaries on the phases. */
struct WallForces
{
  double solids_wall = 0, gas_wall = 0, distributor = 0, outlet = 0;
};

/** The forces of the walls (each phase's wall condition), the inlet and the outlet
 * on the phases along -g (source/postprocess/wall_forces.cc); collective. */
template <int dim>
WallForces evaluate_wall_forces (const SolverState<dim> &state);
} // namespace wetbed
