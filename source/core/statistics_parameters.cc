#include <wetbed/core/input_error.h>
#include <wetbed/core/statistics_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

namespace
{
std::vector<double> heights (ParameterHandler &prm, const std::string &name)
{
  std::vector<double> values;
  for (const auto &item : dealii::Utilities::split_string_list (prm.get (name)))
    values.push_back (parse_number (item, "statistics/" + name));
  return values;
}

/** `name: x y [z], x y [z], count`: a line of `count` points. */
SampleLine parse_line (const std::string &text, const unsigned int dim)
{
  const std::string where = "statistics/lines";
  const auto        colon = text.find (':');
  require (colon != std::string::npos,
           where,
           "'" + text + "' is not 'name: x y z, x y z, count'");
  SampleLine line;
  line.name = dealii::Utilities::trim (text.substr (0, colon));
  require (!line.name.empty () && std::all_of (line.name.begin (),
                                               line.name.end (),
                                               [] (const char c) {
                                                 return std::isalnum (c) || c == '_' ||
                                                        c == '-' || c == '.';
                                               }),
           where,
           "'" + line.name + "' is not a name (letters, digits, _, - and .)");
  const auto parts = dealii::Utilities::split_string_list (text.substr (colon + 1), ',');
  require (parts.size () == 3,
           where,
           "line '" + line.name + "' needs two points and a count ('" + text + "')");
  for (unsigned int end = 0; end < 2; ++end)
  {
    std::vector<double> &point = end == 0 ? line.from : line.to;
    std::istringstream   coordinates (parts[end]);
    for (std::string coordinate; coordinates >> coordinate;)
      point.push_back (parse_number (coordinate, where));
    require (point.size () == dim,
             where,
             "'" + parts[end] + "' of line '" + line.name + "' is not a point with " +
                 std::to_string (dim) + " coordinates");
  }
  const double count = parse_number (parts[2], where);
  require (count >= 2 && count <= 1e6 && count == std::floor (count),
           where,
           "the count of line '" + line.name + "' must be a whole number from 2 to 1e6");
  line.points = static_cast<unsigned int> (count);
  require (line.from != line.to,
           where,
           "the end points of line '" + line.name + "' are the same");
  return line;
}
} // namespace

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
  prm.declare_entry (
      "radial profile heights",
      "",
      Anything (),
      "3D: heights (m, along -g from the origin) of radial profiles across the column: "
      "at `profile points` radii from the axis of the domain's bounding box to the "
      "column's radius (the largest horizontal distance of a mesh vertex from the "
      "axis), each averaged over `averaging points` azimuths. "
      "Velocities in radial, azimuthal and axial components. Written to "
      "statistics/radial_at_H.csv. Empty: none.");
  prm.declare_entry (
      "lateral profile heights",
      "",
      Anything (),
      "Heights (m) of lateral profiles: `profile points` across the first horizontal "
      "axis of the domain's bounding box (in 3D each the mean over `averaging points` "
      "depths), the profile of a slab or quasi-2D bed. Written to "
      "statistics/lateral_at_H.csv. Empty: none.");
  prm.declare_entry ("plane heights",
                     "",
                     Anything (),
                     "Heights (m) of cross-section maps: `plane resolution` points per "
                     "side of the domain's horizontal bounding box (NaN outside the "
                     "domain). Written to statistics/plane_at_H.csv. Empty: none.");
  prm.declare_entry (
      "lines",
      "",
      Anything (),
      "Lines of sample points, separated by ';': `name: x y z, x y z, count` (two end "
      "points, dim coordinates each, and the number of points from one to the other). "
      "Written to statistics/line_NAME.csv. Empty: none.");
  prm.declare_entry ("profile points",
                     "20",
                     Integer (2, 100000),
                     "Points along each radial or lateral profile (at the centres of "
                     "equal bins).");
  prm.declare_entry ("averaging points",
                     "16",
                     Integer (1, 100000),
                     "Azimuths averaged over at each radius of a radial profile; "
                     "depths averaged over at each point of a lateral profile in 3D.");
  prm.declare_entry (
      "plane resolution", "32", Integer (1, 4096), "Points per side of each plane map.");
  prm.leave_subsection ();
}

void StatisticsParameters::parse_parameters (ParameterHandler  &prm,
                                             const unsigned int dim)
{
  prm.enter_subsection ("statistics");
  time_averages           = prm.get_bool ("time averages");
  start_time              = prm.get_double ("start time");
  radial_profile_heights  = heights (prm, "radial profile heights");
  lateral_profile_heights = heights (prm, "lateral profile heights");
  plane_heights           = heights (prm, "plane heights");
  profile_points          = prm.get_integer ("profile points");
  averaging_points        = prm.get_integer ("averaging points");
  plane_resolution        = prm.get_integer ("plane resolution");
  lines.clear ();
  for (const auto &item : dealii::Utilities::split_string_list (prm.get ("lines"), ';'))
  {
    lines.push_back (parse_line (item, dim));
    for (std::size_t k = 0; k + 1 < lines.size (); ++k)
      require (lines[k].name != lines.back ().name,
               "statistics/lines",
               "the name '" + lines.back ().name + "' is given twice");
  }
  prm.leave_subsection ();
  require (radial_profile_heights.empty () || dim == 3,
           "statistics/radial profile heights",
           "needs a 3D case (use `lateral profile heights` in 2D)");
  // a height given twice would write one file twice
  for (const std::vector<double> *list :
       {&radial_profile_heights, &lateral_profile_heights, &plane_heights})
  {
    std::vector<double> sorted = *list;
    std::sort (sorted.begin (), sorted.end ());
    require (std::adjacent_find (sorted.begin (), sorted.end ()) == sorted.end (),
             list == &plane_heights            ? "statistics/plane heights"
             : list == &radial_profile_heights ? "statistics/radial profile heights"
                                               : "statistics/lateral profile heights",
             "a height is given twice");
  }
}
} // namespace wetbed
