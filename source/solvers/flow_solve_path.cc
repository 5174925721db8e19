#include <wetbed/solvers/flow_solve_path.h>
#include <wetbed/solvers/velocity_near_null_space.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <cmath>

namespace wetbed
{
using namespace dealii;

namespace
{
/** The sparsity of L_c and, with `with_system`, of the whole system on this mesh. */
template <int dim>
void reinit_matrices (AssembledFlowOperator                   &op,
                      const typename FlowSolvePath<dim>::Mesh &mesh,
                      const bool                               with_system,
                      MPI_Comm                                 communicator)
{
  const DoFHandler<dim> &dof_handler = mesh.dof_handler;
  const IndexSet         all_owned   = dof_handler.locally_owned_dofs ();
  const IndexSet all_relevant = DoFTools::extract_locally_relevant_dofs (dof_handler);
  Table<2, DoFTools::Coupling> schur_coupling (2 * dim + 1, 2 * dim + 1);
  for (unsigned int c = 0; c < 2 * dim + 1; ++c)
    for (unsigned int d = 0; d < 2 * dim + 1; ++d)
      schur_coupling[c][d] =
          (c == 2 * dim && d == 2 * dim) ? DoFTools::always : DoFTools::none;
  BlockDynamicSparsityPattern schur_dsp (mesh.relevant);
  DoFTools::make_sparsity_pattern (
      dof_handler, schur_coupling, schur_dsp, mesh.schur_constraints, false);
  SparsityTools::distribute_sparsity_pattern (
      schur_dsp, all_owned, communicator, all_relevant);
  if (!with_system)
  {
    op.reinit_schur (mesh.owned, schur_dsp, communicator);
    return;
  }
  Table<2, DoFTools::Coupling> coupling (2 * dim + 1, 2 * dim + 1);
  for (unsigned int c = 0; c < 2 * dim + 1; ++c)
    for (unsigned int d = 0; d < 2 * dim + 1; ++d)
      coupling[c][d] = DoFTools::always; // (p,p) kept for constrained pressure rows
  BlockDynamicSparsityPattern dsp (mesh.relevant);
  DoFTools::make_sparsity_pattern (
      dof_handler, coupling, dsp, mesh.flow_constraints, false);
  SparsityTools::distribute_sparsity_pattern (dsp, all_owned, communicator, all_relevant);
  op.reinit (mesh.owned, dsp, schur_dsp, communicator);
}

/** A fresh block AMG for `op` with the velocity near-null space of this mesh; the build
 * counts of `previous` go on. */
template <int dim>
std::unique_ptr<BlockPreconditioner>
fresh_block_amg (const LinearSolverParameters               &parameters,
                 const AssembledFlowOperator                &op,
                 const typename FlowSolvePath<dim>::Mesh    &mesh,
                 const std::unique_ptr<BlockPreconditioner> &previous,
                 MPI_Comm                                    communicator)
{
  auto preconditioner = std::make_unique<BlockPreconditioner> (parameters, op);
  if (previous)
  {
    preconditioner->velocity_builds = previous->velocity_builds;
    preconditioner->schur_builds    = previous->schur_builds;
  }
  VelocityNearNullSpace space = velocity_near_null_space (mesh.mapping,
                                                          mesh.dof_handler,
                                                          mesh.owned[0],
                                                          parameters.rotation_modes,
                                                          communicator);
  preconditioner->set_near_null_space (std::move (space.modes), space.dofs_per_node);
  return preconditioner;
}
} // namespace

template <int dim>
std::array<double, 3> FlowSolvePath<dim>::uncaptured_reactions (const BlockVector &) const
{
  return {{0, 0, 0}};
}

// ---------------------------------------------------------------- assembled

template <int dim>
AssembledSolvePath<dim>::AssembledSolvePath (const LinearSolverParameters &parameters)
    : parameters (parameters)
{
}

template <int dim>
void AssembledSolvePath<dim>::reinit (const Mesh &mesh, MPI_Comm communicator)
{
  reinit_matrices<dim> (op, mesh, true, communicator);
  preconditioner =
      fresh_block_amg<dim> (parameters, op, mesh, preconditioner, communicator);
}

template <int dim>
typename AssembledSolvePath<dim>::Target
AssembledSolvePath<dim>::begin_assembly (const FlowAssembler<dim> &, bool)
{
  return Target{&op.system, &op.schur, {}};
}

template <int dim>
unsigned int AssembledSolvePath<dim>::solve (FlowLinearSolver  &linear_solver,
                                             const BlockVector &rhs,
                                             BlockVector       &solution,
                                             const double       relative_target,
                                             const double       dt,
                                             SolveHistory      &history,
                                             const std::function<void ()> &)
{
  return linear_solver.solve (
      op, *preconditioner, rhs, solution, relative_target, dt, history);
}

template <int dim>
unsigned int AssembledSolvePath<dim>::velocity_builds () const
{
  return preconditioner ? preconditioner->velocity_builds : 0;
}

template <int dim>
FlowSolveMemory AssembledSolvePath<dim>::memory_consumption () const
{
  FlowSolveMemory memory;
  memory.op    = op.system.memory_consumption ();
  memory.schur = op.schur.memory_consumption ();
  return memory;
}

// ---------------------------------------------------------------- matrix-free

template <int dim>
MatrixFreeSolvePath<dim>::MatrixFreeSolvePath (const LinearSolverParameters &parameters,
                                               const bool                    with_matrix,
                                               ConditionalOStream           &pcout,
                                               TimerOutput                  &timer)
    : parameters (parameters), with_matrix (with_matrix),
      check (parameters.check_operator), pcout (pcout), timer (timer)
{
}

template <int dim>
void MatrixFreeSolvePath<dim>::reinit (const Mesh &mesh, MPI_Comm communicator_)
{
  owned        = mesh.owned;
  communicator = communicator_;
  reinit_matrices<dim> (op, mesh, with_matrix, communicator);
  {
    TimerOutput::Scope scope (timer, "matrix-free setup");
    matrix_free_op.reinit (mesh.mapping, mesh.dof_handler, owned, mesh.flow_constraints);
    reinit_preconditioner (mesh, communicator);
  }
  // the reactions' weighted rows, applied matrix-free (block-0 positions)
  for (unsigned int b = 0; b < 3; ++b)
    reaction_weights[b].clear ();
  if (with_matrix)
    return;
  const auto                          &fe = mesh.dof_handler.get_fe ();
  std::vector<types::global_dof_index> dofs (fe.n_dofs_per_cell ());
  std::vector<bool>                    seen (owned[0].n_elements (), false);
  for (const auto &cell : mesh.dof_handler.active_cell_iterators ())
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
          if (mesh.boundary_velocity_dofs[b].is_element (dofs[i]))
          {
            if (mesh.up[c % dim] != 0)
              reaction_weights[b].emplace_back (position, mesh.up[c % dim]);
            break;
          }
      }
    }
}

