#include <wetbed/closures/kinetic_theory/collisional_terms.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/solver_gmres.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <sstream>

#include <limits>

namespace wetbed
{
using namespace dealii;

namespace
{
/** 2 mu D:D + (lambda - 2/3 mu)(tr D)^2: the viscous heating of the strain rate D. */
double viscous_heating (const closures::KineticTheory::Coefficients &c,
                        const double                                 trace_d,
                        const double                                 d_ddot_d)
{
  return 2 * c.shear_viscosity * d_ddot_d +
         (c.bulk_viscosity - 2.0 / 3 * c.shear_viscosity) * trace_d * trace_d;
}

/** The dissipation and drag exchange at the temperature `theta` of one Gauss point. */
void add_sinks_to_budget (GranularEnergyBudget                        &budget,
                          const closures::KineticTheory::Coefficients &c,
                          const double                                 theta,
                          const double                                 beta,
                          const double                                 JxW)
{
  budget.dissipation += c.dissipation_factor * std::pow (theta, 1.5) * JxW;
  budget.drag_exchange += 3 * beta * theta * JxW;
}

/**
 * Discrete upwinding of a cell's convection-diffusion matrix, weighted by `upwinding`
 * (min(1, Pe_h)): d_ij = upwinding max(0, a_ij, a_ji) off the diagonal moved onto it.
 */
void upwind_cell_matrix (FullMatrix<double> &cell_matrix, const double upwinding)
{
  const unsigned int n = cell_matrix.m ();
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      if (i != j)
      {
        const double d =
            upwinding * std::max ({0.0, cell_matrix (i, j), cell_matrix (j, i)});
        if (d > 0 && j > i)
        {
          cell_matrix (i, j) -= d;
          cell_matrix (j, i) -= d;
          cell_matrix (i, i) += d;
          cell_matrix (j, j) += d;
        }
      }
}

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

/**
 * The FEValues of the Theta assembly on the alpha_s space and the flow space, the fields
 * at the Gauss points of the current cell, its local system, and what the assembly needs
 * of the case.
 */
template <int dim>
struct TwoFluidSolver<dim>::GranularEnergyScratch
{
  using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

  explicit GranularEnergyScratch (const TwoFluidSolver<dim> &solver)
      : quadrature (2), face_quadrature (2),
        theta_values (solver.mapping,
                      solver.alpha_fe,
                      quadrature,
                      update_values | update_gradients | update_quadrature_points |
                          update_JxW_values),
        flow_values (
            solver.mapping, solver.flow_fe, quadrature, update_values | update_gradients),
        theta_face (solver.mapping,
                    solver.alpha_fe,
                    face_quadrature,
                    update_values | update_quadrature_points | update_JxW_values),
        flow_face (solver.mapping,
                   solver.flow_fe,
                   face_quadrature,
                   update_values | update_normal_vectors),
        n (solver.alpha_fe.n_dofs_per_cell ()), n_q (quadrature.size ()),
        cell_matrix (n, n), cell_rhs (n), cell_mass (n), dofs (n), a (n_q), t_now (n_q),
        t_old (n_q), t_old2 (n_q), ug (n_q), us (n_q), grad_us (n_q),
        a_face (face_quadrature.size ()), t_face (face_quadrature.size ()),
        us_face (face_quadrature.size ()), gas (0), solids (dim),
        wall_velocity (solver.moving_wall_velocity ()),
        manufactured_theta (solver.manufactured &&
                            solver.manufactured->has_granular_temperature ())
  {
  }

  /** The fields at the Gauss points of `cell` (and `flow_cell`, the same cell of the
   * flow space), its DoFs, and its local system zeroed. */
  void reinit (const TwoFluidSolver<dim> &solver,
               const CellIterator        &cell,
               const CellIterator        &flow_cell)
  {
    theta_values.reinit (cell);
    flow_values.reinit (flow_cell);
    theta_values.get_function_values (solver.alpha, a);
    theta_values.get_function_values (solver.theta, t_now);
    theta_values.get_function_values (solver.theta_old, t_old);
    theta_values.get_function_values (solver.theta_old2, t_old2);
    flow_values[gas].get_function_values (solver.flow_solution, ug);
    flow_values[solids].get_function_values (solver.flow_solution, us);
    flow_values[solids].get_function_gradients (solver.flow_solution, grad_us);
    cell->get_dof_indices (dofs);
    cell_matrix = 0;
    cell_rhs    = 0;
    cell_mass   = 0;
  }

