#include <wetbed/assembly/scalar_sparsity.h>
#include <wetbed/core/interruptible_solver_control.h>
#include <wetbed/solvers/granular_energy_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wetbed
{
using namespace dealii;

namespace
{
/** The budget summed over the ranks. */
GranularEnergyBudget sum_over_ranks (GranularEnergyBudget budget, MPI_Comm communicator)
{
  for (double *term : {&budget.production,
                       &budget.dissipation,
                       &budget.drag_exchange,
                       &budget.wall_flux})
    *term = Utilities::MPI::sum (*term, communicator);
  return budget;
}
} // namespace

template <int dim>
GranularEnergySolver<dim>::GranularEnergySolver (const Parameters &parameters,
                                                 MPI_Comm          communicator,
                                                 TimerOutput      &timer)
    : parameters (parameters), communicator (communicator), timer (timer),
      assembler (parameters, communicator)
{
}

template <int dim>
void GranularEnergySolver<dim>::reinit (
    const DoFHandler<dim>           &alpha_dof_handler,
    const AffineConstraints<double> &alpha_constraints)
{
  if (parameters.kinetic_theory.algebraic)
    return; // no matrix
  const IndexSet &alpha_owned = alpha_dof_handler.locally_owned_dofs ();
  matrix.reinit (alpha_owned,
                 alpha_owned,
                 distributed_scalar_sparsity (alpha_dof_handler, alpha_constraints),
                 communicator);
}

/**
 * The granular temperature Theta on the alpha_s space (Q1), after the alpha_s and u_s
 * corrections of an outer iteration.
 *
 * PDE (doc/theory.md, "Equations" and "Granular energy"), in advective form (the solids
 * continuity times 3/2 rho Theta subtracted):
 *   3/2 alpha rho (dTheta/dt + u_s.grad Theta) = div(kappa grad Theta)
 *       + 2 mu D:D + (lambda - 2/3 mu)(tr D)^2 - p_hat Theta div u_s
 *       - K_gamma Theta^(3/2) - 3 beta Theta,
 * mu = mu_col + mu_kin (the frictional viscosity does not heat the particles), p_hat =
 * P_kin+col/Theta. Production is explicit and non-negative (viscous heating and
 * compression p_hat Theta* (div u_s)_-) and scaled by min(1, alpha_s/alpha_dilute) (no
 * heating of the empty freeboard by the shear of a velocity that carries no particles),
 * the conductivity scaled the same way (Gidaspow's kappa stays finite as alpha_s -> 0:
 * unscaled, the empty freeboard is a pure Neumann Laplacian, singular, and its Theta is
 * whatever the Krylov solver leaves, measured at the cap), every sink implicit and
 * linearised at the latest Theta* (dissipation K_gamma
 * sqrt(Theta*) Theta, drag exchange 3 beta Theta, expansion p_hat (div u_s)_+ Theta,
 * Johnson-Jackson wall D_w), the mass lumped and the convection upwinded (discrete
 * upwinding on the Galerkin operator), so the matrix is an M-matrix on non-obtuse meshes;
 * BDF2 in time, Theta clamped to [minimum, maximum] (the cap acts in the dilute
 * freeboard, where viscous heating ~ alpha_s outruns collisional dissipation ~
 * alpha_s^2). Johnson- Jackson walls: kappa dTheta/dn = G_w - D_w with G_w = C_JJ
 * |u_slip|^2 explicit.
 *
 * Algebraic: the local equilibrium (doc/theory.md, "Granular energy"; production =
 * dissipation + drag exchange) at the Gauss points, lumped-L2 projected onto the nodes;
 * no matrix.
 */
template <int dim>
bool GranularEnergySolver<dim>::update (const GranularEnergyInputs<dim> &inputs,
                                        AlphaVector                     &theta,
                                        SolveHistory                    &history,
                                        std::string                     &rejection_reason)
{
  TimerOutput::Scope            scope (timer, "granular temperature");
  const bool                    algebraic = parameters.kinetic_theory.algebraic;
  TrilinosWrappers::MPI::Vector rhs (inputs.alpha_dof_handler.locally_owned_dofs (),
                                     communicator),
      solution (rhs);
  GranularEnergyBudget budget;
  if (algebraic)
    assembler.project_algebraic (inputs, theta, solution, budget);
  else
    assembler.assemble (inputs, theta, matrix, rhs, budget);
  last_budget = sum_over_ranks (budget, communicator);

  if (!algebraic &&
      !solve_granular_energy_system (theta, rhs, solution, history, rejection_reason))
    return false;
  return set_granular_temperature (
      solution, inputs.alpha_constraints, theta, rejection_reason);
}

template <int dim>
bool GranularEnergySolver<dim>::solve_granular_energy_system (
    const AlphaVector                   &theta,
    const TrilinosWrappers::MPI::Vector &rhs,
    TrilinosWrappers::MPI::Vector       &solution,
    SolveHistory                        &history,
    std::string                         &rejection_reason) const
{
  for (const auto i : solution.locally_owned_elements ())
    solution (i) = theta (i);
  InterruptibleSolverControl control (
      communicator,
      500,
      parameters.linear_solver.scalar_tolerance * rhs.l2_norm () + 1e-300);
  control.enable_history_data ();
  // right preconditioning: the tolerance applies to the true residual. Left (deal.II's
  // default) measures the AMG-preconditioned residual, ~dt/capacity smaller here: the
  // Theta solves stopped at a true residual ~1e-4 relative (measured: Theta at 2e-4 s
  // moved by 8e-5 between scalar tolerances 1e-13 and 1e-16).
  SolverGMRES<TrilinosWrappers::MPI::Vector> gmres (
      control, SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData (30, true));
  TrilinosWrappers::PreconditionILU amg;
  amg.initialize (matrix);
  try
  {
    gmres.solve (matrix, solution, rhs, amg);
    history.record ("granular temperature GMRES", control, true);
  }
  catch (const SolverControl::NoConvergence &failure)
  {
    history.record ("granular temperature GMRES", control, false);
    std::ostringstream reason;
    reason << "granular temperature GMRES did not converge: " << failure.last_step
           << " iterations, residual " << failure.last_residual / rhs.l2_norm ()
           << " of |rhs| (target " << parameters.linear_solver.scalar_tolerance << ")";
    rejection_reason = reason.str ();
    return false;
  }
  return true;
}

template <int dim>
bool GranularEnergySolver<dim>::set_granular_temperature (
    const TrilinosWrappers::MPI::Vector &solution,
    const AffineConstraints<double>     &alpha_constraints,
    AlphaVector                         &theta,
    std::string                         &rejection_reason) const
{
  const auto &kt     = parameters.kinetic_theory;
  bool        finite = true;
  for (unsigned int i = 0; i < theta.locally_owned_size (); ++i)
  {
    const double value = solution[theta.get_partitioner ()->local_to_global (i)];
    finite             = finite && std::isfinite (value);
    theta.local_element (i) =
        std::clamp (value, kt.minimum_temperature, kt.maximum_temperature);
  }
  if (Utilities::MPI::logical_or (!finite, communicator))
  {
    rejection_reason = "NaN in the granular temperature";
    return false;
  }
  theta.zero_out_ghost_values ();
  alpha_constraints.distribute (theta); // hanging nodes: from their parents
  theta.update_ghost_values ();
  return true;
}

template class GranularEnergySolver<2>;
template class GranularEnergySolver<3>;
} // namespace wetbed
