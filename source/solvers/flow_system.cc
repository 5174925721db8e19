#include <wetbed/solvers/flow_system.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

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
      path (make_flow_solve_path<dim> (parameters.linear_solver, pcout, timer)),
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
  owned = owned_;
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
  path->reinit ({mapping,
                 flow_dof_handler,
                 owned,
                 relevant,
                 flow_constraints,
                 schur_constraints,
                 boundary_velocity_dofs,
                 up},
                communicator);
  rhs.reinit (owned, communicator);
  residual_iterate.reinit (owned, communicator);
  residual.reinit (owned, communicator);
  assembled_flow.reinit (owned, relevant, communicator);
  assembled_alpha.reinit (alpha_layout);
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
  // the solve path's operator data (its coefficients, the p-multigrid's coarse matrix
  // only for a pass whose solve rebuilds the coarse AMG) come from the same pass over
  // the cells as the rhs and L_c
  const auto target = path->begin_assembly (
      *assembler, with_coarse_matrix || linear_solver.rebuild_due (state.dt));
  assembler->assemble (state, flow_constraints, schur_constraints, target, rhs, capture);
  // the same pass into another target, the boundary rows set aside (the operator check)
  const auto reassemble =
      [&] (const typename FlowAssembler<dim>::Target &other, BlockVector &other_rhs)
  {
    std::vector<BoundaryCellSystem>                       systems;
    const typename FlowAssembler<dim>::BoundaryRowCapture other_capture{
        &boundary_velocity_dofs, up, &systems};
    assembler->assemble (
        state, flow_constraints, schur_constraints, other, other_rhs, other_capture);
  };
  path->end_assembly (rhs, flow_constraints, reassemble);
}

template <int dim>
double FlowSystem<dim>::relative_residual (
    const BlockVector &solution, const AffineConstraints<double> &flow_constraints) const
{
  BlockVector &x = residual_iterate;
  x              = solution;
  flow_constraints.set_zero (x); // the solve's unknowns: the constraints are lifted
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
  // the same assembly once more with the coarse matrix (for a rebuild the solve path
  // did not foresee)
  const auto assemble_coarse_matrix = [&] ()
  {
    assemble (last_assembly.state,
              *last_assembly.flow_constraints,
              *last_assembly.schur_constraints,
              true);
  };
  const unsigned int iterations = path->solve (linear_solver,
                                               rhs,
                                               owned_solution,
                                               relative_target,
                                               dt,
                                               history,
                                               assemble_coarse_matrix);
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
  const std::array<double, 3> rows = path->uncaptured_reactions (solution);
  for (unsigned int b = 0; b < 3; ++b)
    residual[b] += rows[b];
  // the rows lack the boundary terms of the integration by parts, -int (-p' I + tau) n
  // . v: what they leave unbalanced is the force the boundary exerts (0 on free rows)
  for (double &r : residual)
    r = Utilities::MPI::sum (r, communicator);
  return residual;
}

template <int dim>
typename FlowSystem<dim>::Memory FlowSystem<dim>::memory_consumption () const
{
  Memory memory  = path->memory_consumption ();
  memory.vectors = rhs.memory_consumption () + assembled_flow.memory_consumption () +
                   assembled_alpha.memory_consumption ();
  return memory;
}

template class FlowSystem<2>;
template class FlowSystem<3>;
} // namespace wetbed
