#pragma once

#include <wetbed/postprocess/monitors.h>
#include <wetbed/solvers/solver_state.h>

namespace wetbed
{
/** Plane averages, the bed surface and the point probes into `row`
 * (source/postprocess/bed_profile.cc); collective. */
template <int dim>
void evaluate_bed_profile (const SolverState<dim> &state, MonitorRow &row);
} // namespace wetbed
