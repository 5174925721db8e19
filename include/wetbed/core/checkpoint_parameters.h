#pragma once

#include <deal.II/base/parameter_handler.h>

namespace wetbed
{
/** `subsection checkpoint`: when the whole run state is saved and whether a run resumes
 * from the last saved state (`<output folder>/checkpoint`). */
struct CheckpointParameters
{
  unsigned int interval;     // accepted steps between checkpoints (0: none on a schedule)
  bool         at_end;       // also at the end time (a finished run can be extended)
  bool         on_signal;    // SIGTERM/SIGINT/SIGUSR2: abandon the step, save the last
                             // completed one, stop; SIGUSR1: save after the step, go on
  double wall_time_interval; // wall-clock seconds between checkpoints (0: none)
  bool   resume;             // continue from the checkpoint instead of the initial state
  double stall_timeout;      // s without progress before the run ends itself (0: never)

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
