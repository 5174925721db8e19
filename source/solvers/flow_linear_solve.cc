#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_gmres.h>

namespace wetbed
{
using namespace dealii;

/**
 * FGMRES on the monolithic (u_g, u_s, p') system with the block preconditioner. The
 * Schur AMG is rebuilt every solve (it is cheap, Q1); the velocity AMG is reused
 * while the iteration count stays within `rebuild growth` of the count right after
 * its last build and for at most `rebuild interval` solves. Returns the iterations,
 * or invalid_unsigned_int when the solve failed (the step is then rejected).
 */
template <int dim>
unsigned int TwoFluidSolver<dim>::solve_flow_system (const double current_dt)
{
  const auto &ls = parameters.linear_solver;
  {
    TimerOutput::Scope scope (timer, "preconditioner setup");
    if (solves_since_build >= ls.rebuild_interval ||
        std::abs (current_dt / dt_at_build - 1.0) > 0.2)
    {
      ComponentMask velocities (2 * dim + 1, true);
      velocities.set (2 * dim, false);
      std::vector<std::vector<bool>> modes;
      DoFTools::extract_constant_modes (flow_dof_handler, velocities, modes);
      // the pressure entries are not part of block 0: keep the velocity rows
      std::vector<std::vector<bool>> velocity_modes (modes.size ());
      const unsigned int             n_velocity = flow_owned[0].n_elements ();
      for (unsigned int m = 0; m < modes.size (); ++m)
        velocity_modes[m].assign (modes[m].begin (), modes[m].begin () + n_velocity);
      preconditioner->build_velocity (flow_matrix.block (0, 0), velocity_modes);
      solves_since_build     = 0;
      iterations_after_build = 0;
      dt_at_build            = current_dt;
    }
    preconditioner->build_schur (schur_matrix.block (1, 1));
  }

  TimerOutput::Scope scope (timer, "Krylov solve");
  BlockVector        solution (flow_owned, communicator);
  solution = flow_solution; // lagged iterate as the initial guess
  flow_constraints.set_zero (solution);
  const double              target = ls.relative_tolerance * flow_rhs.l2_norm ();
  SolverControl             control (ls.maximum_iterations, std::max (target, 1e-300));
  SolverFGMRES<BlockVector> fgmres (
      control, typename SolverFGMRES<BlockVector>::AdditionalData (ls.restart));
  try
  {
    fgmres.solve (flow_matrix, solution, flow_rhs, *preconditioner);
  }
  catch (const SolverControl::NoConvergence &)
  {
    solves_since_build = ls.rebuild_interval;
    pcout << "  FGMRES did not converge in " << control.last_step ()
          << " iterations (residual " << control.last_value () << ", target " << target
          << ")" << std::endl;
    return numbers::invalid_unsigned_int;
  }
  const unsigned int iterations = control.last_step ();
  if (ls.verbose)
    pcout << "    FGMRES " << iterations << " iterations" << std::endl;
  flow_constraints.distribute (solution);
  flow_solution = solution;

  ++solves_since_build;
  if (iterations_after_build == 0)
    iterations_after_build = std::max (1u, iterations);
  else if (iterations > ls.rebuild_growth * iterations_after_build)
    solves_since_build = ls.rebuild_interval;
  return iterations;
}

template unsigned int TwoFluidSolver<2>::solve_flow_system (double);
template unsigned int TwoFluidSolver<3>::solve_flow_system (double);
} // namespace wetbed
