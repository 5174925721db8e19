#include <wetbed/core/input_error.h>
#include <wetbed/core/statistics_parameters.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void StatisticsParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("statistics");
  prm.declare_entry (
      "time averages",
      "false",
      Bool (),
      "From `start time` on, accumulate the time averages of alpha_s, u_g, u_s, p' and "
      "Theta and the variances of alpha_s, p' and of each velocity component "
      "(weighted by the step lengths, updated after every accepted step). They are "
      "written with the fields (alpha_s_mean, gas_velocity_mean, solids_velocity_mean, "
      "pressure_mean, granular_temperature_mean, alpha_s_variance, "
      "gas_velocity_variance, solids_velocity_variance, pressure_variance), kept in "
      "checkpoints and carried through mesh adaptation.");
  prm.declare_entry ("start time",
                     "1",
                     Double (0),
                     "The averages start here (s): leave the start-up out.");
  prm.leave_subsection ();
}

void StatisticsParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("statistics");
  time_averages = prm.get_bool ("time averages");
  start_time    = prm.get_double ("start time");
  prm.leave_subsection ();
}
} // namespace wetbed
