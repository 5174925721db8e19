#include <wetbed/closures/drag/terminal_velocity.h>
#include <wetbed/postprocess/pressure_drop.h>
#include <wetbed/solvers/component_table.h>
#include <wetbed/solvers/divergence_checks.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wetbed
{
using namespace dealii;

namespace
{
/** A cell where a speed exceeds its limit: the speed, the field, the cell centre. */
struct Excess
{
  double      speed;
  std::string field;
  double      x, y, z;

  template <class Archive>
  void serialize (Archive &archive, const unsigned int)
  {
    archive &speed &field &x &y &z;
  }
};

constexpr unsigned int cells_reported = 5;

std::string describe (const std::vector<Excess> &worst,
                      const unsigned long long   count,
                      const double               limit)
{
  std::ostringstream where;
  where << "  " << count << " cell(s) faster than " << limit << " m/s; the fastest:\n";
  for (const Excess &e : worst)
    where << "    " << e.field << " = " << e.speed << " m/s in the cell at (" << e.x
          << ", " << e.y << ", " << e.z << ") m\n";
  return where.str ();
}
} // namespace

template <int dim>
DivergenceChecks<dim>::DivergenceChecks (const Parameters &parameters)
    : parameters (parameters)
{
}

template <int dim>
double DivergenceChecks<dim>::reference_speed (const SolverState<dim> &s) const
{
  if (parameters.divergence_checks.reference_speed > 0)
    return parameters.divergence_checks.reference_speed;
  const auto          &pp = parameters.physical;
  const Tensor<1, dim> up = upward_direction<dim> (pp.gravity);
  double               lo = std::numeric_limits<double>::max (), hi = -lo;
  for (const auto &cell : s.triangulation.active_cell_iterators ())
    if (cell->is_locally_owned ())
      for (const unsigned int v : cell->vertex_indices ())
      {
        lo = std::min (lo, cell->vertex (v) * up);
        hi = std::max (hi, cell->vertex (v) * up);
      }
  const double height = Utilities::MPI::max (hi, s.communicator) +
                        Utilities::MPI::max (-lo, s.communicator);
  const double g        = pp.gravity.norm ();
  const double terminal = closures::terminal_velocity (
      pp.particle_density, pp.particle_diameter, pp.gas_density, pp.gas_viscosity, g);
  return std::max ({s.inlet_peak_velocity / (1 - pp.maximum_packing),
                    terminal,
                    std::sqrt (2 * g * std::max (height, 0.0)),
                    s.moving_wall_velocity.norm ()});
}

template <int dim>
typename DivergenceChecks<dim>::Result
DivergenceChecks<dim>::check_speeds (const SolverState<dim> &s, const double limit) const
{
  // per cell the largest gas speed at a Q2 node and solids speed at a vertex where
  // alpha_s > 1e-3 (as the wave speeds), the cells above the limit worst first
  std::vector<types::global_dof_index> dofs (s.flow_fe.n_dofs_per_cell ()),
      alpha_dofs (s.alpha_fe.n_dofs_per_cell ());
  const unsigned int  n_nodes   = s.flow_fe.base_element (0).n_dofs_per_cell ();
  const auto          component = component_to_system_table (s.flow_fe);
  std::vector<Excess> local;
  Result              result;
  auto                alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      alpha_cell->get_dof_indices (alpha_dofs);
      double speed[2] = {0, 0};
      for (unsigned int node = 0; node < n_nodes; ++node)
      {
        const bool solids = node < GeometryInfo<dim>::vertices_per_cell &&
                            s.alpha (alpha_dofs[node]) > 1e-3;
        for (unsigned int k = 0; k < (solids ? 2u : 1u); ++k)
        {
          double u2 = 0;
          for (unsigned int d = 0; d < dim; ++d)
            u2 += std::pow (s.flow_solution (dofs[component[k * dim + d][node]]), 2);
          speed[k] = std::max (speed[k], std::sqrt (u2));
        }
      }
      const Point<dim> centre = cell->center ();
      for (unsigned int k = 0; k < 2; ++k)
        if (speed[k] > limit)
          local.push_back ({speed[k],
                            k == 0 ? "|u_g|" : "|u_s|",
                            centre[0],
                            dim > 1 ? centre[1] : 0.0,
                            dim > 2 ? centre[dim - 1] : 0.0});
    }
    ++alpha_cell;
  }
  const auto by_speed = [] (const Excess &a, const Excess &b)
  { return a.speed > b.speed; };
  const unsigned long long count = Utilities::MPI::sum (
      static_cast<unsigned long long> (local.size ()), s.communicator);
  if (count == 0)
    return result;
  std::sort (local.begin (), local.end (), by_speed);
  local.resize (std::min<std::size_t> (local.size (), cells_reported));
  std::vector<Excess> worst;
  for (const auto &part : Utilities::MPI::all_gather (s.communicator, local))
    worst.insert (worst.end (), part.begin (), part.end ());
  std::sort (worst.begin (), worst.end (), by_speed);
  worst.resize (std::min<std::size_t> (worst.size (), cells_reported));
  std::ostringstream reason;
  reason << "speed check: " << worst[0].field << " = " << worst[0].speed
         << " m/s exceeds " << limit << " m/s (divergence checks/speed limit factor = "
         << parameters.divergence_checks.speed_factor << " times the reference speed "
         << limit / parameters.divergence_checks.speed_factor << " m/s)";
  result.passed = false;
  result.reason = reason.str ();
  result.where  = describe (worst, count, limit);
  return result;
}