  const QGauss<dim>                    quadrature;
  const QGauss<dim - 1>                face_quadrature;
  FEValues<dim>                        theta_values, flow_values;
  FEFaceValues<dim>                    theta_face, flow_face;
  const unsigned int                   n, n_q;
  FullMatrix<double>                   cell_matrix;
  Vector<double>                       cell_rhs, cell_mass;
  std::vector<types::global_dof_index> dofs;
  std::vector<double>                  a, t_now, t_old, t_old2;
  std::vector<Tensor<1, dim>>          ug, us;
  std::vector<Tensor<2, dim>>          grad_us;
  std::vector<double>                  a_face, t_face;
  std::vector<Tensor<1, dim>>          us_face;
  const FEValuesExtractors::Vector     gas, solids;
  // verification runs: the manufactured volume and boundary sources
  const Tensor<1, dim> wall_velocity;
  const bool           manufactured_theta;
};

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
bool TwoFluidSolver<dim>::update_granular_temperature (const BDFCoefficients &bdf,
                                                       const double           dt)
{
  TimerOutput::Scope            scope (timer, "granular temperature");
  const bool                    algebraic = parameters.kinetic_theory.algebraic;
  TrilinosWrappers::MPI::Vector rhs (alpha_dof_handler.locally_owned_dofs (),
                                     communicator),
      solution (rhs);
  GranularEnergyBudget budget;
  if (algebraic)
    project_algebraic_granular_temperature (solution, budget);
  else
    assemble_granular_energy_system (bdf, dt, rhs, budget);
  granular_energy_budget = sum_over_ranks (budget, communicator);

  if (!algebraic && !solve_granular_energy_system (rhs, solution))
    return false;
  return set_granular_temperature (solution);
}

template <int dim>
void TwoFluidSolver<dim>::project_algebraic_granular_temperature (
    TrilinosWrappers::MPI::Vector &solution, GranularEnergyBudget &budget) const
{
  const auto                   &kt = parameters.kinetic_theory;
  GranularEnergyScratch         scratch (*this);
  const FEValues<dim>          &theta_values = scratch.theta_values;
  Vector<double>               &cell_rhs     = scratch.cell_rhs;
  Vector<double>               &cell_mass    = scratch.cell_mass;
  TrilinosWrappers::MPI::Vector rhs (alpha_dof_handler.locally_owned_dofs (),
                                     communicator),
      lumped (rhs);

  auto flow_cell = flow_dof_handler.begin_active ();
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      scratch.reinit (*this, cell, flow_cell);
      for (unsigned int q = 0; q < scratch.n_q; ++q)
      {
        const double alpha_s = std::max (scratch.a[q], 0.0), JxW = theta_values.JxW (q);
        const SymmetricTensor<2, dim> D        = symmetrize (scratch.grad_us[q]);
        const double                  trace_d  = trace (D);
        const double                  d_ddot_d = D * D;
        const double                  beta =
            closure_evaluator.drag (alpha_s, (scratch.ug[q] - scratch.us[q]).norm ());
        for (unsigned int i = 0; i < scratch.n; ++i)
          cell_mass (i) += theta_values.shape_value (i, q) * JxW;
        // as the PDE's production: scaled by min(1, alpha_s/alpha_dilute) (the local
        // equilibrium of a trace of particles, ~1/alpha_s, is meaningless), clamped
        const double value = std::clamp (
            kt.dilute_weight (alpha_s) *
                kinetic_theory->algebraic_temperature (alpha_s, trace_d, d_ddot_d, beta),
            kt.minimum_temperature,
            kt.maximum_temperature);
        for (unsigned int i = 0; i < scratch.n; ++i)
          cell_rhs (i) += value * theta_values.shape_value (i, q) * JxW;
        const auto c = kinetic_theory->evaluate (alpha_s, value);
        budget.production += viscous_heating (c, trace_d, d_ddot_d) * JxW;
        add_sinks_to_budget (budget, c, value, beta, JxW);
      }
      alpha_constraints.distribute_local_to_global (cell_rhs, scratch.dofs, rhs);
      alpha_constraints.distribute_local_to_global (cell_mass, scratch.dofs, lumped);
    }
    ++flow_cell;
  }
  rhs.compress (VectorOperation::add);
  lumped.compress (VectorOperation::add);

  for (const auto i : solution.locally_owned_elements ())
    solution (i) = alpha_constraints.is_constrained (i) ? 0.0 : rhs (i) / lumped (i);
}

