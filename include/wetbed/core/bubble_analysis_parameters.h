#pragma once

#include <deal.II/base/parameter_handler.h>

namespace wetbed
{
/** `subsection bubble analysis`: detection and tracking of bubbles during the run. */
struct BubbleAnalysisParameters
{
  bool         enabled;
  unsigned int interval;               // accepted steps between analyses
  double       gas_fraction_threshold; // cells with mean alpha_g above it are gas
  double       minimum_diameter;       // smaller gas regions are not bubbles (m)

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
