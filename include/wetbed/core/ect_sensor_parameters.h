#pragma once

#include <deal.II/base/parameter_handler.h>

namespace wetbed
{
/** `subsection ECT sensor`: the cross-section solids fraction of a horizontal slab,
 * sampled at a fixed frame rate as an electrical capacitance tomograph records it. */
struct EctSensorParameters
{
  bool         enabled;
  double       centre_height; // m along -gravity from the origin
  double       thickness;     // m
  double       frame_rate;    // frames per second
  unsigned int resolution;    // pixels per side of the image
  unsigned int levels;        // sampled heights across the thickness

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
