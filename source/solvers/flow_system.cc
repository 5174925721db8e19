#include <wetbed/solvers/flow_system.h>
#include <wetbed/solvers/velocity_near_null_space.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <cmath>

namespace wetbed
{
using namespace dealii;

template <int dim>
FlowSystem<dim>::FlowSystem (const Parameters   &parameters,
                             MPI_Comm            communicator,
                             ConditionalOStream &pcout,
                             TimerOutput        &timer)
    : parameters (parameters), communicator (communicator), timer (timer), pcout (pcout),
      up (upward_direction<dim> (parameters.physical.gravity)),
      multigrid (parameters.linear_solver),
      linear_solver (parameters.linear_solver, pcout, timer)
{
}

template <int dim>
void FlowSystem<dim>::reinit (const Mapping<dim>              &mapping,
                              const DoFHandler<dim>           &flow_dof_handler,
                              const std::vector<IndexSet>     &owned_,
                              const std::vector<IndexSet>     &relevant,
                              const AffineConstraints<double> &flow_constraints,
                              const AffineConstraints<double> &schur_constraints,
                              const Boundaries                &boundaries,
                              const AlphaVector               &alpha_layout)
{
  owned                    = owned_;
  const IndexSet all_owned = flow_dof_handler.locally_owned_dofs ();
  const IndexSet all_relevant =
      DoFTools::extract_locally_relevant_dofs (flow_dof_handler);
  {
    Table<2, DoFTools::Coupling> schur_coupling (2 * dim + 1, 2 * dim + 1);
    for (unsigned int c = 0; c < 2 * dim + 1; ++c)
      for (unsigned int d = 0; d < 2 * dim + 1; ++d)
        schur_coupling[c][d] =
            (c == 2 * dim && d == 2 * dim) ? DoFTools::always : DoFTools::none;
    BlockDynamicSparsityPattern schur_dsp (relevant);
    DoFTools::make_sparsity_pattern (
        flow_dof_handler, schur_coupling, schur_dsp, schur_constraints, false);
    SparsityTools::distribute_sparsity_pattern (
        schur_dsp, all_owned, communicator, all_relevant);
    if (assembled_matrix_needed ())
    {
      Table<2, DoFTools::Coupling> coupling (2 * dim + 1, 2 * dim + 1);
      for (unsigned int c = 0; c < 2 * dim + 1; ++c)
        for (unsigned int d = 0; d < 2 * dim + 1; ++d)
          coupling[c][d] = DoFTools::always; // (p,p) kept for constrained pressure rows
      BlockDynamicSparsityPattern dsp (relevant);
      DoFTools::make_sparsity_pattern (
          flow_dof_handler, coupling, dsp, flow_constraints, false);
      SparsityTools::distribute_sparsity_pattern (
          dsp, all_owned, communicator, all_relevant);
      op.reinit (owned, dsp, schur_dsp, communicator);
    }
    else
      op.reinit_schur (owned, schur_dsp, communicator);
  }
  {
    std::vector<bool> velocity (2 * dim + 1, true);
    velocity[2 * dim] = false;
    // the reactions' parts: every inlet, every wall, every outlet group
    const std::set<types::boundary_id> ids[3] = {boundaries.ids (BoundaryType::inlet),
                                                 boundaries.walls (),
                                                 boundaries.ids (BoundaryType::outlet)};
    for (unsigned int b = 0; b < 3; ++b)
      // (an empty set would mean every boundary to extract_boundary_dofs)
      boundary_velocity_dofs[b] =
          ids[b].empty () ? IndexSet (flow_dof_handler.n_dofs ())
                          : DoFTools::extract_boundary_dofs (
                                flow_dof_handler, ComponentMask (velocity), ids[b]);
  }
  boundary_cell_systems.clear ();
  if (parameters.linear_solver.matrix_free)
  {
    TimerOutput::Scope scope (timer, "matrix-free setup");
    matrix_free_op.reinit (mapping, flow_dof_handler, owned, flow_constraints);
    if (parameters.linear_solver.p_multigrid)
    {
      const unsigned int builds = multigrid.builds;
      multigrid.reinit (matrix_free_op);
      multigrid.builds         = builds;
      multigrid_preconditioner = std::make_unique<MatrixFreeBlockPreconditioner<dim>> (
          parameters.linear_solver, op, multigrid);
    }
  }
  rhs.reinit (owned, communicator);
  assembled_flow.reinit (owned, relevant, communicator);
  assembled_alpha.reinit (alpha_layout);

  // a new mesh needs new hierarchies; the build counts go on
  const unsigned int velocity_builds =
      preconditioner ? preconditioner->velocity_builds : 0;
  const unsigned int schur_builds = preconditioner ? preconditioner->schur_builds : 0;
  preconditioner = std::make_unique<BlockPreconditioner> (parameters.linear_solver);
  preconditioner->velocity_builds = velocity_builds;
  preconditioner->schur_builds    = schur_builds;
  if (!parameters.linear_solver.p_multigrid)
  {
    VelocityNearNullSpace space =
        velocity_near_null_space (mapping,
                                  flow_dof_handler,
                                  owned[0],
                                  parameters.linear_solver.rotation_modes,
                                  communicator);
    preconditioner->set_near_null_space (std::move (space.modes), space.dofs_per_node);
  }
  // the reactions' weighted rows for the matrix-free path (block-0 positions)
  for (unsigned int b = 0; b < 3; ++b)
    reaction_weights[b].clear ();
  if (!assembled_matrix_needed ())
  {
    const auto                          &fe = flow_dof_handler.get_fe ();
    std::vector<types::global_dof_index> dofs (fe.n_dofs_per_cell ());
    std::vector<bool>                    seen (owned[0].n_elements (), false);
    for (const auto &cell : flow_dof_handler.active_cell_iterators ())
      if (cell->is_locally_owned () && cell->at_boundary ())
      {
        cell->get_dof_indices (dofs);
        for (unsigned int i = 0; i < dofs.size (); ++i)
        {
          const unsigned int c = fe.system_to_component_index (i).first;
          if (c >= 2 * dim || !owned[0].is_element (dofs[i]))
            continue;
          const unsigned int position = owned[0].index_within_set (dofs[i]);
          if (seen[position])
            continue;
          seen[position] = true;
          for (unsigned int b = 0; b < 3; ++b)
            if (boundary_velocity_dofs[b].is_element (dofs[i]))
            {
              if (up[c % dim] != 0)
                reaction_weights[b].emplace_back (position, up[c % dim]);
              break;
            }
        }
      }
  }
  linear_solver.reset ();
}

template <int dim>
void FlowSystem<dim>::set_assembler (std::unique_ptr<FlowAssembler<dim>> new_assembler)
{
  assembler = std::move (new_assembler);
}

template <int dim>
void FlowSystem<dim>::assemble (const FlowAssemblyState<dim>    &state,
                                const AffineConstraints<double> &flow_constraints,
                                const AffineConstraints<double> &schur_constraints,
                                const bool                       with_coarse_matrix)
{
  last_assembly = {state, &flow_constraints, &schur_constraints};
  TimerOutput::Scope scope (timer, "flow assembly");
  // the linearisation point (copies of ghosted vectors: the ghost values come along)
  assembled_alpha = *state.alpha;
  assembled_flow  = *state.flow;
  const typename FlowAssembler<dim>::BoundaryRowCapture capture{
      &boundary_velocity_dofs, up, &boundary_cell_systems};
  // the matrix-free operator's coefficients and the p-multigrid's coarse matrix and node
  // blocks come from the same pass over the cells as the rhs and L_c
  typename FlowAssembler<dim>::Sinks sinks;
  if (parameters.linear_solver.matrix_free)
  {
    TimerOutput::Scope mf_scope (timer, "matrix-free coefficients");
    matrix_free_op.begin_update (*assembler);
    sinks.push_back (&matrix_free_op);
    if (parameters.linear_solver.p_multigrid)
    {
      // the coarse matrix only for a pass whose solve rebuilds the coarse AMG
      multigrid.begin_update (with_coarse_matrix || linear_solver.rebuild_due (state.dt));
      sinks.push_back (&multigrid);
    }
  }
  assembler->assemble (state,
                       flow_constraints,
                       schur_constraints,
                       op,
                       rhs,
                       capture,
                       assembled_matrix_needed (),
                       sinks);
  if (parameters.linear_solver.matrix_free)
  {
    TimerOutput::Scope mf_scope (timer, "matrix-free coefficients");
    if (parameters.linear_solver.p_multigrid)
      multigrid.end_update ();
    if (assembled_matrix_needed ())
      matrix_free_op.set_constrained_diagonal (op);
    else
      matrix_free_op.subtract_lifting (rhs, flow_constraints);
  }
  if (parameters.linear_solver.matrix_free && parameters.linear_solver.check_operator)
    check_operator (state, flow_constraints, schur_constraints);
}

template <int dim>
const FlowOperator &FlowSystem<dim>::krylov_operator () const
{
  if (parameters.linear_solver.matrix_free)
    return matrix_free_op;
  return op;
}

template <int dim>
void FlowSystem<dim>::check_operator (const FlowAssemblyState<dim>    &state,
                                      const AffineConstraints<double> &flow_constraints,
                                      const AffineConstraints<double> &schur_constraints)
{
  BlockVector x (owned, communicator), assembled (owned, communicator),
      matrix_free (owned, communicator);
  // a reproducible random vector: the same on any partition
  for (unsigned int b = 0; b < 2; ++b)
    for (const auto i : owned[b])
      x.block (b) (i) = std::sin (1.0 + 0.37 * i + 1.3 * b) + 0.1 * std::cos (7.1 * i);
  x.compress (VectorOperation::insert);
  op.vmult (assembled, x);
  matrix_free_op.vmult (matrix_free, x);
  // normwise: |A_mf x - A x|_inf / (|A|_inf |x|_inf) per block row (the drag and mass
  // terms cancel in A x, so |A x| alone would measure the cancellation)
  double largest = 0;
  for (unsigned int b = 0; b < 2; ++b)
  {
    BlockVector difference (matrix_free);
    difference.block (b) -= assembled.block (b);
    const double row_norm =
        op.system.block (b, 0).linfty_norm () + op.system.block (b, 1).linfty_norm ();
    const double scale = std::max (row_norm * x.linfty_norm (), 1e-300);
    largest            = std::max (largest, difference.block (b).linfty_norm () / scale);
  }
  pcout << "  operator check: matrix-free vs assembled, |A_mf x - A x| / (|A| |x|) = "
        << largest << std::endl;

  // the rhs once more without the local matrices (L_c comes out the same), then the
  // prescribed values carried in matrix-free; the constrained rows set apart
  BlockVector                                           lifted (owned, communicator);
  std::vector<BoundaryCellSystem>                       systems;
  const typename FlowAssembler<dim>::BoundaryRowCapture capture{
      &boundary_velocity_dofs, up, &systems};
  assembler->assemble (
      state, flow_constraints, schur_constraints, op, lifted, capture, false);
  matrix_free_op.subtract_lifting (lifted, flow_constraints);
  BlockVector reference (rhs);
  flow_constraints.set_zero (reference);
  flow_constraints.set_zero (lifted);
  lifted -= reference;
  pcout << "  rhs check: matrix-free lifting vs local matrices, |b_mf - b| / |b| = "
        << lifted.linfty_norm () / std::max (reference.linfty_norm (), 1e-300)
        << std::endl;
}

template <int dim>
double FlowSystem<dim>::relative_residual (
    const BlockVector &solution, const AffineConstraints<double> &flow_constraints) const
{
  BlockVector x (owned, communicator);
  x = solution;
  flow_constraints.set_zero (x); // the solve's unknowns: the constraints are lifted
  BlockVector residual (owned, communicator);
  krylov_operator ().vmult (residual, x);
  residual.sadd (-1.0, 1.0, rhs);
  return residual.l2_norm () / std::max (rhs.l2_norm (), 1e-300);
}

template <int dim>
unsigned int FlowSystem<dim>::solve (BlockVector                     &solution,
                                     const AffineConstraints<double> &flow_constraints,
                                     const double                     relative_target,
                                     const double                     dt,
                                     SolveHistory                    &history)
{
  BlockVector owned_solution (owned, communicator);
  owned_solution = solution; // the lagged iterate as the initial guess
  flow_constraints.set_zero (owned_solution);
  // a rebuild after a failed reused solve needs the coarse matrix of this
  // linearisation, which the assembly left out: the same assembly once more with it
  const auto with_coarse_matrix = [&] ()
  {
    if (!multigrid.coarse_matrix_current ())
      assemble (last_assembly.state,
                *last_assembly.flow_constraints,
                *last_assembly.schur_constraints,
                true);
  };
  const unsigned int iterations = parameters.linear_solver.p_multigrid
                                      ? linear_solver.solve (krylov_operator (),
                                                             matrix_free_op,
                                                             *multigrid_preconditioner,
                                                             rhs,
                                                             owned_solution,
                                                             relative_target,
                                                             dt,
                                                             history,
                                                             with_coarse_matrix)
                                      : linear_solver.solve (krylov_operator (),
                                                             op,
                                                             *preconditioner,
                                                             rhs,
                                                             owned_solution,
                                                             relative_target,
                                                             dt,
                                                             history);
  if (iterations == numbers::invalid_unsigned_int)
    return iterations;
  flow_constraints.distribute (owned_solution);
  solution = owned_solution;
  return iterations;
}

template <int dim>
std::array<double, 3>
FlowSystem<dim>::boundary_reactions (const BlockVector &solution) const
{
  std::array<double, 3> residual = {{0, 0, 0}};
  for (const BoundaryCellSystem &system : boundary_cell_systems)
    for (unsigned int b = 0; b < 3; ++b)
    {
      residual[b] -= system.rhs[b];
      for (unsigned int j = 0; j < system.row[b].size (); ++j)
        residual[b] += system.row[b][j] * solution (system.dofs[j]);
    }
  if (!assembled_matrix_needed ())
  {
    // the rows' matrix part applied matrix-free (the assembly kept their rhs part)
    BlockVector owned_solution (owned, communicator);
    owned_solution = solution;
    const std::array<double, 3> rows =
        matrix_free_op.weighted_row_sums (owned_solution, reaction_weights);
    for (unsigned int b = 0; b < 3; ++b)
      residual[b] += rows[b];
  }
  // the rows lack the boundary terms of the integration by parts, -int (-p' I + tau) n
  // . v: what they leave unbalanced is the force the boundary exerts (0 on free rows)
  for (double &r : residual)
    r = Utilities::MPI::sum (r, communicator);
  return residual;
}

template <int dim>
typename FlowSystem<dim>::Memory FlowSystem<dim>::memory_consumption () const
{
  Memory memory;
  memory.op = op.system.memory_consumption ();
  if (parameters.linear_solver.matrix_free)
    memory.op += matrix_free_op.memory_consumption ();
  memory.schur = op.schur.memory_consumption ();
  if (parameters.linear_solver.p_multigrid)
    memory.multigrid = multigrid.memory_consumption ();
  memory.vectors = rhs.memory_consumption () + assembled_flow.memory_consumption () +
                   assembled_alpha.memory_consumption ();
  return memory;
}

template class FlowSystem<2>;
template class FlowSystem<3>;
} // namespace wetbed
