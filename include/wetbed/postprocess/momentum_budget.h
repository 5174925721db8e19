#pragma once

#include <wetbed/solvers/solver_state.h>

namespace wetbed
{
/** The inertial side of the vertical momentum budget (momentum_budget.cc). */
struct InertialBudget
{
  double momentum = 0, continuity_defect = 0, momentum_outflow = 0;
};

/** After an accepted step (state.time_step): the mixture momentum along -g (kg m/s,
 * per metre depth in 2D), the difference between the conservative momentum change and
 * the assembled inertia (the velocity times the continuity residual of the discrete
 * fractions; large for the advective form), and the momentum flux out through the
 * inlet and outlet (N), from the flow system's linearisation point; collective. */
template <int dim>
InertialBudget evaluate_inertial_budget (const SolverState<dim> &state);
} // namespace wetbed
