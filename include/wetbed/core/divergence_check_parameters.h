#pragma once

#include <deal.II/base/parameter_handler.h>

namespace wetbed
{
/**
 * `subsection divergence checks`: what an accepted step must satisfy besides a
 * converged solve and alpha_s in [0, maximum packing] (doc/user_guide.md, "Failures
 * and exit codes"). A step that fails a check is rejected and retried with half the
 * step; `retries` such rejections in a row, or a step below `time stepping/minimum
 * time step`, stop the run with status 3 and failure_report.txt.
 */
struct DivergenceCheckParameters
{
  bool         enabled;
  double       reference_speed;    // m/s; 0: derived from the case
  double       speed_factor;       // speed limit = factor x the reference speed
  double       fluidization_limit; // |FI| above it fails
  double       energy_growth;      // kinetic energy growth factor over the window
  unsigned int energy_window;      // accepted steps the growth is measured over
  unsigned int retries;            // check rejections in a row before the run stops

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