template <int dim>
typename MatrixFreeSolvePath<dim>::Target
MatrixFreeSolvePath<dim>::begin_assembly (const FlowAssembler<dim> &assembler,
                                          const bool                coarse_matrix)
{
  TimerOutput::Scope scope (timer, "matrix-free coefficients");
  matrix_free_op.begin_update (assembler);
  Target target{with_matrix ? &op.system : nullptr, &op.schur, {&matrix_free_op}};
  begin_preconditioner_update (target, coarse_matrix);
  return target;
}

template <int dim>
void MatrixFreeSolvePath<dim>::end_assembly (
    BlockVector                     &rhs,
    const AffineConstraints<double> &flow_constraints,
    const Reassembly                &reassemble)
{
  {
    TimerOutput::Scope scope (timer, "matrix-free coefficients");
    end_preconditioner_update ();
    if (with_matrix)
      matrix_free_op.set_constrained_diagonal (op);
    else
      matrix_free_op.subtract_lifting (rhs, flow_constraints);
  }
  if (check)
    check_operator (rhs, flow_constraints, reassemble);
}

template <int dim>
void MatrixFreeSolvePath<dim>::check_operator (
    const BlockVector               &rhs,
    const AffineConstraints<double> &flow_constraints,
    const Reassembly                &reassemble)
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
  BlockVector lifted (owned, communicator);
  reassemble (Target{nullptr, &op.schur, {}}, lifted);
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
std::array<double, 3>
MatrixFreeSolvePath<dim>::uncaptured_reactions (const BlockVector &solution) const
{
  if (with_matrix)
    return {{0, 0, 0}};
  BlockVector owned_solution (owned, communicator);
  owned_solution = solution;
  return matrix_free_op.weighted_row_sums (owned_solution, reaction_weights);
}

template <int dim>
FlowSolveMemory MatrixFreeSolvePath<dim>::memory_consumption () const
{
  FlowSolveMemory memory;
  memory.op    = op.system.memory_consumption () + matrix_free_op.memory_consumption ();
  memory.schur = op.schur.memory_consumption ();
  return memory;
}

template <int dim>
MatrixFreeAmgSolvePath<dim>::MatrixFreeAmgSolvePath (
    const LinearSolverParameters &parameters,
    ConditionalOStream           &pcout,
    TimerOutput                  &timer)
    : MatrixFreeSolvePath<dim> (parameters, true, pcout, timer)
{
}

