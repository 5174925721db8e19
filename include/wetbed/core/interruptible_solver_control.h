#pragma once

#include <wetbed/core/stop_signal.h>

#include <deal.II/lac/solver_control.h>

#include <mpi.h>

namespace wetbed
{
/**
 * A SolverControl that also abandons the time step at the first iteration after a stop
 * signal reached any rank (StepInterrupted): a long Krylov solve does not hold up the
 * checkpoint of a run that mpirun or a batch system is about to kill. One reduction of
 * a flag per iteration; every rank checks at the same iteration, as the residual norm
 * is global.
 */
class InterruptibleSolverControl : public dealii::SolverControl
{
public:
  InterruptibleSolverControl (MPI_Comm           communicator,
                              const unsigned int maximum_steps,
                              const double       tolerance)
      : dealii::SolverControl (maximum_steps, tolerance), communicator (communicator)
  {
  }

  State check (const unsigned int step, const double value) override
  {
    abandon_step_on_stop (communicator);
    return dealii::SolverControl::check (step, value);
  }

private:
  MPI_Comm communicator;
};
} // namespace wetbed
