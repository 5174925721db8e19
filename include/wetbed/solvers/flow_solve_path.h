#pragma once

#include <wetbed/assembly/flow/flow_assembler.h>
#include <wetbed/core/parameters.h>
#include <wetbed/solvers/assembled_flow_operator.h>
#include <wetbed/solvers/block_preconditioner.h>
#include <wetbed/solvers/flow_linear_solver.h>
#include <wetbed/solvers/matrix_free_block_preconditioner.h>
#include <wetbed/solvers/matrix_free_flow_operator.h>
#include <wetbed/solvers/solve_history.h>
#include <wetbed/solvers/velocity_multigrid.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/fe/mapping.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace wetbed
{
/** Bytes one rank holds for the flow solve, by part (ML's hierarchies are not counted:
 * Trilinos does not report them). */
struct FlowSolveMemory
{
  std::size_t op        = 0; // the system matrix, or the matrix-free data
  std::size_t schur     = 0; // L_c
  std::size_t multigrid = 0; // the p-multigrid's Q1 space, matrix, transfer, blocks
  std::size_t vectors   = 0; // rhs, linearisation point
};

/**
 * How the coupled flow system is applied and preconditioned (`linear solver/operator`
 * and `velocity preconditioner`): the operator FGMRES applies, the preconditioner made
 * for it, and where the assembly pass writes (FlowAssembler::Target). FlowSystem holds
 * one, made by make_flow_solve_path() from the parameters, and never asks which.
 *
 * A path's day: reinit() on a new mesh; per outer iteration begin_assembly() (the
 * target of the pass), the assembly, end_assembly() (the operator completed from it);
 * then solve().
 */
template <int dim>
class FlowSolvePath
{
public:
  using BlockVector = FlowOperator::BlockVector;
  using Target      = typename FlowAssembler<dim>::Target;
  /** The assembly pass again into another target and rhs, at the same linearisation
   * point (the operator check compares what two targets give). */
  using Reassembly = std::function<void (const Target &, BlockVector &)>;

  /** What a new mesh gives the path. */
  struct Mesh
  {
    const dealii::Mapping<dim>              &mapping;
    const dealii::DoFHandler<dim>           &dof_handler;
    const std::vector<dealii::IndexSet>     &owned, &relevant;
    const dealii::AffineConstraints<double> &flow_constraints, &schur_constraints;
    // the velocity DoFs of the inlet, the walls and the outlet, and the upward direction:
    // the rows of the boundary reactions
    const std::array<dealii::IndexSet, 3> &boundary_velocity_dofs;
    dealii::Tensor<1, dim>                 up;
  };

  virtual ~FlowSolvePath ()         = default;
  virtual std::string name () const = 0;

  /** For a new mesh: the sparsity of what it assembles, the operator's data, a fresh
   * preconditioner (its build counts go on). */
  virtual void reinit (const Mesh &mesh, MPI_Comm communicator) = 0;
  /** Whether the assembly writes the system matrix (the boundary rows are then captured
   * whole; otherwise only their rhs part, the rest is uncaptured_reactions()). */
  virtual bool assembles_matrix () const = 0;
  /** The target of the next assembly pass of `assembler`; `coarse_matrix`: the pass
   * also gives the coarse matrix that a rebuild of the velocity preconditioner needs. */
  virtual Target begin_assembly (const FlowAssembler<dim> &assembler,
                                 bool                      coarse_matrix) = 0;
  /** After the pass: the operator completed from it (the diagonal of its constrained
   * rows, or the lifting of the inhomogeneous constraints into `rhs`), and the
   * operator check if asked for (`linear solver/check operator`). */
  virtual void end_assembly (BlockVector                             &rhs,
                             const dealii::AffineConstraints<double> &flow_constraints,
                             const Reassembly                        &reassemble) = 0;

  /** The operator FGMRES applies. */
  virtual const FlowOperator &krylov_operator () const = 0;
  /** FlowLinearSolver::solve with this path's operator and preconditioner;
   * `assemble_coarse_matrix` runs the assembly once more with the coarse matrix when a
   * failed reused solve rebuilds a preconditioner that needs it. */
  virtual unsigned int solve (FlowLinearSolver             &linear_solver,
                              const BlockVector            &rhs,
                              BlockVector                  &solution,
                              double                        relative_target,
                              double                        dt,
                              SolveHistory                 &history,
                              const std::function<void ()> &assemble_coarse_matrix) = 0;
  /** How often the velocity preconditioner's expensive part was built (the AMG on the
   * Q2 block, or the p-multigrid's coarse AMG and smoother). */
  virtual unsigned int velocity_builds () const = 0;

  /** The part of the inlet's, the walls' and the outlet's reactions at `solution`
   * (ghosted, constraints distributed) that the assembly did not capture: the matrix
   * part of their rows when it wrote no matrix; this rank's share. */
  virtual std::array<double, 3> uncaptured_reactions (const BlockVector &solution) const;
  /** The operator's and preconditioner's bytes on this rank (not the vectors). */
  virtual FlowSolveMemory memory_consumption () const = 0;
};

/** The path the parameters name: `assembled` (matrix and block AMG), `matrix-free` with
 * the block AMG on the assembled velocity block, or `matrix-free` with the velocity
 * p-multigrid (the default). */
template <int dim>
std::unique_ptr<FlowSolvePath<dim>>
make_flow_solve_path (const LinearSolverParameters &parameters,
                      dealii::ConditionalOStream   &pcout,
                      dealii::TimerOutput          &timer);

/** The assembled operator [[A, B^T], [B, 0]] with L_c, preconditioned by the block AMG
 * (BlockPreconditioner): the reference path. */
template <int dim>
class AssembledSolvePath : public FlowSolvePath<dim>
{
public:
  using typename FlowSolvePath<dim>::BlockVector;
  using typename FlowSolvePath<dim>::Target;
  using typename FlowSolvePath<dim>::Mesh;
  using typename FlowSolvePath<dim>::Reassembly;

  explicit AssembledSolvePath (const LinearSolverParameters &parameters);
  std::string name () const override { return "assembled, block AMG"; }
  void        reinit (const Mesh &mesh, MPI_Comm communicator) override;
  bool        assembles_matrix () const override { return true; }
  Target      begin_assembly (const FlowAssembler<dim> &, bool) override;
  void        end_assembly (BlockVector &,
                            const dealii::AffineConstraints<double> &,
                            const Reassembly &) override
  {
  }
  const FlowOperator &krylov_operator () const override { return op; }
  unsigned int        solve (FlowLinearSolver             &linear_solver,
                             const BlockVector            &rhs,
                             BlockVector                  &solution,
                             double                        relative_target,
                             double                        dt,
                             SolveHistory                 &history,
                             const std::function<void ()> &assemble_coarse_matrix) override;
  unsigned int        velocity_builds () const override;
  FlowSolveMemory     memory_consumption () const override;

private:
  const LinearSolverParameters        &parameters;
  AssembledFlowOperator                op;
  std::unique_ptr<BlockPreconditioner> preconditioner;
};

/** What both matrix-free paths share: the matrix-free operator (its coefficients a sink
 * of the assembly), L_c assembled beside it, the system matrix too where the
 * preconditioner or the operator check needs it, and the boundary reactions' rows
 * applied matrix-free where it does not. */
template <int dim>
class MatrixFreeSolvePath : public FlowSolvePath<dim>
{
public:
  using typename FlowSolvePath<dim>::BlockVector;
  using typename FlowSolvePath<dim>::Target;
  using typename FlowSolvePath<dim>::Mesh;
  using typename FlowSolvePath<dim>::Reassembly;

  void                  reinit (const Mesh &mesh, MPI_Comm communicator) override;
  bool                  assembles_matrix () const override { return with_matrix; }
  Target                begin_assembly (const FlowAssembler<dim> &assembler,
                                        bool                      coarse_matrix) override;
  void                  end_assembly (BlockVector                             &rhs,
                                      const dealii::AffineConstraints<double> &flow_constraints,
                                      const Reassembly                        &reassemble) override;
  const FlowOperator   &krylov_operator () const override { return matrix_free_op; }
  std::array<double, 3> uncaptured_reactions (const BlockVector &solution) const override;
  FlowSolveMemory       memory_consumption () const override;

protected:
  /** `with_matrix`: the assembly writes the system matrix too; `check`: the operator
   * check after each assembly (which needs the matrix). */
  MatrixFreeSolvePath (const LinearSolverParameters &parameters,
                       bool                          with_matrix,
                       dealii::ConditionalOStream   &pcout,
                       dealii::TimerOutput          &timer);
  /** The preconditioner's part of reinit (inside the matrix-free setup's timer). */
  virtual void reinit_preconditioner (const Mesh &mesh, MPI_Comm communicator) = 0;
  /** The preconditioner's sinks of the coming assembly pass, and after it. */
  virtual void begin_preconditioner_update (Target &, bool /*coarse_matrix*/) {}
  virtual void end_preconditioner_update () {}

  const LinearSolverParameters &parameters;
  AssembledFlowOperator         op; // L_c, and the system where assembled
  MatrixFreeFlowOperator<dim>   matrix_free_op;

private:
  /** Prints how far A_mf x is from A x, and the matrix-free lifting of the constraints
   * from the rhs the local matrices carried them into. */
  void check_operator (const BlockVector                       &rhs,
                       const dealii::AffineConstraints<double> &flow_constraints,
                       const Reassembly                        &reassemble);

  const bool                    with_matrix, check;
  dealii::ConditionalOStream   &pcout;
  dealii::TimerOutput          &timer;
  std::vector<dealii::IndexSet> owned;
  MPI_Comm                      communicator = MPI_COMM_NULL;
  // without the matrix: each boundary's owned velocity rows (block-0 position) and
  // upward weights, applied matrix-free
  std::array<std::vector<std::pair<unsigned int, double>>, 3> reaction_weights;
};

/** Matrix-free operator, block AMG on the assembled velocity block. */
template <int dim>
class MatrixFreeAmgSolvePath : public MatrixFreeSolvePath<dim>
{
public:
  using typename FlowSolvePath<dim>::BlockVector;
  using typename FlowSolvePath<dim>::Mesh;

  MatrixFreeAmgSolvePath (const LinearSolverParameters &parameters,
                          dealii::ConditionalOStream   &pcout,
                          dealii::TimerOutput          &timer);
  std::string  name () const override { return "matrix-free, block AMG"; }
  unsigned int solve (FlowLinearSolver             &linear_solver,
                      const BlockVector            &rhs,
                      BlockVector                  &solution,
                      double                        relative_target,
                      double                        dt,
                      SolveHistory                 &history,
                      const std::function<void ()> &assemble_coarse_matrix) override;
  unsigned int velocity_builds () const override;

private:
  void reinit_preconditioner (const Mesh &mesh, MPI_Comm communicator) override;
  std::unique_ptr<BlockPreconditioner> preconditioner;
};

/** Matrix-free operator, velocity p-multigrid (the default). */
template <int dim>
class MatrixFreeMultigridSolvePath : public MatrixFreeSolvePath<dim>
{
public:
  using typename FlowSolvePath<dim>::BlockVector;
  using typename FlowSolvePath<dim>::Target;
  using typename FlowSolvePath<dim>::Mesh;

  MatrixFreeMultigridSolvePath (const LinearSolverParameters &parameters,
                                dealii::ConditionalOStream   &pcout,
                                dealii::TimerOutput          &timer);
  std::string     name () const override { return "matrix-free, p-multigrid"; }
  unsigned int    solve (FlowLinearSolver             &linear_solver,
                         const BlockVector            &rhs,
                         BlockVector                  &solution,
                         double                        relative_target,
                         double                        dt,
                         SolveHistory                 &history,
                         const std::function<void ()> &assemble_coarse_matrix) override;
  unsigned int    velocity_builds () const override { return multigrid.builds; }
  FlowSolveMemory memory_consumption () const override;

private:
  void reinit_preconditioner (const Mesh &mesh, MPI_Comm communicator) override;
  void begin_preconditioner_update (Target &target, bool coarse_matrix) override;
  void end_preconditioner_update () override { multigrid.end_update (); }

  VelocityMultigrid<dim>                              multigrid;
  std::unique_ptr<MatrixFreeBlockPreconditioner<dim>> preconditioner;
};
} // namespace wetbed
