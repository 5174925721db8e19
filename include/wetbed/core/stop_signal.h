#pragma once

#include <mpi.h>

#include <exception>

namespace wetbed
{
/** Makes SIGTERM, SIGINT and SIGUSR2 (stop) and SIGUSR1 (checkpoint) only set a flag
 * instead of killing the process: a stop abandons the step under way at its next outer
 * or Krylov iteration, a checkpoint request is served after the current step. */
void catch_stop_signals ();

/** What the signals received since the last call ask for, on any rank. */
enum class SignalRequest
{
  none,
  checkpoint, // SIGUSR1: write a checkpoint and go on
  stop        // SIGTERM, SIGINT, SIGUSR2: write a checkpoint and stop
};

/** The strongest request any rank received (collective: every rank must call it).
 * A checkpoint request is answered by this call: SIGUSR1 signals are counted on each
 * rank, and a checkpoint is asked for when the largest count over the ranks exceeds
 * the number already answered (one signal that mpirun forwards to every rank, seen by
 * the ranks in different steps, is one request). */
SignalRequest signal_request (MPI_Comm communicator);

/** Whether any rank received a stop signal (collective; false on every rank without a
 * call to catch_stop_signals()). The request stays for signal_request(). */
bool stop_requested (MPI_Comm communicator);

/** Thrown at a check point inside a time step (each outer iteration, each Krylov
 * iteration) once a stop signal reached any rank: the step is abandoned, and the run
 * checkpoints its last accepted step at once. mpirun (Open MPI) kills its ranks about
 * a second after it forwards SIGTERM, too soon to finish a step. */
class StepInterrupted : public std::exception
{
public:
  const char *what () const noexcept override
  {
    return "the time step was abandoned on a stop signal";
  }
};

/** Throws StepInterrupted when stop_requested() (collective). */
void abandon_step_on_stop (MPI_Comm communicator);
} // namespace wetbed
