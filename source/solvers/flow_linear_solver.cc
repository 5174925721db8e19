#include <wetbed/core/interruptible_solver_control.h>
#include <wetbed/solvers/flow_linear_solver.h>

#include <deal.II/lac/solver_gmres.h>

#include <cmath>

namespace wetbed
{
using namespace dealii;

namespace
{
/** Caps a solve at `cap_rate` iterations per decade of the reduction it must achieve
 * (known at its first check: the initial residual) plus 10; cap_rate 0: no cap. */
class RateCappedControl : public InterruptibleSolverControl
{
public:
  RateCappedControl (MPI_Comm           communicator,
                     const unsigned int maximum_steps,
                     const double       tolerance,
                     const double       cap_rate)
      : InterruptibleSolverControl (communicator, maximum_steps, tolerance),
        cap_rate (cap_rate)
  {
  }

  State check (const unsigned int step, const double value) override
  {
    if (step == 0 && cap_rate > 0 && value > tolerance ())
    {
      const double decades = std::log10 (value / tolerance ());
      set_max_steps (std::min<unsigned int> (
          max_steps (), static_cast<unsigned int> (std::ceil (cap_rate * decades)) + 10));
    }
    return InterruptibleSolverControl::check (step, value);
  }

private:
  double cap_rate;
};

/** Iterations per decade of residual reduction of a finished solve (0 if it made none).
 */
double iterations_per_decade (const SolverControl &control)
{
  const auto &residuals = control.get_history_data ();
  if (control.last_step () == 0 || residuals.empty () || residuals.front () <= 0 ||
      control.last_value () <= 0)
    return 0.0;
  const double decades = std::log10 (residuals.front () / control.last_value ());
  return control.last_step () / std::max (decades, 0.1);
}
} // namespace

FlowLinearSolver::FlowLinearSolver (const LinearSolverParameters &parameters,
                                    ConditionalOStream           &pcout,
                                    TimerOutput                  &timer)
    : parameters (parameters), pcout (pcout), timer (timer)
{
}

bool FlowLinearSolver::rebuild_due (const double dt) const
{
  return solves_since_build >= parameters.rebuild_interval ||
         std::abs (dt / dt_at_build - 1.0) > 0.2;
}

unsigned int
FlowLinearSolver::solve (const FlowOperator           &op,
                         FlowPreconditioner           &preconditioner,
                         const BlockVector            &rhs,
                         BlockVector                  &solution,
                         const double                  relative_target,
                         const double                  dt,
                         SolveHistory                 &history,
                         const std::function<void ()> &before_unforeseen_rebuild)
{
  const auto &ls               = parameters;
  auto        rebuild_velocity = [&] ()
  {
    preconditioner.update (true);
    solves_since_build = 0;
    rate_after_build   = 0;
    dt_at_build        = dt;
  };
  {
    TimerOutput::Scope scope (timer, "preconditioner setup");
    if (rebuild_due (dt))
      rebuild_velocity ();
    else
      preconditioner.update (false);
  }

  const double      target        = relative_target * rhs.l2_norm ();
  const BlockVector initial_guess = solution;
  unsigned int      spent         = 0;
  for (unsigned int attempt = 0; attempt < 2; ++attempt)
  {
    const bool         reused = solves_since_build > 0;
    TimerOutput::Scope scope (timer, "Krylov solve");
    solution = initial_guess;
    RateCappedControl control (rhs.block (0).get_mpi_communicator (),
                               ls.maximum_iterations,
                               std::max (target, 1e-300),
                               reused ? 3 * rate_after_build : 0.0); // 0: no cap
    control.enable_history_data ();
    SolverFGMRES<BlockVector> fgmres (
        control, typename SolverFGMRES<BlockVector>::AdditionalData (ls.restart));
    try
    {
      fgmres.solve (op, solution, rhs, preconditioner);
    }
    catch (const SolverControl::NoConvergence &)
    {
      history.record (
          reused ? "flow FGMRES (reused AMG)" : "flow FGMRES", control, false);
      spent += control.last_step ();
      if (reused)
      {
        if (before_unforeseen_rebuild)
          before_unforeseen_rebuild ();
        TimerOutput::Scope setup (timer, "preconditioner setup");
        rebuild_velocity ();
        continue;
      }
      solves_since_build = ls.rebuild_interval;
      pcout << "  FGMRES did not converge in " << control.last_step ()
            << " iterations (residual " << control.last_value () << ", target " << target
            << ")" << std::endl;
      return numbers::invalid_unsigned_int;
    }
    const unsigned int iterations = control.last_step ();
    history.record (reused ? "flow FGMRES (reused AMG)" : "flow FGMRES", control, true);
    if (ls.verbose)
    {
      const auto  &residuals = control.get_history_data ();
      const double first     = residuals.empty () ? 0.0 : residuals.front ();
      pcout << "    FGMRES " << iterations << " iterations"
            << (reused ? " (reused AMG)" : "") << ", residual " << first << " -> "
            << control.last_value () << " (target " << target << ", mean reduction "
            << (first > 0 && iterations > 0
                    ? std::pow (control.last_value () / first, 1.0 / iterations)
                    : 0.0)
            << ")" << std::endl;
      BlockVector true_residual (rhs);
      op.vmult (true_residual, solution);
      true_residual.sadd (-1.0, 1.0, rhs);
      pcout << "      true residual " << true_residual.l2_norm () << std::endl;
      const std::string inner = preconditioner.report ();
      if (!inner.empty ())
        pcout << "      " << inner << std::endl;
    }
    ++solves_since_build;
    const double rate = iterations_per_decade (control);
    if (rate_after_build == 0) // the first solve after the build (that iterated)
      rate_after_build = rate;
    else if (rate > ls.rebuild_growth * rate_after_build)
      solves_since_build = ls.rebuild_interval;
    return iterations + spent;
  }
  return numbers::invalid_unsigned_int;
}
} // namespace wetbed
