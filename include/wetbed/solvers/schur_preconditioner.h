#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace wetbed
{
/**
 * The pressure part of the block preconditioners (doc/theory.md, "Block
 * preconditioner"): y_p = -L_c^{-1} r_p with one smoothed-aggregation V-cycle on the
 * partial-elimination mobility Laplacian L_c, or (`inner solves = exact`) a CG solve to
 * 1e-10 preconditioned by it.
 *
 * The hierarchy is built on a copy of L_c and kept until the next build: the flow
 * assembly overwrites L_c in place, and a hierarchy that is reused over later
 * assemblies (the block preconditioners rebuild it with the velocity hierarchy, by
 * FlowLinearSolver's reuse policy) must keep seeing the matrix it was made from — ML
 * reads its finest level from the matrix at every application.
 */
class SchurPreconditioner
{
public:
  explicit SchurPreconditioner (bool exact);

  /** The hierarchy of (a copy of) `schur_matrix`. */
  void build (const dealii::TrilinosWrappers::SparseMatrix &schur_matrix);
  bool built () const { return has_hierarchy; }

  /** dst = -L_c^{-1} src; `current` is the latest L_c (the exact solve's matrix). */
  void vmult (dealii::TrilinosWrappers::MPI::Vector        &dst,
              const dealii::TrilinosWrappers::MPI::Vector  &src,
              const dealii::TrilinosWrappers::SparseMatrix &current) const;

  unsigned int builds = 0;

private:
  const bool                                exact;
  bool                                      has_hierarchy = false;
  dealii::TrilinosWrappers::SparseMatrix    matrix;
  dealii::TrilinosWrappers::PreconditionAMG amg;
};
} // namespace wetbed
