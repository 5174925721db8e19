#include <wetbed/postprocess/bed_monitors.h>
#include <wetbed/postprocess/bed_profile.h>
#include <wetbed/postprocess/gas_flows.h>
#include <wetbed/postprocess/momentum_budget.h>
#include <wetbed/postprocess/pressure_drop.h>
#include <wetbed/postprocess/wall_forces.h>
#include <wetbed/solvers/flow_system.h>

#include <deal.II/base/mpi.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <fstream>
#include <sstream>
#include <tuple>

namespace wetbed
{
using namespace dealii;

namespace
{
/** The height below which `share` of the solids lie (nodal masses sorted by height,
 * heights along -g from the origin); collective. */
template <int dim>
double solids_height (const SolverState<dim> &s, const double share)
{
  const Tensor<1, dim> up = upward_direction<dim> (s.parameters.physical.gravity);
  std::vector<std::pair<double, double>> height_mass;
  const auto                            &mass = s.lumped_mass;
  std::vector<types::global_dof_index>   alpha_dofs (s.alpha_fe.n_dofs_per_cell ());
  std::vector<bool>                      seen (s.alpha.locally_owned_size (), false);
  for (const auto &cell : s.alpha_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (alpha_dofs);
      for (const unsigned int v : cell->vertex_indices ())
        if (s.alpha.locally_owned_elements ().is_element (alpha_dofs[v]))
        {
          const unsigned int local =
              s.alpha.get_partitioner ()->global_to_local (alpha_dofs[v]);
          if (seen[local])
            continue;
          seen[local] = true;
          height_mass.emplace_back (cell->vertex (v) * up,
                                    mass.local_element (local) *
                                        s.alpha.local_element (local));
        }
    }
  const auto all = Utilities::MPI::all_gather (s.communicator, height_mass);
  std::vector<std::pair<double, double>> merged;
  for (const auto &part : all)
    merged.insert (merged.end (), part.begin (), part.end ());
  std::sort (merged.begin (), merged.end ());

  double total = 0;
  for (const auto &hm : merged)
    total += hm.second;
  double running = 0;
  for (const auto &hm : merged)
  {
    running += hm.second;
    if (running >= share * total)
    {
      return hm.first;
    }
  }
  return 0;
}

/** alpha_s's extremes over the nodes; collective. */
template <int dim>
std::pair<double, double> solids_fraction_range (const SolverState<dim> &s)
{
  double lo = std::numeric_limits<double>::max (), hi = -lo;
  for (unsigned int i = 0; i < s.alpha.locally_owned_size (); ++i)
  {
    lo = std::min (lo, s.alpha.local_element (i));
    hi = std::max (hi, s.alpha.local_element (i));
  }
  return {Utilities::MPI::min (lo, s.communicator),
          Utilities::MPI::max (hi, s.communicator)};
}
} // namespace

/**
 * Monitors of the bed after a step: pressure drop (mean p' over the inlet minus the
 * mean over the outlet), fluidization index FI = dP A / ((M_s (1 - rho_g/rho_s)) |g|)
 * (p' excludes the gas hydrostatic part, so the bed weight is taken net of buoyancy),
 * the shares of the bed weight the walls and the distributor carry (wall_forces.cc),
 * solids mass and drift, bounds, peak speeds, the bed height (95% of the solids below
 * it) and, at each probe height, alpha_s averaged over the layer of cells that contains
 * it (heights along -g from the coordinate origin, the inlet plane of the shipped
 * meshes; the cells straddling the height, volume-weighted).
 */
template <int dim>
MonitorRow evaluate_monitors (const SolverState<dim> &s)
{
  MonitorRow row;
  row.active_cells   = s.triangulation.n_global_active_cells ();
  row.step           = s.step_number;
  row.time           = s.time;
  row.time_step      = s.time_step;
  row.inlet_velocity = s.inlet_velocity;
  row.krylov         = s.krylov_iterations;
  row.rejected       = s.rejected_steps;

  const auto &pp  = s.parameters.physical;
  row.solids_mass = s.solids_mass (s.alpha);
  // relative to the initial mass, the fed mass taken out (to the fed mass when the
  // domain starts empty)
  row.mass_drift = s.initial_solids_mass > 0
                       ? (row.solids_mass - s.solids_fed_mass) / s.initial_solids_mass - 1
                   : s.solids_fed_mass > 0 ? row.solids_mass / s.solids_fed_mass - 1
                                           : 0;
  if (s.parameters.boundary.feeds_solids ())
    row.solids_fed = {s.solids_fed_mass};
  const PressureDrop drop = evaluate_pressure_drop (s, row.solids_mass);
  row.pressure_drop       = drop.pressure_drop;
  const GasFlows flows    = evaluate_gas_flows (s);
  row.gas_inflow          = flows.inflow;
  row.gas_outflow         = flows.outflow;
  row.fluidization        = drop.fluidization;
  const double weight =
      row.solids_mass * (1 - pp.gas_density / pp.particle_density) * pp.gravity.norm ();
  if (weight > 0)
  {
    const WallForces forces      = evaluate_wall_forces (s);
    row.wall_support_solids      = forces.solids_wall / weight;
    row.wall_support_gas         = forces.gas_wall / weight;
    row.distributor_support      = forces.distributor / weight;
    row.outlet_support           = forces.outlet / weight;
    const InertialBudget inertia = evaluate_inertial_budget (s);
    row.mixture_momentum         = inertia.momentum / weight;
    row.continuity_defect        = inertia.continuity_defect / weight;
    row.momentum_outflow         = inertia.momentum_outflow / weight;
    const std::array<double, 3> reactions =
        s.flow_system.boundary_reactions (s.flow_solution);
    row.inlet_reaction  = reactions[0] / weight;
    row.wall_reaction   = reactions[1] / weight;
    row.outlet_reaction = reactions[2] / weight;
    row.correction_force =
        s.time_step > 0 ? s.correction_momentum / (s.time_step * weight) : 0;
  }

  std::tie (row.alpha_min, row.alpha_max) = solids_fraction_range (s);

  const WaveSpeeds &speeds = s.wave_speeds;
  row.gas_speed_max        = speeds.gas;
  row.solids_speed_max     = speeds.solids;
  row.granular_sound_speed = speeds.granular_sound;
  row.time_error           = s.time_error;

  row.bed_height = solids_height (s, 0.95);
  // granular temperature: extremes over the nodes, mean weighted by the solids mass
  if (s.kinetic_theory)
  {
    const auto &mass = s.lumped_mass;
    double lo = std::numeric_limits<double>::max (), hi = 0, weighted = 0, weight = 0;
    for (unsigned int i = 0; i < s.theta.locally_owned_size (); ++i)
    {
      lo             = std::min (lo, s.theta.local_element (i));
      hi             = std::max (hi, s.theta.local_element (i));
      const double m = mass.local_element (i) * s.alpha.local_element (i);
      weighted += m * s.theta.local_element (i);
      weight += m;
    }
    row.theta_min = Utilities::MPI::min (lo, s.communicator);
    row.theta_max = Utilities::MPI::max (hi, s.communicator);
    weight        = Utilities::MPI::sum (weight, s.communicator);
    row.theta_mean =
        weight > 0 ? Utilities::MPI::sum (weighted, s.communicator) / weight : 0;
    row.granular_energy = s.granular_energy;
  }
  evaluate_bed_profile (s, row);
  return row;
}

template MonitorRow evaluate_monitors (const SolverState<2> &);
template MonitorRow evaluate_monitors (const SolverState<3> &);
} // namespace wetbed
