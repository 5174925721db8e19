#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/flow_operator.h>
#include <wetbed/solvers/solve_history.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>

#include <functional>
#include <limits>

namespace wetbed
{
/**
 * FGMRES on the monolithic (u_g, u_s, p') system with a flow preconditioner, and the
 * policy of when the preconditioner's expensive (velocity) part is rebuilt: after
 * `rebuild interval` solves, when dt changed by more than 20%, or when the solves got
 * slower than `rebuild growth` times those right after its build. Speed is measured in
 * iterations per decade of residual reduction, so solves to different targets (the
 * inexact solves of the outer iterations) compare. A solve with a reused velocity part
 * gets at most 3x the iterations the build's rate needs for its reduction (+10): if it
 * misses that, the part is rebuilt and the same solve is repeated, so reuse never costs
 * a rejected step.
 */
class FlowLinearSolver
{
public:
  using BlockVector = FlowOperator::BlockVector;

  FlowLinearSolver (const LinearSolverParameters &parameters,
                    dealii::ConditionalOStream   &pcout,
                    dealii::TimerOutput          &timer);

  /** Rebuild everything at the next solve (after a mesh change). */
  void reset () { solves_since_build = std::numeric_limits<unsigned int>::max () / 2; }

  /** Whether the next solve (at step dt) rebuilds the velocity part by the policy;
   * a reused solve that fails rebuilds it too, which no one can foresee. */
  bool rebuild_due (double dt) const;

  /** Solves A x = rhs to |rhs - A x| <= relative_target |rhs| with `op` as A and
   * `preconditioner` (updated from the operator it was made for: the same, or the
   * assembled matrix beside a matrix-free A); `solution` holds the
   * initial guess on entry (owned layout, constrained entries zero) and the solution on
   * exit (constraints not distributed). Returns the iterations, or invalid_unsigned_int
   * when the solve failed with a fresh preconditioner (the step is then rejected).
   * `before_unforeseen_rebuild` (if set) runs before the rebuild that follows a failed
   * reused solve, which rebuild_due() could not announce. */
  unsigned int solve (const FlowOperator           &op,
                      FlowPreconditioner           &preconditioner,
                      const BlockVector            &rhs,
                      BlockVector                  &solution,
                      double                        relative_target,
                      double                        dt,
                      SolveHistory                 &history,
                      const std::function<void ()> &before_unforeseen_rebuild = {});

private:
  const LinearSolverParameters &parameters;
  dealii::ConditionalOStream   &pcout;
  dealii::TimerOutput          &timer;
  // solves since the last velocity build, iterations right after it, its dt
  unsigned int solves_since_build = std::numeric_limits<unsigned int>::max () / 2;
  double       rate_after_build = 0; // iterations per decade of the first solve after it
  double       dt_at_build      = 1.0;
};
} // namespace wetbed
