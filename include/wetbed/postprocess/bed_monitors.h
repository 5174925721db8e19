#pragma once

#include <wetbed/postprocess/monitors.h>
#include <wetbed/solvers/solver_state.h>

namespace wetbed
{
/** The monitors.csv row of the state after a step: pressure drop, FI, the momentum
 * budget (wall forces, inertia, the flow system's boundary reactions), bounds, peak
 * speeds, bed height, Theta, the bed profile (source/postprocess/bed_monitors.cc);
 * collective. */
template <int dim>
MonitorRow evaluate_monitors (const SolverState<dim> &state);
} // namespace wetbed
