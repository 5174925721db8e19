#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <string>

namespace wetbed
{
/**
 * The linearised flow system (u_g, u_s, p') as the Krylov solver sees it: an operator
 * that can be applied. Implementations: the assembled matrix (AssembledFlowOperator)
 * and the matrix-free operator (MatrixFreeFlowOperator, the default). A solve path
 * (FlowSolvePath) pairs one with the preconditioner made for it, which holds that
 * operator by its own type.
 */
class FlowOperator
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

  virtual ~FlowOperator ()          = default;
  virtual std::string name () const = 0;
  /** dst = A src. */
  virtual void vmult (BlockVector &dst, const BlockVector &src) const = 0;
  /** Inner-solve statistics since the last call (diagnostic modes), else empty. */
  virtual std::string report () const { return {}; }
};

/** A preconditioner of the flow system, updated before a solve from the operator it
 * was made for (given to it on construction). */
class FlowPreconditioner
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

  virtual ~FlowPreconditioner () = default;
  /** Rebuilds from the operator's current state: the cheap parts always, the velocity
   * part only with `rebuild_velocity` (otherwise the last one is reused). */
  virtual void update (bool rebuild_velocity)                         = 0;
  virtual void vmult (BlockVector &dst, const BlockVector &src) const = 0;
  /** Inner-solve statistics since the last call (diagnostic modes), else empty. */
  virtual std::string report () const { return {}; }
};
} // namespace wetbed
