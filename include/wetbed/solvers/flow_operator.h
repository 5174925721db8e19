#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <string>

namespace wetbed
{
/**
 * The linearised flow system (u_g, u_s, p') as the Krylov solver sees it: an operator
 * that can be applied. Implementations: the assembled matrix (AssembledFlowOperator);
 * a matrix-free operator plugs in here. Preconditioners (FlowPreconditioner) take
 * what they need from the implementation they are made for.
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

/** A preconditioner of the flow system, updated from the operator before a solve. */
class FlowPreconditioner
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

  virtual ~FlowPreconditioner () = default;
  /** Rebuilds from the current operator: the cheap parts always, the velocity part
   * only with `rebuild_velocity` (otherwise the last one is reused). */
  virtual void update (const FlowOperator &op, bool rebuild_velocity) = 0;
  virtual void vmult (BlockVector &dst, const BlockVector &src) const = 0;
  /** Inner-solve statistics since the last call (diagnostic modes), else empty. */
  virtual std::string report () const { return {}; }
};
} // namespace wetbed
