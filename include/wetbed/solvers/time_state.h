#pragma once

namespace wetbed
{
/**
 * Where the time integration stands: the time, the steps and their counters. A
 * checkpoint keeps the first five (Checkpointing); the others describe the last step and
 * the run since its start or resume.
 */
struct TimeState
{
  double       time               = 0;
  double       time_step          = 0; // the next step to try (s)
  double       previous_time_step = 0; // the last accepted step (0 before the first)
  unsigned int step_number        = 0; // accepted steps
  unsigned int rejected_steps     = 0;
  // the last attempt's FGMRES and outer iterations, whether its outer iterations
  // converged
  unsigned int last_krylov_iterations = 0, last_outer_iterations = 0;
  bool         last_outer_converged = true;
  // over the accepted steps of this run: the outer iterations, the FGMRES iterations
  // and the steps that used all `outer iterations` (outer tolerance > 0; the test of
  // the last iterate would need another assembly)
  unsigned int       outer_iterations_run = 0, unconverged_steps = 0;
  unsigned long long krylov_iterations_run = 0;
  double             time_error = 0; // alpha_s's local error estimate of the last step
};
} // namespace wetbed