template <int dim>
void TwoFluidSolver<dim>::assemble_granular_energy_system (
    const BDFCoefficients         &bdf,
    const double                   dt,
    TrilinosWrappers::MPI::Vector &rhs,
    GranularEnergyBudget          &budget)
{
  GranularEnergyScratch scratch (*this);
  granular_energy_matrix = 0;

  auto flow_cell = flow_dof_handler.begin_active ();
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      scratch.reinit (*this, cell, flow_cell);
      const double peclet =
          assemble_granular_energy_volume_terms (cell, scratch, bdf, dt, budget);
      // discrete upwinding: d_ij = max(0, a_ij, a_ji) of the convection-diffusion
      // matrix, weighted by min(1, Pe_h). On Q1 hexahedra the Laplacian's entries
      // between edge neighbours are zero (positive on distorted cells), so the full
      // d_ij is O(rho |u| h^2) however fine the mesh: a first-order error (measured:
      // Theta converged at rate 1.0 in the 3D manufactured solution). Weighted by Pe_h
      // it is O(h^2) where the conduction resolves the convection and the full
      // upwinding (an M-matrix) where it does not (the dilute freeboard, coarse beds).
      const double upwinding = std::min (1.0, peclet);
      upwind_cell_matrix (scratch.cell_matrix, upwinding);
      assemble_granular_energy_boundary_terms (cell, flow_cell, scratch, budget);
      alpha_constraints.distribute_local_to_global (
          scratch.cell_matrix, scratch.dofs, granular_energy_matrix);
      alpha_constraints.distribute_local_to_global (scratch.cell_rhs, scratch.dofs, rhs);
    }
    ++flow_cell;
  }
  rhs.compress (VectorOperation::add);
  granular_energy_matrix.compress (VectorOperation::add);
}

template <int dim>
double TwoFluidSolver<dim>::assemble_granular_energy_volume_terms (
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    GranularEnergyScratch                                &scratch,
    const BDFCoefficients                                &bdf,
    const double                                          dt,
    GranularEnergyBudget                                 &budget) const
{
  const auto          &kt             = parameters.kinetic_theory;
  const double         rho_s          = parameters.physical.particle_density;
  const double         residual_alpha = 1e-6;
  const unsigned int   n              = scratch.n;
  const FEValues<dim> &theta_values   = scratch.theta_values;
  FullMatrix<double>  &cell_matrix    = scratch.cell_matrix;
  Vector<double>      &cell_rhs       = scratch.cell_rhs;
  const auto          &us             = scratch.us;
  // cell Peclet number of the Theta convection (the largest over the Gauss points)
  const double h_cell = cell->diameter () / std::sqrt (double (dim));
  double       peclet = 0;
  for (unsigned int q = 0; q < scratch.n_q; ++q)
  {
    const double alpha_s = std::max (scratch.a[q], 0.0), JxW = theta_values.JxW (q);
    const SymmetricTensor<2, dim> D        = symmetrize (scratch.grad_us[q]);
    const double                  trace_d  = trace (D);
    const double                  d_ddot_d = D * D;
    const double beta = closure_evaluator.drag (alpha_s, (scratch.ug[q] - us[q]).norm ());
    const double theta_star   = std::max (scratch.t_now[q], kt.minimum_temperature);
    const auto   c            = kinetic_theory->evaluate (alpha_s, theta_star);
    const double capacity     = 1.5 * rho_s * std::max (alpha_s, residual_alpha);
    const double dilute       = kt.dilute_weight (alpha_s);
    const double conductivity = dilute * c.conductivity;
    peclet                    = std::max (peclet,
                       capacity * us[q].norm () * h_cell /
                           (2 * conductivity + std::numeric_limits<double>::min ()));
    const double heating =
        dilute * (viscous_heating (c, trace_d, d_ddot_d) +
                  c.pressure_factor * theta_star * std::max (-trace_d, 0.0));
    const double sink = c.dissipation_factor * std::sqrt (theta_star) + 3 * beta +
                        c.pressure_factor * std::max (trace_d, 0.0);
    const double history = -(bdf.a1 * scratch.t_old[q] + bdf.a2 * scratch.t_old2[q]) / dt;
    const double source =
        scratch.manufactured_theta
            ? manufactured->granular_energy_source (theta_values.quadrature_point (q))
            : 0.0;
    budget.production += heating * JxW;
    add_sinks_to_budget (budget, c, theta_star, beta, JxW);
    for (unsigned int i = 0; i < n; ++i)
    {
      const double phi_i = theta_values.shape_value (i, q);
      // lumped: mass, history, sinks on the diagonal
      cell_matrix (i, i) += (capacity * bdf.a0 / dt + sink) * phi_i * JxW;
      cell_rhs (i) += (heating + source + capacity * history) * phi_i * JxW;
      for (unsigned int j = 0; j < n; ++j)
        cell_matrix (i, j) +=
            (capacity * phi_i * (us[q] * theta_values.shape_grad (j, q)) +
             conductivity *
                 (theta_values.shape_grad (i, q) * theta_values.shape_grad (j, q))) *
            JxW;
    }
  }
  return peclet;
}

