#include <wetbed/solvers/two_fluid_solver.h>

namespace wetbed
{
using namespace dealii;

/** The flow solve of one outer iteration from the lagged iterate (FlowLinearSolver);
 * the iterate becomes the solution, constraints distributed. */
template <int dim>
unsigned int TwoFluidSolver<dim>::solve_flow_system (const double current_dt)
{
  BlockVector solution (flow_owned, communicator);
  solution = flow_solution; // lagged iterate as the initial guess
  flow_constraints.set_zero (solution);
  const unsigned int iterations = flow_linear_solver.solve (
      flow_operator, *preconditioner, flow_rhs, solution, current_dt, solve_history);
  if (iterations == numbers::invalid_unsigned_int)
    return iterations;
  flow_constraints.distribute (solution);
  flow_solution = solution;
  return iterations;
}

template unsigned int TwoFluidSolver<2>::solve_flow_system (double);
template unsigned int TwoFluidSolver<3>::solve_flow_system (double);
} // namespace wetbed
