#include <wetbed/solvers/time_step_controller.h>

#include <algorithm>

namespace wetbed
{
double TimeStepController::next (const double      dt,
                                 const WaveSpeeds &speeds,
                                 const double      node_spacing) const
{
  if (!parameters.adaptive)
    return dt;
  const double speed =
      std::max ({speeds.solids, 0.25 * speeds.gas, speeds.granular_sound, 1e-12});
  const double cfl_dt = parameters.cfl_target * node_spacing / speed;
  return std::min ({parameters.maximum_time_step, parameters.growth_factor * dt, cfl_dt});
}
} // namespace wetbed
