#include <wetbed/core/stall_watchdog.h>

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace wetbed
{
namespace
{
using Clock = std::chrono::steady_clock;

std::atomic<Clock::rep> last_progress{0};

Clock::rep now ()
{
  return Clock::now ().time_since_epoch ().count ();
}
} // namespace

StallWatchdog::StallWatchdog (const double timeout, const std::string &folder)
    : timeout (timeout), folder (folder)
{
  report_progress ();
  if (timeout > 0)
    thread = std::thread ([this] () { watch (); });
}

StallWatchdog::~StallWatchdog ()
{
  {
    std::lock_guard<std::mutex> lock (mutex);
    finished = true;
  }
  wake.notify_all ();
  if (thread.joinable ())
    thread.join ();
}

void StallWatchdog::report_progress ()
{
  last_progress.store (now (), std::memory_order_relaxed);
}

void StallWatchdog::watch ()
{
  const auto                   limit = std::chrono::duration<double> (timeout);
  std::unique_lock<std::mutex> lock (mutex);
  while (!finished)
  {
    // look a few times per timeout (at least once a second)
    wake.wait_for (lock, std::min (limit / 8, std::chrono::duration<double> (1.0)));
    if (finished)
      return;
    const Clock::duration idle (now () - last_progress.load (std::memory_order_relaxed));
    if (idle > limit)
    {
      int rank = 0, initialized = 0;
      MPI_Initialized (&initialized);
      if (initialized)
        MPI_Comm_rank (MPI_COMM_WORLD, &rank);
      std::fprintf (stderr,
                    "wetbed: error: checkpoint/stall timeout: no progress on rank %d "
                    "for %.0f s (another rank stopped, hangs or was lost?): ending the "
                    "run with status %d; the last checkpoint in %s/checkpoint is kept\n",
                    rank,
                    std::chrono::duration<double> (idle).count (),
                    exit_status,
                    folder.c_str ());
      std::fflush (stderr);
      std::_Exit (exit_status);
    }
  }
}
} // namespace wetbed
