#include <wetbed/solvers/matrix_free_block_preconditioner.h>

namespace wetbed
{
template <int dim>
MatrixFreeBlockPreconditioner<dim>::MatrixFreeBlockPreconditioner (
    const AssembledFlowOperator &schur_source, VelocityMultigrid<dim> &multigrid)
    : schur_source (schur_source), multigrid (multigrid)
{
}

template <int dim>
void MatrixFreeBlockPreconditioner<dim>::update (const FlowOperator &flow_operator,
                                                 const bool          rebuild_velocity)
{
  op = dynamic_cast<const MatrixFreeFlowOperator<dim> *> (&flow_operator);
  if (op == nullptr)
    throw std::logic_error ("the p-multigrid preconditioner needs the matrix-free flow "
                            "operator, not '" +
                            flow_operator.name () + "'");
  if (gradient.size () != op->velocity_dofs ().n_dofs ())
  {
    op->initialize_velocity_vector (gradient);
    op->initialize_velocity_vector (rhs);
    op->initialize_velocity_vector (solution);
  }
  if (rebuild_velocity)
    multigrid.rebuild ();
  dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic        = true;
  data.smoother_sweeps = 2;
  schur_amg.initialize (schur_source.schur_block (), data);
}

template <int dim>
void MatrixFreeBlockPreconditioner<dim>::vmult (BlockVector       &dst,
                                                const BlockVector &src) const
{
  // pressure: y_p = -L_c^{-1} r_p
  schur_amg.vmult (dst.block (1), src.block (1));
  dst.block (1) *= -1.0;
  // velocity: y_u = MG(r_u - B^T y_p), the constrained rows zero inside
  op->vmult_gradient (gradient, dst.block (1));
  op->to_velocity (rhs, src.block (0));
  rhs -= gradient;
  op->zero_constrained_velocity (rhs);
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

template class MatrixFreeBlockPreconditioner<2>;
template class MatrixFreeBlockPreconditioner<3>;
} // namespace wetbed
