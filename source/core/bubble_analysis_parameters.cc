#include <wetbed/core/bubble_analysis_parameters.h>
#include <wetbed/core/input_error.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void BubbleAnalysisParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("bubble analysis");
  prm.declare_entry ("enabled",
                     "true",
                     Bool (),
                     "Detect bubbles (connected gas regions, the freeboard excluded) "
                     "every `interval` steps, follow them from one analysis to the "
                     "next, count splitting and coalescence events; writes "
                     "bubbles.csv, bubble_events.csv and bubble_summary.csv.");
  prm.declare_entry ("interval",
                     "10",
                     Integer (1),
                     "Accepted steps between analyses. Tracking matches bubbles by "
                     "overlap: a bubble should rise less than its own size between "
                     "two analyses.");
  prm.declare_entry ("gas fraction threshold",
                     "0.8",
                     Double (0, 1),
                     "A cell is gas where its mean gas fraction alpha_g exceeds this.");
  prm.declare_entry ("minimum diameter",
                     "0",
                     Double (0),
                     "Gas regions of smaller equivalent diameter (m; circle in 2D, "
                     "sphere in 3D) are not reported (0: every region).");
  prm.leave_subsection ();
}

void BubbleAnalysisParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("bubble analysis");
  enabled                = prm.get_bool ("enabled");
  interval               = prm.get_integer ("interval");
  gas_fraction_threshold = prm.get_double ("gas fraction threshold");
  minimum_diameter       = prm.get_double ("minimum diameter");
  prm.leave_subsection ();
  require (gas_fraction_threshold > 0 && gas_fraction_threshold < 1,
           "bubble analysis/gas fraction threshold",
           "must lie in (0, 1)");
}
} // namespace wetbed
