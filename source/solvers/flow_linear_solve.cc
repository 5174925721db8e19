#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_gmres.h>

namespace wetbed
{
using namespace dealii;

template <int dim>
void TwoFluidSolver<dim>::build_velocity_preconditioner (const double current_dt)
{
  // near-null space of the velocity block: per phase, the translation of each component
  // and, with `rotation modes`, the rigid rotations about the mesh centre (the modes a
  // slip wall leaves almost free: a rotation in a cylinder costs only its axial shear)
  const IndexSet    &owned = flow_owned[0];
  const unsigned int n_rotations =
      parameters.linear_solver.rotation_modes ? (dim == 2 ? 1 : 3) : 0;
  const unsigned int               per_phase = dim + n_rotations;
  std::vector<std::vector<double>> modes (2 * per_phase,
                                          std::vector<double> (owned.n_elements (), 0.0));
  Point<dim>                       lower, upper;
  for (unsigned int d = 0; d < dim; ++d)
  {
    lower[d] = std::numeric_limits<double>::max ();
    upper[d] = -lower[d];
  }
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned ())
      for (const auto v : cell->vertex_indices ())
        for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min (lower[d], cell->vertex (v)[d]);
          upper[d] = std::max (upper[d], cell->vertex (v)[d]);
        }
  Point<dim> centre;
  for (unsigned int d = 0; d < dim; ++d)
    centre[d] = 0.5 * (Utilities::MPI::min (lower[d], communicator) +
                       Utilities::MPI::max (upper[d], communicator));
  const Quadrature<dim> nodes (flow_fe.get_unit_support_points ());
  FEValues<dim>         node_values (mapping, flow_fe, nodes, update_quadrature_points);
  std::vector<types::global_dof_index> dofs (flow_fe.n_dofs_per_cell ());
  // node blocks: ML aggregates nodes and smooths node blocks when the 2 dim velocity
  // DoFs of every support point are consecutive rows (the numbering keeps them so;
  // checked here, and the blocks are dropped where it would not hold)
  bool nodes_contiguous = true;
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      node_values.reinit (cell);
      for (unsigned int i = 0; i < dofs.size (); ++i)
      {
        const auto [c, node] = flow_fe.system_to_component_index (i);
        if (c >= 2 * dim || !owned.is_element (dofs[i]))
          continue;
        if (dofs[i] != dofs[flow_fe.component_to_system_index (0, node)] + c)
          nodes_contiguous = false;
        const auto         row   = owned.index_within_set (dofs[i]);
        const unsigned int phase = c / dim, d = c % dim;
        modes[phase * per_phase + d][row] = 1.0;
        const Tensor<1, dim> x            = node_values.quadrature_point (i) - centre;
        if (n_rotations == 1) // (-y, x)
          modes[phase * per_phase + dim][row] = d == 0 ? -x[1] : x[0];
        else if (n_rotations == 3) // e_a x x
          for (unsigned int a = 0; a < 3; ++a)
          {
            const unsigned int b = (a + 1) % 3, e = (a + 2) % 3;
            modes[phase * per_phase + dim + a][row] = d == b   ? -x[e]
                                                      : d == e ? x[b]
                                                               : 0.0;
          }
      }
    }
  nodes_contiguous = Utilities::MPI::min (nodes_contiguous ? 1 : 0, communicator) == 1;
  preconditioner->build_velocity (
      flow_matrix.block (0, 0), modes, nodes_contiguous ? 2 * dim : 1);
  solves_since_build     = 0;
  iterations_after_build = 0;
  dt_at_build            = current_dt;
}

/**
 * FGMRES on the monolithic (u_g, u_s, p') system with the block preconditioner. The
 * Schur AMG is rebuilt every solve (it is cheap, Q1). The velocity AMG is rebuilt after
 * `rebuild interval` solves, when dt changed by more than 20%, or when the iterations
 * grew beyond `rebuild growth` times those right after its build. A solve with a reused
 * hierarchy gets at most 3x those iterations (+10): if it misses that, the hierarchy is
 * rebuilt and the same solve is repeated, so reuse never costs a rejected step.
 * Returns the iterations, or invalid_unsigned_int when the solve failed with a fresh
 * hierarchy (the step is then rejected).
 */
template <int dim>
unsigned int TwoFluidSolver<dim>::solve_flow_system (const double current_dt)
{
  const auto &ls = parameters.linear_solver;
  {
    TimerOutput::Scope scope (timer, "preconditioner setup");
    if (solves_since_build >= ls.rebuild_interval ||
        std::abs (current_dt / dt_at_build - 1.0) > 0.2)
      build_velocity_preconditioner (current_dt);
    preconditioner->build_schur (schur_matrix.block (1, 1));
  }

  const double target = ls.relative_tolerance * flow_rhs.l2_norm ();
  BlockVector  solution (flow_owned, communicator);
  unsigned int spent = 0;
  for (unsigned int attempt = 0; attempt < 2; ++attempt)
  {
    const bool         reused = solves_since_build > 0;
    const unsigned int limit =
        reused ? std::min (ls.maximum_iterations, 3 * iterations_after_build + 10)
               : ls.maximum_iterations;
    TimerOutput::Scope scope (timer, "Krylov solve");
    solution = flow_solution; // lagged iterate as the initial guess
    flow_constraints.set_zero (solution);
    SolverControl control (limit, std::max (target, 1e-300));
    control.enable_history_data ();
    SolverFGMRES<BlockVector> fgmres (
        control, typename SolverFGMRES<BlockVector>::AdditionalData (ls.restart));
    try
    {
      fgmres.solve (flow_matrix, solution, flow_rhs, *preconditioner);
    }
    catch (const SolverControl::NoConvergence &)
    {
      solve_history.record (
          reused ? "flow FGMRES (reused AMG)" : "flow FGMRES", control, false);
      spent += control.last_step ();
      if (reused)
      {
        TimerOutput::Scope setup (timer, "preconditioner setup");
        build_velocity_preconditioner (current_dt);
        continue;
      }
      solves_since_build = ls.rebuild_interval;
      pcout << "  FGMRES did not converge in " << control.last_step ()
            << " iterations (residual " << control.last_value () << ", target " << target
            << ")" << std::endl;
      return numbers::invalid_unsigned_int;
    }
    const unsigned int iterations = control.last_step ();
    solve_history.record (
        reused ? "flow FGMRES (reused AMG)" : "flow FGMRES", control, true);
    if (ls.verbose)
      pcout << "    FGMRES " << iterations << " iterations"
            << (reused ? " (reused AMG)" : "") << std::endl;
    flow_constraints.distribute (solution);
    flow_solution = solution;
    ++solves_since_build;
    if (iterations_after_build == 0)
      iterations_after_build = std::max (1u, iterations);
    else if (iterations > ls.rebuild_growth * iterations_after_build)
      solves_since_build = ls.rebuild_interval;
    return iterations + spent;
  }
  return numbers::invalid_unsigned_int;
}

template unsigned int TwoFluidSolver<2>::solve_flow_system (double);
template unsigned int TwoFluidSolver<3>::solve_flow_system (double);
template void         TwoFluidSolver<2>::build_velocity_preconditioner (double);
template void         TwoFluidSolver<3>::build_velocity_preconditioner (double);
} // namespace wetbed
