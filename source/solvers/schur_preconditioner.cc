#include <wetbed/solvers/schur_preconditioner.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

namespace wetbed
{
SchurPreconditioner::SchurPreconditioner (const bool exact) : exact (exact) {}

void SchurPreconditioner::build (const dealii::TrilinosWrappers::SparseMatrix &L)
{
  matrix.copy_from (L);
  dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic        = true;
  data.smoother_sweeps = 2;
  amg.initialize (matrix, data);
  ++builds;
  has_hierarchy = true;
}

void SchurPreconditioner::vmult (
    dealii::TrilinosWrappers::MPI::Vector        &dst,
    const dealii::TrilinosWrappers::MPI::Vector  &src,
    const dealii::TrilinosWrappers::SparseMatrix &current) const
{
  if (exact)
  {
    dealii::SolverControl              control (10000, 1e-10 * src.l2_norm () + 1e-300);
    dealii::TrilinosWrappers::SolverCG cg (control);
    dst = 0;
    cg.solve (current, dst, src, amg);
  }
  else
    amg.vmult (dst, src);
  dst *= -1.0;
}
} // namespace wetbed
