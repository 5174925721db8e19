#pragma once

#include <mpi.h>

namespace wetbed
{
/** Makes SIGTERM, SIGINT and SIGUSR2 (stop) and SIGUSR1 (checkpoint) only set a flag
 * that the run reads at the end of its current step, instead of killing the process. */
void catch_stop_signals ();

/** What the signals received since the last call ask for, on any rank. */
enum class SignalRequest
{
  none,
  checkpoint, // SIGUSR1: write a checkpoint and go on
  stop        // SIGTERM, SIGINT, SIGUSR2: write a checkpoint and stop
};

/** The strongest request any rank received (collective: every rank must call it);
 * a checkpoint request is answered by this call (cleared). */
SignalRequest signal_request (MPI_Comm communicator);
} // namespace wetbed
