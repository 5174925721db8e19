#include <wetbed/core/stop_signal.h>

#include <deal.II/base/mpi.h>

#include <csignal>

namespace wetbed
{
namespace
{
volatile std::sig_atomic_t stop_signal_received = 0;

extern "C" void record_stop_signal (int)
{
  stop_signal_received = 1;
}
} // namespace

void catch_stop_signals ()
{
  std::signal (SIGTERM, record_stop_signal);
  std::signal (SIGINT, record_stop_signal);
}

bool stop_requested (MPI_Comm communicator)
{
  const unsigned int local = stop_signal_received != 0 ? 1 : 0;
  return dealii::Utilities::MPI::max (local, communicator) != 0;
}
} // namespace wetbed
