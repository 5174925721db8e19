#include <wetbed/core/checkpoint_parameters.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void CheckpointParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("checkpoint");
  prm.declare_entry ("interval",
                     "0",
                     Integer (0),
                     "Accepted time steps between checkpoints (mesh, every field and its "
                     "BDF history, the time-stepping state and the monitors position, "
                     "in <output folder>/checkpoint; the previous one is replaced only "
                     "once the new one is complete). 0: none on a schedule.");
  prm.declare_entry ("at end",
                     "true",
                     Bool (),
                     "Write a checkpoint when the run reaches the end time, so that it "
                     "can be continued with a later end time and `resume = true`.");
  prm.declare_entry ("wall time interval",
                     "900",
                     Double (0),
                     "Wall-clock seconds between checkpoints (after the step that "
                     "passes each multiple), so that even a hard kill loses at most "
                     "this much work. 0: none on the clock.");
  prm.declare_entry ("on signal",
                     "true",
                     Bool (),
                     "On SIGTERM, SIGINT or SIGUSR2, abandon the time step under way, "
                     "write a checkpoint of the last completed step and stop (exit "
                     "status 4); on SIGUSR1 write a checkpoint after the current step "
                     "and go on (Slurm's `--signal`). mpirun forwards SIGUSR1/SIGUSR2 "
                     "to the ranks as they are and turns a SIGINT/SIGTERM into SIGTERM "
                     "to the ranks, which then write the checkpoint within mpirun's "
                     "grace period. false: the signals' default action.");
  prm.declare_entry ("resume",
                     "false",
                     Bool (),
                     "Continue the run saved in <output folder>/checkpoint (also "
                     "`wetbed CASE.prm --resume`): monitors.csv is cut back to the "
                     "checkpoint's step and continued. The mesh file and the physics "
                     "must be those of the saved run; the end time may be later. The "
                     "number of MPI ranks may differ.");
  prm.declare_entry (
      "stall timeout",
      "1800",
      Double (0),
      "Seconds without progress (a Krylov iteration or a step completed) after which "
      "each rank ends the run with exit status 5 and one line: a rank stopped "
      "(SIGSTOP), hanging or lost with its node would otherwise keep the others "
      "waiting in a collective for ever. Longer than the slowest step's set-up, "
      "adaptation or checkpoint write. The last checkpoint stays. 0: never.");
  prm.leave_subsection ();
}

void CheckpointParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("checkpoint");
  interval           = prm.get_integer ("interval");
  at_end             = prm.get_bool ("at end");
  on_signal          = prm.get_bool ("on signal");
  wall_time_interval = prm.get_double ("wall time interval");
  resume             = prm.get_bool ("resume");
  stall_timeout      = prm.get_double ("stall timeout");
  prm.leave_subsection ();
}
} // namespace wetbed
