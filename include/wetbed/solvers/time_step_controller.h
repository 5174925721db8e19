#pragma once

#include <wetbed/core/parameters.h>

namespace wetbed
{
/** The signal speeds the explicit parts of a step see (m/s). */
struct WaveSpeeds
{
  double gas            = 0; // peak |u_g| over the Q2 nodes
  double solids         = 0; // peak |u_s| over the vertices where alpha_s > 1e-3
  double granular_sound = 0; // sqrt(2 P_kin/(alpha_s rho_s)), the kinetic pressure's
};

/**
 * The next time step from the last one and the current wave speeds (`time stepping`):
 * the Courant target on the solids speed, the kinetic pressure's sound speed and a
 * quarter of the gas speed per Q2 node spacing, at most `growth factor` times the last
 * step and `maximum time step`; the last step unchanged when not adaptive.
 */
class TimeStepController
{
public:
  explicit TimeStepController (const TimeSteppingParameters &parameters)
      : parameters (parameters)
  {
  }

  double next (double dt, const WaveSpeeds &speeds, double node_spacing) const;

private:
  const TimeSteppingParameters &parameters;
};
} // namespace wetbed
