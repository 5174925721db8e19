// The time-step controller (doc/theory.md "Time step"): the Courant limit per cell
// (local) against the global peaks, the time-error limit, and the alpha_s time-error
// estimate on fields sampled from known functions of time.
#include "test_utilities.h"

#include <wetbed/solvers/time_error.h>
#include <wetbed/solvers/time_step_controller.h>

#include <deal.II/base/mpi.h>

using namespace wetbed;
using wetbed::testing::check;
using wetbed::testing::check_close;
using Vector = dealii::LinearAlgebra::distributed::Vector<double>;

namespace
{
TimeSteppingParameters parameters ()
{
  TimeSteppingParameters p{};
  p.maximum_time_step    = 1e-2;
  p.cfl_target           = 0.5;
  p.growth_factor        = 1.2;
  p.adaptive             = true;
  p.local_courant        = true;
  p.time_error_tolerance = 0;
  return p;
}

/** Three nodes sampled from alpha(t) at t_{n-1}, t_n, t_{n+1}; the third never holds
 * solids. */
double estimate (const std::function<double (double)> &alpha,
                 const double                          dt,
                 const double                          dt_old,
                 const std::vector<double>            &mass)
{
  Vector now (3), old (3), older (3), lumped (3);
  for (unsigned int i = 0; i < 2; ++i)
  {
    now (i)   = alpha (dt) + 0.1 * i;
    old (i)   = alpha (0) + 0.1 * i;
    older (i) = alpha (-dt_old) + 0.1 * i;
  }
  now (2) = 1e-4, old (2) = 5e-4, older (2) = 9e-4; // changes, but holds no solids
  for (unsigned int i = 0; i < 3; ++i)
    lumped (i) = mass[i];
  return alpha_time_error (now, old, older, lumped, dt, dt_old, MPI_COMM_WORLD);
}
} // namespace

int main (int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi (argc, argv, 1);

  // Courant limits: a fast gas in a cell without solids sets the global limit only
  TimeSteppingParameters p = parameters ();
  WaveSpeeds             speeds;
  speeds.gas            = 20; // the peak: in a channel cell without solids
  speeds.solids         = 1;  // the peak over the cells that hold solids
  speeds.granular_sound = 0.5;
  speeds.courant_rate   = 2000; // max over cells: 2 m/s (u_g/4 in a bed cell) / 1 mm
  const TimeStepController controller (p);
  check_close (controller.courant_limit (speeds, 5e-4), 0.5 / 2000, 1e-14, "local limit");
  check_close (controller.next (1e-3, speeds, 5e-4, 0), 2.5e-4, 1e-14, "local step");
  p.local_courant = false;
  check_close (controller.courant_limit (speeds, 5e-4),
               0.5 * 5e-4 / 5.0,
               1e-14,
               "global limit: a quarter of the peak gas speed on the smallest spacing");
  // growth and the cap
  p.local_courant     = true;
  speeds.courant_rate = 1;
  check_close (controller.next (1e-3, speeds, 5e-4, 0), 1.2e-3, 1e-14, "growth factor");
  check_close (controller.next (9e-3, speeds, 5e-4, 0), 1e-2, 1e-14, "maximum step");
  // the time-error limit: 0.9 dt (tol/E)^(1/2), at least dt/2, off with tol = 0
  check_close (controller.next (1e-3, speeds, 5e-4, 4e-3), 1.2e-3, 1e-14, "tol 0: off");
  p.time_error_tolerance = 1e-3;
  check_close (controller.next (1e-3, speeds, 5e-4, 4e-3), 0.5e-3, 1e-14, "E = 4 tol");
  check_close (
      controller.next (1e-3, speeds, 5e-4, 1e-3 * 0.81 / 1.21), 1.1e-3, 1e-12, "E < tol");
  check_close (
      controller.next (1e-3, speeds, 5e-4, 1e-1), 0.5e-3, 1e-14, "at least dt/2");
  check_close (controller.next (1e-3, speeds, 5e-4, 0), 1.2e-3, 1e-14, "no estimate yet");
  p.adaptive = false;
  check_close (controller.next (1e-3, speeds, 5e-4, 1e-1), 1e-3, 1e-14, "not adaptive");

  // towards the end time: the planned step, the rest where it is at most 1% longer (no
  // sliver left: 20 steps of 0.25 ms and an end time 1e-9 s above 5 ms), and a rest
  // shorter than two steps split into two equal ones
  struct EndCase
  {
    double      dt, time, end, expected;
    const char *what;
  };
  const double  end         = 20 * 2.5e-4 + 1e-9;
  const EndCase end_cases[] = {
      {2.5e-4, 0.0, end, 2.5e-4, "far"},
      {2.5e-4, 19 * 2.5e-4, end, 2.5e-4 + 1e-9, "the last step takes the sliver"},
      {2.5e-4, 4.9e-3, 5e-3, 1e-4, "a shorter rest: stop at the end"},
      {1e-3, 0, 1.02e-3, 0.51e-3, "2% longer: two equal steps"},
      {1e-3, 0.51e-3, 1.02e-3, 0.51e-3, "the second of the two equal steps ends the run"},
      {1e-3, 0, 1.999e-3, 0.9995e-3, "a rest just short of 2 dt: two equal steps"},
      {1e-3, 0, 2e-3, 1e-3, "a rest of 2 dt: a full step"}};
  for (const EndCase &c : end_cases)
    check_close (TimeStepController::step_towards_end (c.dt, c.time, c.end),
                 c.expected,
                 1e-14,
                 c.what);

  // the estimate: 0 for alpha linear in time, whatever the steps
  const double dt = 2e-3, dt_old = 1e-3;
  check (estimate ([] (double t) { return 0.3 + 5 * t; }, dt, dt_old, {1, 1, 1}) < 1e-15,
         "linear in time: no error");
  // alpha = 0.3 + c t^2 sampled exactly: alpha^{n+1} - alpha^P = c dt (dt + dt_old) (the
  // predictor's error), scaled by dt/(2 dt + dt_old)
  const double c        = 40;
  const double expected = dt / (2 * dt + dt_old) * c * dt * (dt + dt_old);
  check_close (
      estimate ([&] (double t) { return 0.3 + c * t * t; }, dt, dt_old, {1, 3, 7}),
      expected,
      1e-12,
      "quadratic in time: the scaled predictor difference (mass-weighted RMS over "
      "the nodes holding solids)");
  // no node holding solids: 0
  Vector empty (2), lumped (2);
  lumped = 1;
  check (alpha_time_error (empty, empty, empty, lumped, dt, dt_old, MPI_COMM_WORLD) == 0,
         "no solids: no estimate");
  return wetbed::testing::failure_count () != 0;
}