template <int dim>
void MatrixFreeAmgSolvePath<dim>::reinit_preconditioner (const Mesh &mesh,
                                                         MPI_Comm    communicator)
{
  preconditioner = fresh_block_amg<dim> (
      this->parameters, this->op, mesh, preconditioner, communicator);
}

template <int dim>
unsigned int MatrixFreeAmgSolvePath<dim>::solve (FlowLinearSolver  &linear_solver,
                                                 const BlockVector &rhs,
                                                 BlockVector       &solution,
                                                 const double       relative_target,
                                                 const double       dt,
                                                 SolveHistory      &history,
                                                 const std::function<void ()> &)
{
  return linear_solver.solve (
      this->matrix_free_op, *preconditioner, rhs, solution, relative_target, dt, history);
}

template <int dim>
unsigned int MatrixFreeAmgSolvePath<dim>::velocity_builds () const
{
  return preconditioner ? preconditioner->velocity_builds : 0;
}

template <int dim>
MatrixFreeMultigridSolvePath<dim>::MatrixFreeMultigridSolvePath (
    const LinearSolverParameters &parameters,
    ConditionalOStream           &pcout,
    TimerOutput                  &timer)
    : MatrixFreeSolvePath<dim> (parameters, parameters.check_operator, pcout, timer),
      multigrid (parameters)
{
}

template <int dim>
void MatrixFreeMultigridSolvePath<dim>::reinit_preconditioner (const Mesh &, MPI_Comm)
{
  // a new mesh needs new hierarchies; the build count goes on
  const unsigned int builds = multigrid.builds;
  multigrid.reinit (this->matrix_free_op);
  multigrid.builds = builds;
  preconditioner   = std::make_unique<MatrixFreeBlockPreconditioner<dim>> (
      this->parameters, this->matrix_free_op, this->op, multigrid);
}

template <int dim>
void MatrixFreeMultigridSolvePath<dim>::begin_preconditioner_update (
    Target &target, const bool coarse_matrix)
{
  // the coarse matrix only for a pass whose solve rebuilds the coarse AMG
  multigrid.begin_update (coarse_matrix);
  target.sinks.push_back (&multigrid);
}

template <int dim>
unsigned int MatrixFreeMultigridSolvePath<dim>::solve (
    FlowLinearSolver             &linear_solver,
    const BlockVector            &rhs,
    BlockVector                  &solution,
    const double                  relative_target,
    const double                  dt,
    SolveHistory                 &history,
    const std::function<void ()> &assemble_coarse_matrix)
{
  // a rebuild after a failed reused solve needs the coarse matrix of this
  // linearisation, which the assembly left out
  const auto with_coarse_matrix = [&] ()
  {
    if (!multigrid.coarse_matrix_current ())
      assemble_coarse_matrix ();
  };
  return linear_solver.solve (this->matrix_free_op,
                              *preconditioner,
                              rhs,
                              solution,
                              relative_target,
                              dt,
                              history,
                              with_coarse_matrix);
}

template <int dim>
FlowSolveMemory MatrixFreeMultigridSolvePath<dim>::memory_consumption () const
{
  FlowSolveMemory memory = MatrixFreeSolvePath<dim>::memory_consumption ();
  memory.multigrid       = multigrid.memory_consumption ();
  return memory;
}

// ---------------------------------------------------------------- factory

template <int dim>
std::unique_ptr<FlowSolvePath<dim>>
make_flow_solve_path (const LinearSolverParameters &parameters,
                      ConditionalOStream           &pcout,
                      TimerOutput                  &timer)
{
  if (!parameters.matrix_free)
    return std::make_unique<AssembledSolvePath<dim>> (parameters);
  if (!parameters.p_multigrid)
    return std::make_unique<MatrixFreeAmgSolvePath<dim>> (parameters, pcout, timer);
  return std::make_unique<MatrixFreeMultigridSolvePath<dim>> (parameters, pcout, timer);
}

template class FlowSolvePath<2>;
template class FlowSolvePath<3>;
template class AssembledSolvePath<2>;
template class AssembledSolvePath<3>;
template class MatrixFreeSolvePath<2>;
template class MatrixFreeSolvePath<3>;
template class MatrixFreeAmgSolvePath<2>;
template class MatrixFreeAmgSolvePath<3>;
template class MatrixFreeMultigridSolvePath<2>;
template class MatrixFreeMultigridSolvePath<3>;
template std::unique_ptr<FlowSolvePath<2>> make_flow_solve_path<2> (
    const LinearSolverParameters &, ConditionalOStream &, TimerOutput &);
template std::unique_ptr<FlowSolvePath<3>> make_flow_solve_path<3> (
    const LinearSolverParameters &, ConditionalOStream &, TimerOutput &);
} // namespace wetbed
