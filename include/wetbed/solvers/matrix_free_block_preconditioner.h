#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/assembled_flow_operator.h>
#include <wetbed/solvers/matrix_free_flow_operator.h>
#include <wetbed/solvers/schur_preconditioner.h>
#include <wetbed/solvers/velocity_multigrid.h>

#include <deal.II/lac/trilinos_precondition.h>

namespace wetbed
{
/**
 * The block upper-triangular preconditioner of "Block preconditioner" (doc/theory.md)
 * for the matrix-free flow operator:
 *   y_p = -L_c^{-1} r_p,   y_u = MG(r_u - B^T y_p),
 * MG one V-cycle of the velocity p-multigrid (VelocityMultigrid), B^T applied
 * matrix-free, L_c^{-1} one smoothed-aggregation V-cycle on the assembled Q1 mobility
 * Laplacian. Constrained rows: y_i = r_i / diagonal_i.
 *
 * For diagnosis (`linear solver/inner solves`): `exact` solves L_c by CG to 1e-10 and
 * the velocity block by GMRES preconditioned with the V-cycle to 1e-10, `exact velocity`
 * only the velocity block; the inner GMRES iterations are then counted (report()).
 */
template <int dim>
class MatrixFreeBlockPreconditioner : public FlowPreconditioner
{
public:
  using LocalVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /** For the matrix-free operator `op`; `schur_source` holds L_c (assembled beside
   * it); `multigrid` is updated with each assembly (its coefficient sink). */
  MatrixFreeBlockPreconditioner (const LinearSolverParameters      &parameters,
                                 const MatrixFreeFlowOperator<dim> &op,
                                 const AssembledFlowOperator       &schur_source,
                                 VelocityMultigrid<dim>            &multigrid);

  /** The velocity multigrid's coarse AMG and smoother and the Schur hierarchy with
   * `rebuild_velocity` (the Schur one also when it has none yet); otherwise the last
   * ones are reused with the new node blocks. */
  void update (bool rebuild_velocity) override;
  void vmult (BlockVector &dst, const BlockVector &src) const override;
  /** With exact inner solves: the inner velocity GMRES iterations since the last
   * report (their mean per application), else empty. */
  std::string report () const override;

private:
  void solve_velocity (LocalVector &dst, const LocalVector &src) const;

  const bool                         exact_schur, exact_velocity;
  const AssembledFlowOperator       &schur_source;
  VelocityMultigrid<dim>            &multigrid;
  const MatrixFreeFlowOperator<dim> *op;
  SchurPreconditioner                schur_preconditioner;
  mutable LocalVector                gradient, rhs, solution;
  mutable unsigned int               inner_iterations = 0, inner_solves = 0;
};
} // namespace wetbed
