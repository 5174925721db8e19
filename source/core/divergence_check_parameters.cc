#include <wetbed/core/divergence_check_parameters.h>
#include <wetbed/core/input_error.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void DivergenceCheckParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("divergence checks");
  prm.declare_entry ("enabled",
                     "true",
                     Bool (),
                     "Reject a step whose state fails one of the checks below (and stop "
                     "the run, status 3, when halving the step does not help).");
  prm.declare_entry (
      "reference speed",
      "0",
      Double (0),
      "The speed scale of the case (m/s) the speed and energy checks use; 0: the largest "
      "of the interstitial inlet speed U(t)/(1 - maximum packing), the single-particle "
      "terminal velocity (Schiller-Naumann), the free-fall speed over the domain height "
      "sqrt(2 g H) and the moving wall's speed.");
  prm.declare_entry (
      "speed limit factor",
      "20",
      Double (0),
      "A gas speed at a Q2 node, or a solids speed at a vertex where alpha_s > 1e-3, "
      "above this factor times the reference speed fails the step.");
  prm.declare_entry ("fluidization index limit",
                     "50",
                     Double (0),
                     "A fluidization index |FI| (pressure drop times inlet area over the "
                     "buoyant bed weight) above this fails the step. A packed bed at "
                     "start-up can carry several bed weights; a diverging run reaches "
                     "thousands.");
  prm.declare_entry (
      "energy growth factor",
      "100",
      Double (1),
      "The kinetic energy of both phases growing by more than this factor "
      "over the smallest of the last `energy growth window` accepted steps "
      "fails the step, once it exceeds that of the solids moving at the "
      "reference speed divided by this factor.");
  prm.declare_entry ("energy growth window",
                     "10",
                     Integer (1, 1000),
                     "Accepted steps over which the kinetic energy growth is measured.");
  prm.declare_entry ("retries",
                     "3",
                     Integer (0, 50),
                     "Steps failing a check are retried this many times with half the "
                     "step each; then the run stops with status 3.");
  prm.leave_subsection ();
}

void DivergenceCheckParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("divergence checks");
  enabled            = prm.get_bool ("enabled");
  reference_speed    = prm.get_double ("reference speed");
  speed_factor       = prm.get_double ("speed limit factor");
  fluidization_limit = prm.get_double ("fluidization index limit");
  energy_growth      = prm.get_double ("energy growth factor");
  energy_window      = prm.get_integer ("energy growth window");
  retries            = prm.get_integer ("retries");
  prm.leave_subsection ();
  require_positive (speed_factor, "divergence checks/speed limit factor");
  require_positive (fluidization_limit, "divergence checks/fluidization index limit");
}
} // namespace wetbed
