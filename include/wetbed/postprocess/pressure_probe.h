#pragma once

#include <wetbed/postprocess/cross_section_sampler.h>
#include <wetbed/postprocess/monitors.h>
#include <wetbed/solvers/solver_state.h>

namespace wetbed
{
/**
 * The pressure probe of `bed monitors/pressure probe height`: the pressure drop from a
 * height above the inlet to the outlet, as a wall probe of an experiment measures it
 * (the bed above the probe), and the fluidization index from it
 * (source/postprocess/pressure_probe.cc).
 */
template <int dim>
class PressureProbe
{
public:
  explicit PressureProbe (double height);

  /** row.pressure_probe = {the cross-section mean of p' at the height (16 x 16 points)
   * minus the mean over the outlet, that times the inlet area over the buoyant weight
   * of row.solids_mass}; collective. */
  void fill (const SolverState<dim> &state, MonitorRow &row);

private:
  CrossSectionSampler<dim> sampler;
};
} // namespace wetbed
