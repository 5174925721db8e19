#include <wetbed/solvers/wave_speeds.h>

#include <deal.II/base/mpi.h>

#include <cmath>

namespace wetbed
{
using namespace dealii;

/**
 * The peak speeds of the current fields: gas at every Q2 node, solids at the vertices
 * where alpha_s > 1e-3 (u_s has no meaning where there are no solids), and with the
 * kinetic theory the kinetic pressure's wave speed sqrt(dP/d(alpha rho)) ~ sqrt(2 P_kin
 * / (alpha_s rho_s)) (explicit in the step); collective.
 */
template <int dim>
WaveSpeeds evaluate_wave_speeds (const SolverState<dim> &s)
{
  std::vector<types::global_dof_index> dofs (s.flow_fe.n_dofs_per_cell ()),
      alpha_cell_dofs (s.alpha_fe.n_dofs_per_cell ());
  const unsigned int n_nodes   = s.flow_fe.base_element (0).n_dofs_per_cell ();
  double             gas_speed = 0, solids_speed = 0;
  auto               alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      alpha_cell->get_dof_indices (alpha_cell_dofs);
      for (unsigned int node = 0; node < n_nodes; ++node)
      {
        double g2 = 0, s2 = 0;
        for (unsigned int d = 0; d < dim; ++d)
        {
          g2 += std::pow (
              s.flow_solution (dofs[s.flow_fe.component_to_system_index (d, node)]), 2);
          s2 += std::pow (
              s.flow_solution (dofs[s.flow_fe.component_to_system_index (dim + d, node)]),
              2);
        }
        gas_speed = std::max (gas_speed, std::sqrt (g2));
        if (node < GeometryInfo<dim>::vertices_per_cell &&
            s.alpha (alpha_cell_dofs[node]) > 1e-3)
          solids_speed = std::max (solids_speed, std::sqrt (s2));
      }
    }
    ++alpha_cell;
  }
  double sound = 0;
  if (s.kinetic_theory)
    for (unsigned int i = 0; i < s.theta.locally_owned_size (); ++i)
    {
      const double a = std::max (s.alpha.local_element (i), 0.0);
      if (a > 1e-3)
        sound = std::max (
            sound,
            std::sqrt (2.0 * s.kinetic_theory->evaluate (a, 1.0).pressure_factor *
                       s.theta.local_element (i) /
                       (a * s.parameters.physical.particle_density)));
    }
  WaveSpeeds speeds;
  speeds.gas            = Utilities::MPI::max (gas_speed, s.communicator);
  speeds.solids         = Utilities::MPI::max (solids_speed, s.communicator);
  speeds.granular_sound = Utilities::MPI::max (sound, s.communicator);
  return speeds;
}

template WaveSpeeds evaluate_wave_speeds (const SolverState<2> &);
template WaveSpeeds evaluate_wave_speeds (const SolverState<3> &);
} // namespace wetbed
