#include <wetbed/solvers/time_step_controller.h>

#include <algorithm>
#include <cmath>

namespace wetbed
{
double TimeStepController::courant_limit (const WaveSpeeds &speeds,
                                          const double      node_spacing) const
{
  if (parameters.local_courant)
    return parameters.cfl_target / std::max (speeds.courant_rate, 1e-12);
  const double speed =
      std::max ({speeds.solids, 0.25 * speeds.gas, speeds.granular_sound, 1e-12});
  return parameters.cfl_target * node_spacing / speed;
}

double TimeStepController::next (const double      dt,
                                 const WaveSpeeds &speeds,
                                 const double      node_spacing,
                                 const double      time_error) const
{
  if (!parameters.adaptive)
    return dt;
  double       next      = std::min ({parameters.maximum_time_step,
                                      parameters.growth_factor * dt,
                                      courant_limit (speeds, node_spacing)});
  const double tolerance = parameters.time_error_tolerance;
  if (tolerance > 0 && time_error > 0)
    next = std::min (next, dt * std::max (0.5, 0.9 * std::sqrt (tolerance / time_error)));
  return next;
}

double TimeStepController::step_towards_end (const double dt,
                                             const double time,
                                             const double end_time)
{
  // a rest up to 1% longer than dt: one step; up to 2 dt: two equal steps (the first of
  // them here), so that the last step is never shorter than half the one before it
  const double rest = end_time - time;
  if (rest <= 1.01 * dt)
    return rest;
  return rest < 2 * dt ? 0.5 * rest : dt;
}
} // namespace wetbed
