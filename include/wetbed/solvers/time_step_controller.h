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
  // the largest over the cells of max(u_s, granular sound, u_g/4 where the cell holds
  // solids) per the cell's own Q2 node spacing (1/s): the Courant number per unit step
  double courant_rate = 0;
};

/**
 * The next time step from the last one, the current wave speeds and the last step's
 * time-error estimate (`time stepping`): the Courant target on the solids speed, the
 * kinetic pressure's sound speed and a quarter of the gas speed, per cell on its own
 * node spacing (`courant measure = local`) or the peaks on the smallest spacing
 * (`global`); with a `time error tolerance` tol > 0 also dt (tol/e)^(1/2) x 0.9 for an
 * estimate e (the error of a first-order step grows as dt^2), never below dt/2; at most
 * `growth factor` times the last step and `maximum time step`; the last step unchanged
 * when not adaptive (doc/theory.md "Time step").
 */
class TimeStepController
{
public:
  explicit TimeStepController (const TimeSteppingParameters &parameters)
      : parameters (parameters)
  {
  }

  double next (double            dt,
               const WaveSpeeds &speeds,
               double            node_spacing,
               double            time_error) const;

  /** The step to take from `time` with the planned step `dt`: the rest up to
   * `end_time` where that is at most 1% longer than dt, half the rest where that is
   * shorter than 2 dt, else dt; so that no sliver of a step is left for the end (a step
   * far shorter than the last makes the BDF2 coefficients and the pressure, which
   * scales with 1/dt, blow up). */
  static double step_towards_end (double dt, double time, double end_time);

  /** The step the Courant target allows alone. */
  double courant_limit (const WaveSpeeds &speeds, double node_spacing) const;

private:
  const TimeSteppingParameters &parameters;
};
} // namespace wetbed
