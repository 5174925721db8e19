#include <wetbed/core/bed_monitor_parameters.h>
#include <wetbed/core/input_error.h>

#include <cmath>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void BedMonitorParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("bed monitors");
  prm.declare_entry ("pressure drop between",
                     "",
                     List (Double (0), 0, 2),
                     "Two heights along -gravity from the origin (m): monitors.csv gains "
                     "pressure_drop_<a>_<b>, the cross-section average of p' over the "
                     "cell layer at a minus that at b (a pressure-probe pair as in an "
                     "experiment). Empty: none.");
  prm.declare_entry ("surface solids fraction",
                     "0.1",
                     Double (0, 1),
                     "bed_surface_height: the top of the highest of 200 horizontal "
                     "slices whose mean alpha_s exceeds this; expansion_ratio: it "
                     "divided by initial conditions/bed height.");
  prm.declare_entry ("point probes",
                     "",
                     Anything (),
                     "Points 'x, y[, z]; x, y[, z]; ...' (m): monitors.csv gains "
                     "probe_<i>_alpha_s and probe_<i>_pressure (p') there. Empty: none.");
  prm.declare_entry (
      "pressure probe height",
      "",
      List (Double (0), 0, 1),
      "A pressure probe at this height along -gravity from the origin (m), as the "
      "wall probe of an experiment: monitors.csv gains "
      "probe_pressure_drop, the cross-section mean of p' at that height "
      "(16 x 16 points) minus the outlet's, and "
      "probe_fluidization_index, FI = probe_pressure_drop A / (buoyant "
      "bed weight). A dry bubbling bed reads FI = 1 minus the share of "
      "the bed below the probe. Empty: none.");
  prm.leave_subsection ();
}

void BedMonitorParameters::parse_parameters (ParameterHandler  &prm,
                                             const unsigned int dim)
{
  prm.enter_subsection ("bed monitors");
  pressure_drop_planes.clear ();
  for (const auto &item :
       dealii::Utilities::split_string_list (prm.get ("pressure drop between")))
    pressure_drop_planes.push_back (dealii::Utilities::string_to_double (item));
  surface_solids_fraction        = prm.get_double ("surface solids fraction");
  const std::string probes       = prm.get ("point probes");
  const std::string probe_height = prm.get ("pressure probe height");
  pressure_probe_height =
      probe_height.empty () ? -1 : dealii::Utilities::string_to_double (probe_height);
  prm.leave_subsection ();
  require (pressure_drop_planes.size () != 1,
           "bed monitors/pressure drop between",
           "needs two heights (or none)");
  point_probes.clear ();
  for (const auto &point : dealii::Utilities::split_string_list (probes, ';'))
  {
    const auto coordinates = dealii::Utilities::split_string_list (point, ',');
    require (coordinates.size () == dim,
             "bed monitors/point probes",
             "'" + point + "' is not a point with " + std::to_string (dim) +
                 " coordinates");
    std::array<double, 3> p{{0, 0, 0}};
    for (unsigned int d = 0; d < dim; ++d)
    {
      try
      {
        std::size_t used = 0;
        p[d]             = std::stod (coordinates[d], &used);
        require (used == coordinates[d].size (),
                 "bed monitors/point probes",
                 "'" + coordinates[d] + "' is not a number");
        require (std::isfinite (p[d]),
                 "bed monitors/point probes",
                 "'" + coordinates[d] + "' is not a finite number");
      }
      catch (const std::logic_error &)
      {
        throw InputError ("bed monitors/point probes",
                          "'" + coordinates[d] + "' is not a number");
      }
    }
    point_probes.push_back (p);
  }
}
} // namespace wetbed