template <int dim>
void TwoFluidSolver<dim>::assemble_granular_energy_boundary_terms (
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const typename DoFHandler<dim>::active_cell_iterator &flow_cell,
    GranularEnergyScratch                                &scratch,
    GranularEnergyBudget                                 &budget) const
{
  const auto            &kt              = parameters.kinetic_theory;
  const unsigned int     n               = scratch.n;
  const QGauss<dim - 1> &face_quadrature = scratch.face_quadrature;
  FEFaceValues<dim>     &theta_face      = scratch.theta_face;
  FEFaceValues<dim>     &flow_face       = scratch.flow_face;
  FullMatrix<double>    &cell_matrix     = scratch.cell_matrix;
  Vector<double>        &cell_rhs        = scratch.cell_rhs;
  for (const auto &face : cell->face_iterators ())
  {
    if (!face->at_boundary ())
      continue;
    const bool wall_face = boundaries.is_wall (face->boundary_id ()) &&
                           wall_conditions.at (face->boundary_id (), Phase::solids)
                               .has_granular_energy_flux ();
    // the slip is relative to a moving wall
    const Tensor<1, dim> wall_motion =
        boundaries.is (face->boundary_id (), BoundaryType::moving_wall)
            ? scratch.wall_velocity
            : Tensor<1, dim> ();
    if (scratch.manufactured_theta)
    {
      theta_face.reinit (cell, face);
      flow_face.reinit (flow_cell, face);
      for (unsigned int q = 0; q < face_quadrature.size (); ++q)
      {
        const double flux = manufactured->granular_energy_boundary_source (
            theta_face.quadrature_point (q), flow_face.normal_vector (q), wall_face);
        for (unsigned int i = 0; i < n; ++i)
          cell_rhs (i) += flux * theta_face.shape_value (i, q) * theta_face.JxW (q);
      }
    }
    if (wall_face)
    {
      theta_face.reinit (cell, face);
      flow_face.reinit (flow_cell, face);
      theta_face.get_function_values (alpha, scratch.a_face);
      theta_face.get_function_values (theta, scratch.t_face);
      flow_face[scratch.solids].get_function_values (flow_solution, scratch.us_face);
      for (unsigned int q = 0; q < face_quadrature.size (); ++q)
      {
        const double alpha_s     = std::max (scratch.a_face[q], 0.0);
        const double theta_star  = std::max (scratch.t_face[q], kt.minimum_temperature);
        const double g0          = kinetic_theory->radial_distribution (alpha_s);
        const Tensor<1, dim> n_w = flow_face.normal_vector (q);
        const Tensor<1, dim> relative = scratch.us_face[q] - wall_motion;
        const double         slip     = (relative - (relative * n_w) * n_w).norm ();
        const double         generation =
            kt.dilute_weight (alpha_s) *
            kinetic_theory->wall ().energy_generation (alpha_s, g0, theta_star, slip);
        const double sink =
            kinetic_theory->wall ().energy_dissipation (alpha_s, g0, theta_star) /
            theta_star;
        budget.wall_flux += (generation - sink * theta_star) * theta_face.JxW (q);
        for (unsigned int i = 0; i < n; ++i)
        {
          const double phi_i = theta_face.shape_value (i, q) * theta_face.JxW (q);
          cell_rhs (i) += generation * phi_i;
          cell_matrix (i, i) += sink * phi_i;
        }
      }
    }
  }
}

template <int dim>
bool TwoFluidSolver<dim>::solve_granular_energy_system (
    const TrilinosWrappers::MPI::Vector &rhs, TrilinosWrappers::MPI::Vector &solution)
{
  for (const auto i : solution.locally_owned_elements ())
    solution (i) = theta (i);
  SolverControl control (
      500, parameters.linear_solver.scalar_tolerance * rhs.l2_norm () + 1e-300);
  control.enable_history_data ();
  // right preconditioning: the tolerance applies to the true residual. Left (deal.II's
  // default) measures the AMG-preconditioned residual, ~dt/capacity smaller here: the
  // Theta solves stopped at a true residual ~1e-4 relative (measured: Theta at 2e-4 s
  // moved by 8e-5 between scalar tolerances 1e-13 and 1e-16).
  SolverGMRES<TrilinosWrappers::MPI::Vector> gmres (
      control, SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData (30, true));
  TrilinosWrappers::PreconditionILU amg;
  amg.initialize (granular_energy_matrix);
  try
  {
    gmres.solve (granular_energy_matrix, solution, rhs, amg);
    solve_history.record ("granular temperature GMRES", control, true);
  }
  catch (const SolverControl::NoConvergence &failure)
  {
    solve_history.record ("granular temperature GMRES", control, false);
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
bool TwoFluidSolver<dim>::set_granular_temperature (
    const TrilinosWrappers::MPI::Vector &solution)
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

template bool TwoFluidSolver<2>::update_granular_temperature (const BDFCoefficients &,
                                                              double);
template bool TwoFluidSolver<3>::update_granular_temperature (const BDFCoefficients &,
                                                              double);
} // namespace wetbed
