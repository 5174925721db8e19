#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace wetbed
{
/**
 * Ends a run that stopped making progress (`checkpoint/stall timeout`): a rank that was
 * stopped (SIGSTOP), hangs or lost its node leaves the others waiting in a collective
 * for ever. While it lives, a thread on each rank checks that report_progress() was
 * called within the timeout (the run calls it at every Krylov iteration and after every
 * step); if not, it prints one line and ends its process with status 5, whereupon
 * mpirun ends the job. The checkpoint of the last completed one stays
 * (source/core/stall_watchdog.cc).
 */
class StallWatchdog
{
public:
  /** `timeout` in seconds; 0: no watchdog. `folder`: named in the message. */
  StallWatchdog (double timeout, const std::string &folder);
  ~StallWatchdog ();
  StallWatchdog (const StallWatchdog &)            = delete;
  StallWatchdog &operator= (const StallWatchdog &) = delete;

  /** The run made progress (cheap: one atomic store). */
  static void report_progress ();

  /** Exit status of a run the watchdog ended. */
  static constexpr int exit_status = 5;

private:
  void watch ();

  double                  timeout;
  std::string             folder;
  std::thread             thread;
  std::mutex              mutex;
  std::condition_variable wake;
  bool                    finished = false;
};
} // namespace wetbed
