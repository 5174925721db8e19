#include <wetbed/core/stall_watchdog.h>
#include <wetbed/core/stop_signal.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <csignal>

namespace wetbed
{
namespace
{
volatile std::sig_atomic_t stop_signal_received = 0;
// SIGUSR1 is counted, not flagged: mpirun forwards one signal to every rank, and the
// ranks may see it in different steps; the largest count over the ranks is the number
// of requests, so a rank that sees the signal a step later does not ask again
volatile std::sig_atomic_t checkpoint_signals_received = 0;
unsigned int               checkpoint_signals_answered = 0;
bool                       signals_caught              = false;

extern "C" void record_stop_signal (int)
{
  stop_signal_received = 1;
}

extern "C" void record_checkpoint_signal (int)
{
  checkpoint_signals_received = checkpoint_signals_received + 1;
}
} // namespace

void catch_stop_signals ()
{
  signals_caught = true;
  std::signal (SIGTERM, record_stop_signal);
  std::signal (SIGINT, record_stop_signal);
  std::signal (SIGUSR2, record_stop_signal);
  std::signal (SIGUSR1, record_checkpoint_signal);
}

SignalRequest signal_request (MPI_Comm communicator)
{
  const unsigned int local[2] = {stop_signal_received != 0 ? 1u : 0u,
                                 static_cast<unsigned int> (checkpoint_signals_received)};
  unsigned int any[2];
  dealii::Utilities::MPI::max (dealii::ArrayView<const unsigned int> (local, 2),
                               communicator,
                               dealii::ArrayView<unsigned int> (any, 2));
  const bool checkpoint       = any[1] > checkpoint_signals_answered;
  checkpoint_signals_answered = std::max (checkpoint_signals_answered, any[1]);
  return any[0] != 0  ? SignalRequest::stop
         : checkpoint ? SignalRequest::checkpoint
                      : SignalRequest::none;
}

bool stop_requested (MPI_Comm communicator)
{
  // called at every Krylov iteration: the run's heartbeat for the stall watchdog
  // (after the collective, which a stopped rank would not let finish)
  if (!signals_caught)
  {
    StallWatchdog::report_progress ();
    return false;
  }
  const unsigned int local = stop_signal_received != 0 ? 1 : 0;
  const bool         stop  = dealii::Utilities::MPI::max (local, communicator) != 0;
  StallWatchdog::report_progress ();
  return stop;
}

void abandon_step_on_stop (MPI_Comm communicator)
{
  if (stop_requested (communicator))
    throw StepInterrupted ();
}
} // namespace wetbed