template <int dim>
typename DivergenceChecks<dim>::Result
DivergenceChecks<dim>::check (const SolverState<dim> &s) const
{
  const auto  &checks    = parameters.divergence_checks;
  const auto  &pp        = parameters.physical;
  const double reference = reference_speed (s);
  Result       result    = check_speeds (s, checks.speed_factor * reference);

  // kinetic energy of both phases, lumped at the vertices (u at the Q2 vertex nodes)
  std::vector<types::global_dof_index> dofs (s.flow_fe.n_dofs_per_cell ()),
      alpha_dofs (s.alpha_fe.n_dofs_per_cell ());
  std::vector<bool> seen (s.alpha.locally_owned_size (), false);
  const auto        component  = component_to_system_table (s.flow_fe);
  double            energy     = 0;
  auto              alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      alpha_cell->get_dof_indices (alpha_dofs);
      for (const unsigned int v : cell->vertex_indices ())
      {
        if (!s.alpha.locally_owned_elements ().is_element (alpha_dofs[v]))
          continue;
        const unsigned int local =
            s.alpha.get_partitioner ()->global_to_local (alpha_dofs[v]);
        if (seen[local])
          continue;
        seen[local]     = true;
        const double a  = std::clamp (s.alpha.local_element (local), 0.0, 1.0);
        double       e2 = 0;
        for (unsigned int k = 0; k < 2; ++k)
        {
          double u2 = 0;
          for (unsigned int d = 0; d < dim; ++d)
            u2 += std::pow (s.flow_solution (dofs[component[k * dim + d][v]]), 2);
          e2 += (k == 0 ? (1 - a) * pp.gas_density : a * pp.particle_density) * u2;
        }
        energy += 0.5 * s.lumped_mass.local_element (local) * e2;
      }
    }
    ++alpha_cell;
  }
  result.kinetic_energy    = Utilities::MPI::sum (energy, s.communicator);
  const double solids_mass = s.solids_mass (s.alpha);
  if (!result.passed)
    return result;

  const PressureDrop drop = evaluate_pressure_drop (s, solids_mass);
  if (std::abs (drop.fluidization) > checks.fluidization_limit)
  {
    std::ostringstream reason;
    reason << "fluidization index check: FI = " << drop.fluidization << " (pressure drop "
           << drop.pressure_drop
           << " Pa) exceeds divergence checks/fluidization index limit = "
           << checks.fluidization_limit;
    result.passed = false;
    result.reason = reason.str ();
    return result;
  }

  if (!energies.empty ())
  {
    const double floor = 0.5 * solids_mass * reference * reference / checks.energy_growth;
    const double base =
        std::max (*std::min_element (energies.begin (), energies.end ()), floor);
    if (result.kinetic_energy > checks.energy_growth * base)
    {
      std::ostringstream reason;
      reason << "kinetic energy check: " << result.kinetic_energy << " J is "
             << result.kinetic_energy / base << " times the least of the last "
             << energies.size () << " steps (divergence checks/energy growth factor = "
             << checks.energy_growth << ")";
      result.passed = false;
      result.reason = reason.str ();
      result.where  = check_speeds (s, 0.5 * reference).where;
    }
  }
  return result;
}

template <int dim>
void DivergenceChecks<dim>::accept (const double kinetic_energy)
{
  energies.push_back (kinetic_energy);
  while (energies.size () > parameters.divergence_checks.energy_window)
    energies.pop_front ();
}

template class DivergenceChecks<2>;
template class DivergenceChecks<3>;
} // namespace wetbed
