#include <wetbed/core/input_error.h>
#include <wetbed/core/spectrum_parameters.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void SpectrumParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("spectrum");
  prm.declare_entry ("enabled",
                     "true",
                     Bool (),
                     "At the end of the run, write spectrum.csv: the Welch power "
                     "spectra of the pressure drop and of every alpha_s_plane_* column "
                     "of monitors.csv and their dominant frequencies (also printed). "
                     "Skipped when the run ends before `start time`.");
  prm.declare_entry ("start time",
                     "1",
                     Double (0),
                     "Samples before this time (the start-up) are left out (s).");
  prm.declare_entry ("segments",
                     "4",
                     Integer (1, 1024),
                     "Welch segments (Hann window, 50% overlap): more segments, less "
                     "noise, coarser frequency resolution.");
  prm.leave_subsection ();
}

void SpectrumParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("spectrum");
  enabled    = prm.get_bool ("enabled");
  start_time = prm.get_double ("start time");
  segments   = prm.get_integer ("segments");
  prm.leave_subsection ();
}
} // namespace wetbed
