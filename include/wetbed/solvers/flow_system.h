#pragma once

#include <wetbed/assembly/flow/flow_assembler.h>
#include <wetbed/core/parameters.h>
#include <wetbed/mesh/boundaries.h>
#include <wetbed/solvers/flow_linear_solver.h>
#include <wetbed/solvers/flow_solve_path.h>
#include <wetbed/solvers/solve_history.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <memory>
#include <vector>

namespace wetbed
{
/**
 * The coupled (u_g, u_s, p') system of one outer iteration as a component: its terms
 * (FlowAssembler), the solve path (FlowSolvePath: the operator they assemble or give
 * coefficients to, and its preconditioner) and the FGMRES solver with its reuse policy.
 * It reads the state it is given and writes only itself and the solution it is asked to
 * solve for. Besides the solution it yields what belongs to it: the linearisation point
 * of its last assembly (alpha*, u*) and the consistent reactions of the inlet, the walls
 * and the outlet (the residuals of their velocity rows, doc/theory.md "Bed and bubble
 * analytics"), which the momentum budget of monitors.csv reads.
 */
template <int dim>
class FlowSystem
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  FlowSystem (const Parameters           &parameters,
              MPI_Comm                    communicator,
              dealii::ConditionalOStream &pcout,
              dealii::TimerOutput        &timer);

  /** For a new mesh (after the DoFs and constraints): the solve path's operator and a
   * fresh preconditioner (its build counts go on), the vectors, the boundary rows of
   * the reactions. */
  void reinit (const dealii::Mapping<dim>              &mapping,
               const dealii::DoFHandler<dim>           &flow_dof_handler,
               const std::vector<dealii::IndexSet>     &owned,
               const std::vector<dealii::IndexSet>     &relevant,
               const dealii::AffineConstraints<double> &flow_constraints,
               const dealii::AffineConstraints<double> &schur_constraints,
               const Boundaries                        &boundaries,
               const AlphaVector                       &alpha_layout);

  /** The terms of this case (add_flow_terms); replaces any earlier ones. */
  void set_assembler (std::unique_ptr<FlowAssembler<dim>> assembler);
  bool has_assembler () const { return static_cast<bool> (assembler); }

  /** The system linearised about `state` (its flow iterate and alpha_s), and that
   * linearisation point kept. The p-multigrid's coarse matrix is assembled when the
   * next solve rebuilds the coarse AMG, or with `with_coarse_matrix`. */
  void assemble (const FlowAssemblyState<dim>            &state,
                 const dealii::AffineConstraints<double> &flow_constraints,
                 const dealii::AffineConstraints<double> &schur_constraints,
                 bool                                     with_coarse_matrix = false);

  /** Solves the last assembled system from `solution` (ghosted: the lagged iterate
   * on entry, the new one with constraints distributed on exit); the iterations, or
   * invalid_unsigned_int when the solve failed with a fresh preconditioner (then
   * `solution` is unchanged). It stops at |b - A x| <= relative_target |b|. */
  unsigned int solve (BlockVector                             &solution,
                      const dealii::AffineConstraints<double> &flow_constraints,
                      double                                   relative_target,
                      double                                   dt,
                      SolveHistory                            &history);
  /** |b - A x| / |b| of the last assembled system at x = `solution` (ghosted, the
   * constraints of that assembly distributed): the outer iterations' convergence
   * measure (doc/theory.md "Outer iterations"); one operator product; collective. */
  double
  relative_residual (const BlockVector                       &solution,
                     const dealii::AffineConstraints<double> &flow_constraints) const;

  /** The vertical forces of the inlet, the walls and the outlet on the mixture (N, per
   * metre depth in 2D; in this order): the residuals of their velocity rows in the
   * unconstrained cell systems of the last assembly at `solution`; collective. */
  std::array<double, 3> boundary_reactions (const BlockVector &solution) const;

  /** The alpha_s and the flow iterate the last assembly linearised about. */
  const AlphaVector &linearisation_alpha () const { return assembled_alpha; }
  const BlockVector &linearisation_flow () const { return assembled_flow; }

  /** How often the velocity preconditioner's expensive part was built (the AMG on the
   * Q2 block, or the p-multigrid's coarse AMG and smoother). */
  unsigned int velocity_builds () const { return path->velocity_builds (); }
  using Memory = FlowSolveMemory;
  Memory memory_consumption () const;

  /** The operator FGMRES applies (`linear solver/operator`). */
  const FlowOperator &krylov_operator () const { return path->krylov_operator (); }
  /** The solve path (`linear solver/operator`, `velocity preconditioner`). */
  const FlowSolvePath<dim> &solve_path () const { return *path; }
  const FlowAssembler<dim> &flow_assembler () const { return *assembler; }

private:
  const Parameters                   &parameters;
  MPI_Comm                            communicator;
  dealii::TimerOutput                &timer;
  dealii::ConditionalOStream         &pcout;
  std::vector<dealii::IndexSet>       owned;
  dealii::Tensor<1, dim>              up;
  std::unique_ptr<FlowAssembler<dim>> assembler;
  std::unique_ptr<FlowSolvePath<dim>> path;
  BlockVector                         rhs;
  // work vectors of relative_residual (owned layout), kept across calls
  mutable BlockVector residual_iterate, residual;
  FlowLinearSolver    linear_solver;
  // the last assembly's arguments (for the coarse matrix that a rebuild after a
  // failed reused solve needs)
  struct
  {
    FlowAssemblyState<dim>                   state{};
    const dealii::AffineConstraints<double> *flow_constraints  = nullptr;
    const dealii::AffineConstraints<double> *schur_constraints = nullptr;
  } last_assembly;
  AlphaVector assembled_alpha;
  BlockVector assembled_flow;
  // the velocity DoFs of the inlet, the walls and the outlet, and the weighted
  // unconstrained rows of the cells that hold them in the last assembly
  std::array<dealii::IndexSet, 3> boundary_velocity_dofs;
  std::vector<BoundaryCellSystem> boundary_cell_systems;
};
} // namespace wetbed
