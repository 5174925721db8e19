#include <wetbed/core/ect_sensor_parameters.h>
#include <wetbed/core/input_error.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void EctSensorParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("ECT sensor");
  prm.declare_entry ("enabled",
                     "false",
                     Bool (),
                     "Record the solids fraction of a horizontal slab as an electrical "
                     "capacitance tomograph does: ect.csv holds its cross-section mean "
                     "alpha_s_slab at each frame, ect_images.csv the image (resolution x "
                     "resolution pixels over the domain's horizontal bounding box, "
                     "each pixel alpha_s averaged across the slab; nan outside the "
                     "domain). Frames fall at multiples of 1/frame rate, interpolated "
                     "linearly in time between the steps around them, independent of "
                     "the time step. The spectrum of alpha_s_slab goes to "
                     "ect_spectrum.csv (subsection spectrum).");
  prm.declare_entry ("centre height",
                     "0.076",
                     Double (0),
                     "Height of the slab's centre along -gravity from the origin (m).");
  prm.declare_entry (
      "thickness",
      "0.038",
      Double (0),
      "Thickness of the slab (m): the height over which a frame averages.");
  prm.declare_entry ("frame rate", "100", Double (0), "Frames per second (Hz).");
  prm.declare_entry (
      "resolution", "32", Integer (1, 256), "Pixels per side of a frame's image.");
  prm.declare_entry ("levels",
                     "8",
                     Integer (1, 64),
                     "Heights sampled across the slab (at the centres of equal parts of "
                     "its thickness).");
  prm.leave_subsection ();
}

void EctSensorParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("ECT sensor");
  enabled       = prm.get_bool ("enabled");
  centre_height = prm.get_double ("centre height");
  thickness     = prm.get_double ("thickness");
  frame_rate    = prm.get_double ("frame rate");
  resolution    = prm.get_integer ("resolution");
  levels        = prm.get_integer ("levels");
  prm.leave_subsection ();
  if (!enabled)
    return;
  require_positive (thickness, "ECT sensor/thickness");
  require_positive (frame_rate, "ECT sensor/frame rate");
  require (centre_height >= thickness / 2,
           "ECT sensor/centre height",
           "puts the slab below the origin (centre height " +
               std::to_string (centre_height) + " m < half the thickness " +
               std::to_string (thickness / 2) + " m)");
}
} // namespace wetbed
