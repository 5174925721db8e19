#include <wetbed/solvers/component_table.h>
#include <wetbed/solvers/wave_speeds.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace wetbed
{
using namespace dealii;

namespace
{
/** The kinetic pressure's wave speed sqrt(dP/d(alpha rho)) ~ sqrt(2 P_kin/(alpha_s
 * rho_s)) at a node (explicit in the step); 0 without solids or kinetic theory. */
template <int dim>
double granular_sound (const SolverState<dim> &s, const double alpha, const double theta)
{
  const double a = std::max (alpha, 0.0);
  if (!s.kinetic_theory || a <= 1e-3)
    return 0;
  return std::sqrt (2.0 * s.kinetic_theory->evaluate (a, 1.0).pressure_factor *
                    std::max (theta, 0.0) / (a * s.parameters.physical.particle_density));
}
} // namespace

/**
 * The peak speeds of the current fields: gas at every Q2 node, solids at the vertices
 * where alpha_s > 1e-3 (u_s has no meaning where there are no solids), the kinetic
 * pressure's wave speed at the vertices; and the Courant rate, per cell the largest of
 * its solids speed, its sound speed and a quarter of its gas speed where one of its
 * vertices holds solids (alpha_s > 1e-3), over its Q2 node spacing (half the shortest
 * vertex distance) (doc/theory.md "Time step"); collective.
 */
template <int dim>
WaveSpeeds evaluate_wave_speeds (const SolverState<dim> &s)
{
  // the sound speed once per alpha_s node (owned and ghost), not per cell around it
  typename SolverState<dim>::AlphaVector node_sound (s.alpha);
  for (unsigned int i = 0; i < node_sound.locally_owned_size () +
                                   node_sound.get_partitioner ()->n_ghost_indices ();
       ++i)
    node_sound.local_element (i) =
        granular_sound (s, s.alpha.local_element (i), s.theta.local_element (i));
  std::vector<types::global_dof_index> dofs (s.flow_fe.n_dofs_per_cell ()),
      alpha_cell_dofs (s.alpha_fe.n_dofs_per_cell ());
  const unsigned int n_nodes   = s.flow_fe.base_element (0).n_dofs_per_cell ();
  const auto         component = component_to_system_table (s.flow_fe);
  double             gas_speed = 0, solids_speed = 0, sound_speed = 0, rate = 0;
  auto               alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      alpha_cell->get_dof_indices (alpha_cell_dofs);
      double gas = 0, solids = 0, sound = 0;
      bool   holds_solids = false;
      for (unsigned int node = 0; node < n_nodes; ++node)
      {
        double g2 = 0, s2 = 0;
        for (unsigned int d = 0; d < dim; ++d)
        {
          g2 += std::pow (s.flow_solution (dofs[component[d][node]]), 2);
          s2 += std::pow (s.flow_solution (dofs[component[dim + d][node]]), 2);
        }
        gas = std::max (gas, std::sqrt (g2));
        if (node < GeometryInfo<dim>::vertices_per_cell &&
            s.alpha (alpha_cell_dofs[node]) > 1e-3)
        {
          holds_solids = true;
          solids       = std::max (solids, std::sqrt (s2));
          sound        = std::max (sound, node_sound (alpha_cell_dofs[node]));
        }
      }
      gas_speed            = std::max (gas_speed, gas);
      solids_speed         = std::max (solids_speed, solids);
      sound_speed          = std::max (sound_speed, sound);
      const double spacing = cell->minimum_vertex_distance () / 2.0;
      rate                 = std::max (
          rate, std::max ({solids, sound, holds_solids ? 0.25 * gas : 0.0}) / spacing);
    }
    ++alpha_cell;
  }
  WaveSpeeds speeds;
  speeds.gas            = Utilities::MPI::max (gas_speed, s.communicator);
  speeds.solids         = Utilities::MPI::max (solids_speed, s.communicator);
  speeds.granular_sound = Utilities::MPI::max (sound_speed, s.communicator);
  speeds.courant_rate   = Utilities::MPI::max (rate, s.communicator);
  return speeds;
}

template WaveSpeeds evaluate_wave_speeds (const SolverState<2> &);
template WaveSpeeds evaluate_wave_speeds (const SolverState<3> &);
} // namespace wetbed
