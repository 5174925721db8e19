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
  prm.declare_entry ("on signal",
                     "true",
                     Bool (),
                     "On SIGTERM or SIGINT, finish the current time step, write a "
                     "checkpoint and stop (exit status 4). false: the signal's default "
                     "action (the run is killed).");
  prm.declare_entry ("resume",
                     "false",
                     Bool (),
                     "Continue the run saved in <output folder>/checkpoint (also "
                     "`wetbed CASE.prm --resume`): monitors.csv is cut back to the "
                     "checkpoint's step and continued. The mesh file and the physics "
                     "must be those of the saved run; the end time may be later. The "
                     "number of MPI ranks may differ.");
  prm.leave_subsection ();
}

void CheckpointParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("checkpoint");
  interval  = prm.get_integer ("interval");
  at_end    = prm.get_bool ("at end");
  on_signal = prm.get_bool ("on signal");
  resume    = prm.get_bool ("resume");
  prm.leave_subsection ();
}
} // namespace wetbed
