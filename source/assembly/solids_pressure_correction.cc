#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>

namespace wetbed
{
using namespace dealii;

/**
 * Implicit solids-pressure correction (DESIGN s4.2, the OpenFOAM implicitPhasePressure /
 * MFIX solids-correction idea in increment form). The momentum solve that produced the
 * transporting u_s saw -grad P_s(alpha_m); the correction makes the compaction response
 * implicit in the change since then:
 *   M_L (alpha - alpha*)/dt + K[D_p] (alpha - alpha_m) = 0,
 *   D_p = alpha_s P_s'(alpha*) / (a0 alpha_s rho_s / dt + beta).
 * K[D_p] is symmetric with zero row sums, so the solids mass is kept to solver
 * tolerance; a bed at rest (alpha* = alpha_m) is left exactly at rest. Skipped where
 * P_s' = 0, i.e. in every scene without compacted regions.
 */
template <int dim>
void TwoFluidSolver<dim>::correct_solids_pressure (const AlphaVector     &alpha_momentum,
                                                   const BDFCoefficients &bdf,
                                                   const double           dt)
{
  TimerOutput::Scope scope (timer, "solids pressure correction");
  const double       rho_s = parameters.physical.particle_density;

  const QGauss<dim>  quadrature (2);
  FEValues<dim>      alpha_values (mapping,
                              alpha_fe,
                              quadrature,
                              update_values | update_gradients | update_JxW_values);
  FEValues<dim>      flow_values (mapping, flow_fe, quadrature, update_values);
  const unsigned int n = alpha_fe.n_dofs_per_cell ();
  FullMatrix<double> cell_matrix (n, n);
  Vector<double>     cell_rhs (n);
  std::vector<types::global_dof_index> dofs (n);
  std::vector<double>                  a (quadrature.size ()), a_m (quadrature.size ());
  std::vector<Tensor<1, dim>>          ug (quadrature.size ()), us (quadrature.size ());
  const FEValuesExtractors::Vector     gas (0), solids (dim);

  correction_matrix = 0;
  TrilinosWrappers::MPI::Vector rhs (alpha_dof_handler.locally_owned_dofs (),
                                     communicator);
  bool                          active    = false;
  auto                          flow_cell = flow_dof_handler.begin_active ();
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      alpha_values.reinit (cell);
      flow_values.reinit (flow_cell);
      alpha_values.get_function_values (alpha, a);
      flow_values[gas].get_function_values (flow_solution, ug);
      flow_values[solids].get_function_values (flow_solution, us);
      cell->get_dof_indices (dofs);
      cell_matrix = 0;
      cell_rhs    = 0;
      for (unsigned int q = 0; q < quadrature.size (); ++q)
      {
        const double alpha_s = a[q];
        const double slope =
            solids_stress->evaluate ({alpha_s, 0.0, 0.0}).pressure_derivative;
        const double beta =
            alpha_s > 0
                ? drag->coefficient (alpha_s, (ug[q] - us[q]).norm (), gas_particle)
                : 0;
        const double diffusivity =
            slope > 0 ? alpha_s * slope / (bdf.a0 * alpha_s * rho_s / dt + beta) : 0.0;
        active = active || diffusivity > 0;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            cell_matrix (i, j) +=
                diffusivity * dt *
                (alpha_values.shape_grad (i, q) * alpha_values.shape_grad (j, q)) *
                alpha_values.JxW (q);
      }
      // rhs: K (alpha_m - alpha*) so that the unknown is the increment alpha - alpha*
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          cell_rhs (i) +=
              cell_matrix (i, j) * (alpha_momentum (dofs[j]) - alpha (dofs[j]));
      // lumped mass on the diagonal
      for (unsigned int q = 0; q < quadrature.size (); ++q)
        for (unsigned int i = 0; i < n; ++i)
          cell_matrix (i, i) += alpha_values.shape_value (i, q) * alpha_values.JxW (q);
      correction_matrix.add (dofs, cell_matrix);
      rhs.add (dofs, cell_rhs);
    }
    ++flow_cell;
  }
  correction_matrix.compress (VectorOperation::add);
  rhs.compress (VectorOperation::add);
  if (!Utilities::MPI::logical_or (active, communicator))
    return;

  TrilinosWrappers::MPI::Vector increment (rhs);
  increment = 0;
  SolverControl control (
      1000, parameters.linear_solver.scalar_tolerance * rhs.l2_norm () + 1e-300);
  SolverCG<TrilinosWrappers::MPI::Vector> cg (control);
  TrilinosWrappers::PreconditionAMG       amg;
  amg.initialize (correction_matrix);
  cg.solve (correction_matrix, increment, rhs, amg);
  // x = alpha* + increment - alpha_m; the increment becomes the limited edge fluxes
  // -A_ij (x_j - x_i) of the scaled operator A = dt K (its off-diagonal part)
  AlphaVector x (alpha);
  for (unsigned int i = 0; i < x.locally_owned_size (); ++i)
    x.local_element (i) = alpha.local_element (i) +
                          increment[alpha.get_partitioner ()->local_to_global (i)] -
                          alpha_momentum.local_element (i);
  x.update_ghost_values ();
  transport.apply_diffusive_fluxes (
      alpha, correction_matrix, x, parameters.physical.maximum_packing);
}

template <int dim>
void TwoFluidSolver<dim>::solids_velocity_at_alpha_nodes (
    const BlockVector &flow, std::vector<AlphaVector> &u) const
{
  // Q1 nodes are the vertices; the Q2 vertex dofs carry u_s there exactly.
  std::vector<types::global_dof_index> flow_dofs (flow_fe.n_dofs_per_cell ()),
      alpha_dofs (alpha_fe.n_dofs_per_cell ());
  auto alpha_cell = alpha_dof_handler.begin_active ();
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (flow_dofs);
      alpha_cell->get_dof_indices (alpha_dofs);
      for (const unsigned int v : cell->vertex_indices ())
        if (u[0].locally_owned_elements ().is_element (alpha_dofs[v]))
          for (unsigned int d = 0; d < dim; ++d)
            u[d](alpha_dofs[v]) =
                flow (flow_dofs[flow_fe.component_to_system_index (dim + d, v)]);
    }
    ++alpha_cell;
  }
  for (auto &component : u)
    component.update_ghost_values ();
}

template void TwoFluidSolver<2>::correct_solids_pressure (const AlphaVector &,
                                                          const BDFCoefficients &,
                                                          double);
template void TwoFluidSolver<3>::correct_solids_pressure (const AlphaVector &,
                                                          const BDFCoefficients &,
                                                          double);
template void
TwoFluidSolver<2>::solids_velocity_at_alpha_nodes (const BlockVector &,
                                                   std::vector<AlphaVector> &) const;
template void
TwoFluidSolver<3>::solids_velocity_at_alpha_nodes (const BlockVector &,
                                                   std::vector<AlphaVector> &) const;
} // namespace wetbed
