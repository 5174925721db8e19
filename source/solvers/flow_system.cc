#include <wetbed/solvers/flow_system.h>
#include <wetbed/solvers/velocity_near_null_space.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

namespace wetbed
{
using namespace dealii;

template <int dim>
FlowSystem<dim>::FlowSystem (const Parameters   &parameters,
                             MPI_Comm            communicator,
                             ConditionalOStream &pcout,
                             TimerOutput        &timer)
    : parameters (parameters), communicator (communicator), timer (timer),
      up (upward_direction<dim> (parameters.physical.gravity)),
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
    Table<2, DoFTools::Coupling> coupling (2 * dim + 1, 2 * dim + 1);
    for (unsigned int c = 0; c < 2 * dim + 1; ++c)
      for (unsigned int d = 0; d < 2 * dim + 1; ++d)
        coupling[c][d] = DoFTools::always; // (p,p) kept for constrained pressure rows
    BlockDynamicSparsityPattern dsp (relevant);
    DoFTools::make_sparsity_pattern (
        flow_dof_handler, coupling, dsp, flow_constraints, false);
    SparsityTools::distribute_sparsity_pattern (
        dsp, all_owned, communicator, all_relevant);
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
    op.reinit (owned, dsp, schur_dsp, communicator);
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
  VelocityNearNullSpace space =
      velocity_near_null_space (mapping,
                                flow_dof_handler,
                                owned[0],
                                parameters.linear_solver.rotation_modes,
                                communicator);
  preconditioner->set_near_null_space (std::move (space.modes), space.dofs_per_node);
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
                                const AffineConstraints<double> &schur_constraints)
{
  TimerOutput::Scope scope (timer, "flow assembly");
  // the linearisation point (copies of ghosted vectors: the ghost values come along)
  assembled_alpha = *state.alpha;
  assembled_flow  = *state.flow;
  const typename FlowAssembler<dim>::BoundaryRowCapture capture{
      &boundary_velocity_dofs, up, &boundary_cell_systems};
  assembler->assemble (state, flow_constraints, schur_constraints, op, rhs, capture);
}

template <int dim>
unsigned int FlowSystem<dim>::solve (BlockVector                     &solution,
                                     const AffineConstraints<double> &flow_constraints,
                                     const double                     dt,
                                     SolveHistory                    &history)
{
  BlockVector owned_solution (owned, communicator);
  owned_solution = solution; // the lagged iterate as the initial guess
  flow_constraints.set_zero (owned_solution);
  const unsigned int iterations =
      linear_solver.solve (op, *preconditioner, rhs, owned_solution, dt, history);
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
  // the rows lack the boundary terms of the integration by parts, -int (-p' I + tau) n
  // . v: what they leave unbalanced is the force the boundary exerts (0 on free rows)
  for (double &r : residual)
    r = Utilities::MPI::sum (r, communicator);
  return residual;
}

template class FlowSystem<2>;
template class FlowSystem<3>;
} // namespace wetbed
