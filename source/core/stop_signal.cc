#include <wetbed/core/stop_signal.h>

#include <deal.II/base/mpi.h>

#include <csignal>

namespace wetbed
{
namespace
{
volatile std::sig_atomic_t stop_signal_received       = 0;
volatile std::sig_atomic_t checkpoint_signal_received = 0;
bool                       signals_caught             = false;

extern "C" void record_stop_signal (int)
{
  stop_signal_received = 1;
}

extern "C" void record_checkpoint_signal (int)
{
  checkpoint_signal_received = 1;
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
  const unsigned int local   = stop_signal_received != 0         ? 2
                               : checkpoint_signal_received != 0 ? 1
                                                                 : 0;
  checkpoint_signal_received = 0;
  const unsigned int any     = dealii::Utilities::MPI::max (local, communicator);
  return any == 2   ? SignalRequest::stop
         : any == 1 ? SignalRequest::checkpoint
                    : SignalRequest::none;
}

bool stop_requested (MPI_Comm communicator)
{
  if (!signals_caught)
    return false;
  const unsigned int local = stop_signal_received != 0 ? 1 : 0;
  return dealii::Utilities::MPI::max (local, communicator) != 0;
}

void abandon_step_on_stop (MPI_Comm communicator)
{
  if (stop_requested (communicator))
    throw StepInterrupted ();
}
} // namespace wetbed
