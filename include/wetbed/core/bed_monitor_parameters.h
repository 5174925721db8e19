#pragma once

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <vector>

namespace wetbed
{
/** `subsection bed monitors`: optional columns of monitors.csv. */
struct BedMonitorParameters
{
  std::vector<double> pressure_drop_planes;    // two heights, or none
  double              surface_solids_fraction; // of the bed surface definition
  std::vector<std::array<double, 3>> point_probes;
  double pressure_probe_height = -1; // m along -gravity from the origin; < 0: none

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm, unsigned int dim);
};
} // namespace wetbed
