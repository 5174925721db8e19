#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/assembled_flow_operator.h>
#include <wetbed/solvers/schur_preconditioner.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_MultiVector.h>

#include <memory>
#include <vector>

namespace wetbed
{
/**
 * Block upper-triangular preconditioner for [[A, B^T], [B, 0]] (doc/theory.md,
 * "Block preconditioner"):
 *   y_p = -L_c^{-1} r_p,   y_u = A^{-1} (r_u - B^T y_p),
 * A^{-1}: one ML V-cycle on both velocities (2 dim constant modes), L_c^{-1}: one
 * smoothed-aggregation V-cycle on the partial-elimination mobility Laplacian. With
 * `inner solves = exact`, A^{-1} is a sparse direct solve and L_c^{-1} a CG solve to
 * 1e-10 (diagnosis: the FGMRES count is then that of the Schur approximation alone).
 * With `inner solves = exact velocity` only the velocity solve is direct.
 */
class BlockPreconditioner : public FlowPreconditioner
{
public:
  /** For the assembled operator `op` (its velocity, gradient and L_c blocks). */
  BlockPreconditioner (const LinearSolverParameters &parameters,
                       const AssembledFlowOperator  &op);

  /** The near-null space of the velocity block on this mesh (see build_velocity). */
  void set_near_null_space (std::vector<std::vector<double>> modes,
                            unsigned int                     dofs_per_node);
  /** The velocity and Schur hierarchies from the operator's current matrices with
   * `rebuild_velocity` (the Schur one also when it has none yet); otherwise the last
   * ones are reused. */
  void update (bool rebuild_velocity) override;

  /** Builds (or rebuilds) the velocity hierarchy from the current A with the given
   * near-null space: one vector per mode, each with the locally owned velocity rows in
   * order (translations of each velocity component, and rigid rotations if chosen).
   * dofs_per_node: the velocity DoFs of one support point, consecutive rows (ML's
   * "PDE equations": node aggregation and node-block smoothing), or 1. */
  void build_velocity (const dealii::TrilinosWrappers::SparseMatrix &velocity_matrix,
                       const std::vector<std::vector<double>>       &near_null_space,
                       unsigned int                                  dofs_per_node);

  void vmult (BlockVector &dst, const BlockVector &src) const override;

  unsigned int velocity_builds = 0, schur_builds = 0;

private:
  const LinearSolverParameters                 &parameters;
  const AssembledFlowOperator                  &op;
  dealii::TrilinosWrappers::PreconditionAMG     velocity_amg;
  const dealii::TrilinosWrappers::SparseMatrix *gradient = nullptr;
  const dealii::TrilinosWrappers::SparseMatrix *schur    = nullptr;
  bool                                          exact    = false;
  bool exact_velocity = false; // `inner solves = exact velocity`: direct velocity only
  mutable dealii::SolverControl                                   direct_control;
  mutable std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> velocity_direct;
  mutable dealii::TrilinosWrappers::MPI::Vector                   velocity_tmp;
  std::unique_ptr<Epetra_MultiVector> null_space; // ML keeps a pointer to its values
  std::vector<std::vector<double>>    modes;
  SchurPreconditioner                 schur_preconditioner;
  unsigned int                        dofs_per_node = 1;
};
} // namespace wetbed
