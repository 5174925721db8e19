#include <wetbed/solvers/matrix_free_block_preconditioner.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_solver.h>

#include <sstream>

namespace wetbed
{
template <int dim>
MatrixFreeBlockPreconditioner<dim>::MatrixFreeBlockPreconditioner (
    const LinearSolverParameters      &parameters,
    const MatrixFreeFlowOperator<dim> &op,
    const AssembledFlowOperator       &schur_source,
    VelocityMultigrid<dim>            &multigrid)
    : exact_schur (parameters.inner_solves == "exact"),
      exact_velocity (exact_schur || parameters.inner_solves == "exact velocity"),
      schur_source (schur_source), multigrid (multigrid), op (&op),
      schur_preconditioner (exact_schur)
{
}

template <int dim>
void MatrixFreeBlockPreconditioner<dim>::update (const bool rebuild_velocity)
{
  if (gradient.size () != op->velocity_dofs ().n_dofs ())
  {
    op->initialize_velocity_vector (gradient);
    op->initialize_velocity_vector (rhs);
    op->initialize_velocity_vector (solution);
  }
  if (rebuild_velocity)
    multigrid.rebuild ();
  if (rebuild_velocity || !schur_preconditioner.built ())
    schur_preconditioner.build (schur_source.schur_block ());
}

template <int dim>
void MatrixFreeBlockPreconditioner<dim>::vmult (BlockVector       &dst,
                                                const BlockVector &src) const
{
  // pressure: y_p = -L_c^{-1} r_p
  schur_preconditioner.vmult (dst.block (1), src.block (1), schur_source.schur_block ());
  // velocity: y_u = MG(r_u - B^T y_p), the constrained rows zero inside
  op->vmult_gradient (gradient, dst.block (1));
  op->to_velocity (rhs, src.block (0));
  rhs -= gradient;
  op->zero_constrained_velocity (rhs);
  if (exact_velocity)
    solve_velocity (solution, rhs);
  else
    multigrid.vmult (solution, rhs);
  const auto &rows = op->constrained_rows (0);
  op->from_velocity (dst.block (0), solution);
  const auto &diagonal = op->constrained_row_diagonal (0);
  for (unsigned int i = 0; i < rows.size (); ++i)
    dst.block (0).begin ()[rows[i]] = src.block (0).begin ()[rows[i]] / diagonal[i];
  // the pressure's constrained rows likewise
  const auto &p_rows     = op->constrained_rows (1);
  const auto &p_diagonal = op->constrained_row_diagonal (1);
  for (unsigned int i = 0; i < p_rows.size (); ++i)
    dst.block (1).begin ()[p_rows[i]] = src.block (1).begin ()[p_rows[i]] / p_diagonal[i];
}

template <int dim>
void MatrixFreeBlockPreconditioner<dim>::solve_velocity (LocalVector       &dst,
                                                         const LocalVector &src) const
{
  struct Block
  {
    const MatrixFreeFlowOperator<dim> *op;
    void vmult (LocalVector &y, const LocalVector &x) const { op->vmult_velocity (y, x); }
  } block{op};
  dealii::SolverControl            control (10000, 1e-10 * src.l2_norm () + 1e-300);
  dealii::SolverGMRES<LocalVector> gmres (
      control, typename dealii::SolverGMRES<LocalVector>::AdditionalData (200, true));
  dst = 0;
  gmres.solve (block, dst, src, multigrid);
  inner_iterations += control.last_step ();
  ++inner_solves;
}

template <int dim>
std::string MatrixFreeBlockPreconditioner<dim>::report () const
{
  std::ostringstream text;
  if (inner_solves > 0)
    text << "velocity GMRES (V-cycle preconditioned, to 1e-10): " << inner_iterations
         << " iterations in " << inner_solves << " solves ("
         << static_cast<double> (inner_iterations) / inner_solves << " per solve)";
  if (multigrid.coarse_solves > 0)
    text << "coarse Q1 GMRES (ML preconditioned, to 1e-10): "
         << static_cast<double> (multigrid.coarse_iterations) / multigrid.coarse_solves
         << " iterations per V-cycle";
  inner_iterations = inner_solves = 0;
  multigrid.coarse_iterations = multigrid.coarse_solves = 0;
  return text.str ();
}

template class MatrixFreeBlockPreconditioner<2>;
template class MatrixFreeBlockPreconditioner<3>;
} // namespace wetbed
