#pragma once

#include <mpi.h>

namespace wetbed
{
/** Makes SIGTERM and SIGINT only set a flag (the run saves a checkpoint and stops at
 * the end of its current step) instead of killing the process. */
void catch_stop_signals ();

/** Whether any rank received SIGTERM/SIGINT (collective: every rank must call it). */
bool stop_requested (MPI_Comm communicator);
} // namespace wetbed
