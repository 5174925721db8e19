#pragma once

#include <deal.II/base/parameter_handler.h>

namespace wetbed
{
/** `subsection adaptive refinement`: bubble-following refinement and coarsening. */
struct AdaptiveRefinementParameters
{
  bool         enabled;
  unsigned int interval;                     // accepted steps between adaptations
  unsigned int minimum_level, maximum_level; // absolute levels of the gmsh mesh
  double       velocity_weight; // weight of the Kelly term of u_s (0: alpha_s only)
  double       refine_threshold, coarsen_threshold; // of the indicator
  unsigned int initial_cycles;    // adapt to the initial state before the first step
  double distributor_band_height; // cells below it are held at maximum_level (0: none)

  static void declare_parameters (dealii::ParameterHandler &prm);
  void parse_parameters (dealii::ParameterHandler &prm, unsigned int initial_refinement);
};
} // namespace wetbed
