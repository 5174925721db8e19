#pragma once

#include <deal.II/lac/solver_control.h>

#include <string>
#include <vector>

namespace wetbed
{
/**
 * The residual history of the attempts at one time step: for each attempt its dt and
 * BDF order, every linear solve it made (which solve, in which outer iteration, the
 * iterations, the initial and final residual against the target, and for a solve that
 * failed its residual every few iterations, so that a stall can be told from a
 * divergence) and why the attempt was rejected. Cleared when a step begins; the failure
 * report prints it when the time step cannot be made small enough.
 */
class SolveHistory
{
public:
  void clear ();
  void begin_attempt (double dt, unsigned int bdf_order);
  void set_outer_iteration (unsigned int k);
  /** A finished or failed solve; `control` must have had enable_history_data(). */
  void        record (const std::string           &solver,
                      const dealii::SolverControl &control,
                      bool                         converged);
  void        reject (const std::string &reason);
  std::string describe () const;

private:
  struct Solve
  {
    std::string         solver;
    unsigned int        outer_iteration, iterations;
    double              target;
    bool                converged;
    std::vector<double> residuals; // one per iteration, the first the initial residual
  };
  struct Attempt
  {
    double             dt;
    unsigned int       bdf_order;
    std::vector<Solve> solves;
    std::string        rejection;
  };
  std::vector<Attempt> attempts;
  unsigned int         outer_iteration = 0;
};
} // namespace wetbed
