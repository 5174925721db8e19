#include <wetbed/postprocess/pressure_drop.h>
#include <wetbed/postprocess/pressure_probe.h>

namespace wetbed
{
template <int dim>
PressureProbe<dim>::PressureProbe (const double height) : sampler ({height}, 16)
{
}

template <int dim>
void PressureProbe<dim>::fill (const SolverState<dim> &s, MonitorRow &row)
{
  const PressureDrop drop = evaluate_pressure_drop (s, row.solids_mass);
  const double       probe_drop =
      CrossSectionSampler<dim>::mean (sampler.pressure (s)) - drop.outlet_pressure;
  const auto  &pp = s.parameters.physical;
  const double weight =
      row.solids_mass * (1 - pp.gas_density / pp.particle_density) * pp.gravity.norm ();
  row.pressure_probe = {probe_drop,
                        weight > 0 ? probe_drop * drop.inlet_area / weight : 0};
}

template class PressureProbe<2>;
template class PressureProbe<3>;
} // namespace wetbed
