#include <wetbed/solvers/block_preconditioner.h>

#include <Teuchos_ParameterList.hpp>

namespace wetbed
{
BlockPreconditioner::BlockPreconditioner (const LinearSolverParameters &parameters)
    : parameters (parameters)
{
}

void BlockPreconditioner::build_velocity (
    const dealii::TrilinosWrappers::SparseMatrix &A,
    const std::vector<std::vector<bool>>         &constant_modes)
{
  dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic              = true;
  data.higher_order_elements = true;
  data.smoother_sweeps       = parameters.smoother_sweeps;
  data.aggregation_threshold = parameters.aggregation_threshold;
  data.constant_modes        = constant_modes;
  Teuchos::ParameterList              ml;
  std::unique_ptr<Epetra_MultiVector> null_space;
  data.set_parameters (ml, null_space, A.trilinos_matrix ());
  if (parameters.smoother == "ILU")
    ml.set ("smoother: type", "ILU");
  velocity_amg.initialize (A, ml);
  velocity_tmp.reinit (A.locally_owned_range_indices (), A.get_mpi_communicator ());
  ++velocity_builds;
}

void BlockPreconditioner::build_schur (const dealii::TrilinosWrappers::SparseMatrix &L)
{
  dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic        = true;
  data.smoother_sweeps = 2;
  schur_amg.initialize (L, data);
  ++schur_builds;
}

void BlockPreconditioner::vmult (BlockVector &dst, const BlockVector &src) const
{
  // pressure: y_p = -L_c^{-1} r_p
  schur_amg.vmult (dst.block (1), src.block (1));
  dst.block (1) *= -1.0;
  // velocity: y_u = A^{-1}(r_u - B^T y_p)
  gradient->vmult (velocity_tmp, dst.block (1));
  velocity_tmp.sadd (-1.0, src.block (0));
  velocity_amg.vmult (dst.block (0), velocity_tmp);
}
} // namespace wetbed
