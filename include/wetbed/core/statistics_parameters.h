#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace wetbed
{
/** A straight line of sample points (`statistics/lines`). */
struct SampleLine
{
  std::string         name;
  std::vector<double> from, to; // the end points (dim coordinates each)
  unsigned int        points;
};

/** `subsection statistics`: time-averaged fields, and the profiles and cross-section
 * maps sampled from them. */
struct StatisticsParameters
{
  bool   time_averages; // accumulate means and variances of the fields
  double start_time;    // from this time on (s): the start-up left out

  std::vector<double>     radial_profile_heights;  // m; 3D: azimuthal averages
  std::vector<double>     lateral_profile_heights; // m; across the first horizontal axis
  std::vector<double>     plane_heights;           // m; maps of the cross-section
  std::vector<SampleLine> lines;
  unsigned int            profile_points;   // along a radial or lateral profile
  unsigned int            averaging_points; // azimuths (radial), depths (lateral, 3D)
  unsigned int            plane_resolution; // points per side of a plane map

  /** Whether any profile, plane or line is sampled. */
  bool samples () const
  {
    return !radial_profile_heights.empty () || !lateral_profile_heights.empty () ||
           !plane_heights.empty () || !lines.empty ();
  }

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm, unsigned int dim);
};
} // namespace wetbed
