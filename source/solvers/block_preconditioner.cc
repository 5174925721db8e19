#include <wetbed/solvers/block_preconditioner.h>

#include <Teuchos_ParameterList.hpp>

namespace wetbed
{
BlockPreconditioner::BlockPreconditioner (const LinearSolverParameters &parameters,
                                          const AssembledFlowOperator  &op)
    : parameters (parameters), op (op), exact (parameters.inner_solves == "exact"),
      exact_velocity (exact || parameters.inner_solves == "exact velocity"),
      schur_preconditioner (exact)
{
}

void BlockPreconditioner::set_near_null_space (std::vector<std::vector<double>> vectors,
                                               const unsigned int dofs_per_velocity_node)
{
  modes         = std::move (vectors);
  dofs_per_node = dofs_per_velocity_node;
}

void BlockPreconditioner::update (const bool rebuild_velocity)
{
  gradient = &op.gradient_block ();
  schur    = &op.schur_block ();
  if (rebuild_velocity)
    build_velocity (op.velocity_block (), modes, dofs_per_node);
  if (rebuild_velocity || !schur_preconditioner.built ())
  {
    schur_preconditioner.build (*schur);
    ++schur_builds;
  }
}

void BlockPreconditioner::build_velocity (
    const dealii::TrilinosWrappers::SparseMatrix &A,
    const std::vector<std::vector<double>>       &near_null_space,
    const unsigned int                            dofs_per_node)
{
  dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic              = true;
  data.higher_order_elements = true;
  data.smoother_sweeps       = parameters.smoother_sweeps;
  data.aggregation_threshold = parameters.aggregation_threshold;
  Teuchos::ParameterList              ml;
  std::unique_ptr<Epetra_MultiVector> unused;
  data.set_parameters (ml, unused, A.trilinos_matrix ());
  // the near-null space, pre-computed (the translations alone are what deal.II's
  // constant modes give; rigid rotations added where chosen)
  const Epetra_Map &rows = A.trilinos_matrix ().RowMap ();
  null_space = std::make_unique<Epetra_MultiVector> (rows, near_null_space.size ());
  for (unsigned int m = 0; m < near_null_space.size (); ++m)
    for (int i = 0; i < rows.NumMyElements (); ++i)
      (*null_space)[m][i] = near_null_space[m][i];
  // aggregate whole nodes (all velocity components of a support point together) and,
  // with the block Gauss-Seidel smoother, relax each node's block exactly: on a curved
  // wall the Nitsche penalty couples the Cartesian components of a node through n n^T,
  // which point smoothers cannot see (a tangential motion looks stiff to them)
  ml.set ("PDE equations", static_cast<int> (dofs_per_node));
  ml.set ("null space: type", "pre-computed");
  ml.set ("null space: dimension", null_space->NumVectors ());
  ml.set ("null space: vectors", null_space->Values ());
  if (parameters.smoother == "ILU")
    ml.set ("smoother: type", "ILU");
  else if (parameters.smoother == "block Gauss-Seidel")
    ml.set ("smoother: type", "symmetric block Gauss-Seidel");
  if (exact_velocity)
  {
    velocity_direct =
        std::make_unique<dealii::TrilinosWrappers::SolverDirect> (direct_control);
    velocity_direct->initialize (A);
  }
  else
    velocity_amg.initialize (A, ml);
  velocity_tmp.reinit (A.locally_owned_range_indices (), A.get_mpi_communicator ());
  ++velocity_builds;
}

void BlockPreconditioner::vmult (BlockVector &dst, const BlockVector &src) const
{
  // pressure: y_p = -L_c^{-1} r_p
  schur_preconditioner.vmult (dst.block (1), src.block (1), *schur);
  // velocity: y_u = A^{-1}(r_u - B^T y_p)
  gradient->vmult (velocity_tmp, dst.block (1));
  velocity_tmp.sadd (-1.0, src.block (0));
  if (exact_velocity)
    velocity_direct->solve (dst.block (0), velocity_tmp);
  else
    velocity_amg.vmult (dst.block (0), velocity_tmp);
}
} // namespace wetbed
