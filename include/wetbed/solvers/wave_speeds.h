#pragma once

#include <wetbed/solvers/solver_state.h>
#include <wetbed/solvers/time_step_controller.h>

namespace wetbed
{
/** The peak speeds of the state's fields (source/solvers/wave_speeds.cc); collective. */
template <int dim>
WaveSpeeds evaluate_wave_speeds (const SolverState<dim> &state);
} // namespace wetbed
