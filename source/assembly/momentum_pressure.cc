#include <wetbed/assembly/inertial_fraction.h>
#include <wetbed/assembly/nitsche_wall.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/manifold.h>

namespace wetbed
{
using namespace dealii;

/**
 * Assembles the Oseen-linearised two-fluid system at t_{n+1} (DESIGN s1, s4.5):
 *   gas:    a0 a_g rho_g u_g/dt + a_g rho_g (u_g*.grad) u_g - div tau_g + beta (u_g -
 * u_s)
 *           - (p', div(a_g v)) = rhs
 *   solids: a0 a_s rho_s u_s/dt + a_s rho_s (u_s*.grad) u_s - div tau_s - beta (u_g -
 * u_s)
 *           - (p', div(a_s v)) = (P_s, div v) + a_s (rho_s - rho_g) g + rhs
 *   mixture continuity: -(q, div(a_g u_g + a_s u_s)) = 0
 * with beta, P_s, mu_s lagged (closures evaluated once per quadrature point), and the
 * partial-elimination Schur mobility Laplacian L_c for the preconditioner.
 *
 * Well-balanced compaction force: P_s is the Q1 interpolant of P_s(alpha_j) at the
 * nodes and the buoyant solids weight uses the cell mean of alpha_s. Then a bed whose
 * nodal alpha_s satisfies P_s(alpha_k) - P_s(alpha_k+1) = h (rho_s - rho_g)|g|
 * (alpha_k + alpha_k+1)/2 cell by cell is an exact discrete rest state (grad P_h and
 * the weight are the same cell-wise constant vector), free surface included. With
 * P_s(alpha_h) at quadrature points and the pointwise weight no such state exists: P_s
 * is far from linear across the cell at the bed top and the residual drives a steady
 * spurious circulation (measured 0.07 m/s in a packed bed).
 */
template <int dim>
void TwoFluidSolver<dim>::assemble_flow_system (const BDFCoefficients &bdf,
                                                const double           dt)
{
  TimerOutput::Scope scope (timer, "flow assembly");
  flow_matrix = 0;
  boundary_cell_systems.clear ();
  // (copies of ghosted vectors: the ghost values come with them)
  assembled_alpha         = alpha;
  assembled_flow          = flow_solution;
  const Tensor<1, dim> up = upward_direction<dim> (parameters.physical.gravity);
  schur_matrix            = 0;
  flow_rhs                = 0;
  const auto  &pp         = parameters.physical;
  const double rho_g = pp.gas_density, rho_s = pp.particle_density,
               mu_g = pp.gas_viscosity;
  Tensor<1, dim> gravity;
  for (unsigned int d = 0; d < dim; ++d)
    gravity[d] = pp.gravity[d];

  const QGauss<dim>     quadrature (3);
  const QGauss<dim - 1> face_quadrature (3);
  FEValues<dim>         fe_values (mapping,
                           flow_fe,
                           quadrature,
                           update_values | update_gradients | update_quadrature_points |
                               update_JxW_values);
  FEValues<dim>         alpha_values (
      mapping, alpha_fe, quadrature, update_values | update_gradients);
  FEFaceValues<dim> face_values (mapping,
                                 flow_fe,
                                 face_quadrature,
                                 update_values | update_gradients |
                                     update_normal_vectors | update_quadrature_points |
                                     update_JxW_values);
  FEFaceValues<dim> alpha_face_values (mapping, alpha_fe, face_quadrature, update_values);

  const unsigned int n_dofs = flow_fe.n_dofs_per_cell ();
  const unsigned int n_q    = quadrature.size ();
  FullMatrix<double> cell_matrix (n_dofs, n_dofs), cell_schur (n_dofs, n_dofs);
  Vector<double>     cell_rhs (n_dofs);
  std::vector<types::global_dof_index> dofs (n_dofs);

  std::vector<unsigned int> component (n_dofs);
  for (unsigned int i = 0; i < n_dofs; ++i)
    component[i] = flow_fe.system_to_component_index (i).first;

  const FEValuesExtractors::Vector gas (0), solids (dim);
  std::vector<double>              a_s (n_q), theta_q (n_q);
  std::vector<Tensor<1, dim>>      grad_a_s (n_q);
  std::vector<Tensor<1, dim>>      ug_lag (n_q), us_lag (n_q), ug_old (n_q), us_old (n_q),
      ug_old2 (n_q), us_old2 (n_q);
  std::vector<Tensor<2, dim>> grad_us_lag (n_q), grad_ug_lag (n_q);
  std::vector<double>         a_s_old (n_q), a_s_old2 (n_q);
  const bool                  conservative = parameters.conservative_momentum;
  Vector<double>              alpha_nodal (alpha_fe.n_dofs_per_cell ()),
      pressure_nodal (alpha_fe.n_dofs_per_cell ());
  std::vector<double>         pressure_interpolant (n_q);
  std::vector<double>         phi (n_dofs);
  std::vector<Tensor<1, dim>> grad_phi (n_dofs);

  // verification runs keep the wall conditions only with slip walls (else: exact values)
  const bool           slip_walls    = !manufactured || manufactured->slip_walls ();
  const Tensor<1, dim> wall_velocity = moving_wall_velocity ();
  const bool           partial_slip =
      (parameters.boundary.solids_wall == WallCondition::partial_slip ||
       parameters.boundary.solids_wall == WallCondition::johnson_jackson) &&
      slip_walls;
  const bool wall_source = manufactured && slip_walls;
  const bool johnson_jackson_wall =
      parameters.boundary.solids_wall == WallCondition::johnson_jackson;
  std::vector<double> alpha_face (face_quadrature.size ()),
      theta_face (face_quadrature.size ());
  std::vector<Tensor<1, dim>> ug_face (face_quadrature.size ()),
      us_face (face_quadrature.size ());
  std::vector<Tensor<2, dim>> grad_us_face (face_quadrature.size ());
  const double                wall_friction = parameters.boundary.solids_wall_friction;
  // weak no-penetration (Nitsche) for each phase that slips on the walls
  const bool   nitsche[2] = {slip_walls && parameters.boundary.nitsche &&
                                 parameters.boundary.gas_wall != WallCondition::no_slip,
                             slip_walls && parameters.boundary.nitsche &&
                                 parameters.boundary.solids_wall != WallCondition::no_slip};
  const double nitsche_gamma =
      parameters.boundary.nitsche_penalty * std::pow (flow_fe.degree + 1.0, 2);
  const bool stabilized = parameters.stabilization;

  auto alpha_cell = alpha_dof_handler.begin_active ();
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
  {
    if (!cell->is_locally_owned ())
    {
      ++alpha_cell;
      continue;
    }
    fe_values.reinit (cell);
    alpha_values.reinit (alpha_cell);
    alpha_values.get_function_values (alpha, a_s);
    alpha_values.get_function_values (theta, theta_q);
    alpha_values.get_function_gradients (alpha, grad_a_s);
    fe_values[gas].get_function_values (flow_solution, ug_lag);
    fe_values[solids].get_function_values (flow_solution, us_lag);
    fe_values[solids].get_function_gradients (flow_solution, grad_us_lag);
    if (conservative)
    {
      fe_values[gas].get_function_gradients (flow_solution, grad_ug_lag);
      alpha_values.get_function_values (alpha_old, a_s_old);
      alpha_values.get_function_values (alpha_old2, a_s_old2);
    }
    fe_values[gas].get_function_values (flow_old, ug_old);
    fe_values[solids].get_function_values (flow_old, us_old);
    fe_values[gas].get_function_values (flow_old2, ug_old2);
    fe_values[solids].get_function_values (flow_old2, us_old2);
    const double h = cell->diameter () / std::sqrt (double (dim));
    // Well-balanced compaction force (see the class comment): P_s enters as the Q1
    // interpolant of its nodal values, the buoyant weight with the cell mean of alpha_s.
    alpha_cell->get_dof_values (alpha, alpha_nodal);
    for (unsigned int j = 0; j < alpha_nodal.size (); ++j)
      pressure_nodal[j] = solids_stress->evaluate ({alpha_nodal[j], 0.0, 0.0}).pressure;
    double cell_volume = 0, alpha_mean = 0;
    for (unsigned int q = 0; q < n_q; ++q)
    {
      pressure_interpolant[q] = 0;
      for (unsigned int j = 0; j < alpha_nodal.size (); ++j)
        pressure_interpolant[q] += pressure_nodal[j] * alpha_values.shape_value (j, q);
      cell_volume += fe_values.JxW (q);
      alpha_mean += a_s[q] * fe_values.JxW (q);
    }
    alpha_mean /= cell_volume;

    cell_matrix = 0;
    cell_schur  = 0;
    cell_rhs    = 0;
    for (unsigned int q = 0; q < n_q; ++q)
    {
      const double alpha_s = a_s[q], alpha_g = 1.0 - alpha_s;
      // inertia and drag of the solids at no less than the residual fraction
      const double alpha_inertia        = std::max (alpha_s, pp.residual_solids_fraction);
      const Tensor<1, dim> grad_alpha_s = grad_a_s[q], grad_alpha_g = -grad_a_s[q];
      // closures, once per quadrature point
      const double slip = (ug_lag[q] - us_lag[q]).norm ();
      const double beta = drag->coefficient (alpha_inertia, slip, gas_particle);
      const SymmetricTensor<2, dim> strain   = symmetrize (grad_us_lag[q]);
      const SymmetricTensor<2, dim> deviator = deviator_tensor<dim> () * strain;
      const closures::SolidsStress  stress   = solids_stress->evaluate (
          {alpha_s, theta_q[q], std::sqrt (2.0 * deviator * deviator)});
      const double mu_s = stress.shear_viscosity, lambda_s = stress.bulk_viscosity;
      const double JxW = fe_values.JxW (q);

      const double inertia_g = alpha_g * rho_g, inertia_s = alpha_inertia * rho_s;
      const double mass_g = bdf.a0 * inertia_g / dt, mass_s = bdf.a0 * inertia_s / dt;
      // the BDF history: conservative, each level with its own volume fraction
      double history[2][2] = {{inertia_g, inertia_g}, {inertia_s, inertia_s}};
      // conservative: rho_k div(alpha_k* u_k*) u_k, implicit where positive (mass
      // added), with the lagged u_k* where negative (keeps the diagonal positive)
      double         continuity_mass[2] = {0, 0};
      Tensor<1, dim> continuity_force[2];
      if (conservative)
      {
        const double         residual           = pp.residual_solids_fraction;
        const double         density[2]         = {rho_g, rho_s};
        const Tensor<1, dim> lagged[2]          = {ug_lag[q], us_lag[q]};
        const Tensor<2, dim> lagged_gradient[2] = {grad_ug_lag[q], grad_us_lag[q]};
        for (unsigned int k = 0; k < 2; ++k)
        {
          history[k][0] = inertial_fraction (k, a_s_old[q], residual) * density[k];
          history[k][1] = inertial_fraction (k, a_s_old2[q], residual) * density[k];
          const double divergence = inertial_flux_divergence<dim> (
              k, alpha_s, grad_alpha_s, lagged[k], lagged_gradient[k], residual);
          continuity_mass[k]  = density[k] * std::max (divergence, 0.0);
          continuity_force[k] = -density[k] * std::min (divergence, 0.0) * lagged[k];
        }
      }
      const Tensor<1, dim> history_g =
          -(bdf.a1 * history[0][0] * ug_old[q] + bdf.a2 * history[0][1] * ug_old2[q]) /
              dt +
          continuity_force[0];
      Tensor<1, dim> force_s =
          -(bdf.a1 * history[1][0] * us_old[q] + bdf.a2 * history[1][1] * us_old2[q]) /
              dt +
          continuity_force[1] + alpha_mean * (rho_s - rho_g) * gravity;
      Tensor<1, dim> force_g       = history_g;
      double         volume_source = 0;
      if (manufactured)
      {
        const Point<dim> &x = fe_values.quadrature_point (q);
        force_g += manufactured->gas_momentum_source (x);
        force_s += manufactured->solids_momentum_source (x);
        volume_source = manufactured->mixture_volume_source (x);
      }
      // partial-elimination mobility of the mixture volume flux (DESIGN s5)
      const double a_g_local = mass_g + alpha_g * mu_g / (h * h);
      const double a_s_local = mass_s + mu_s / (h * h);
      const double mobility =
          (alpha_g * alpha_g * a_s_local + alpha_s * alpha_s * a_g_local + beta) /
          (a_g_local * a_s_local + beta * (a_g_local + a_s_local));

      const double viscosity[2] = {alpha_g * mu_g, mu_s};
      const double bulk[2] = {-2.0 / 3.0 * alpha_g * mu_g, lambda_s - 2.0 / 3.0 * mu_s};
      const double mass[2] = {mass_g, mass_s};
      const double inertia[2]               = {inertia_g, inertia_s};
      const double fraction[2]              = {alpha_g, alpha_s};
      const Tensor<1, dim> grad_fraction[2] = {grad_alpha_g, grad_alpha_s};
      const Tensor<1, dim> advecting[2]     = {ug_lag[q], us_lag[q]};
      const Tensor<1, dim> force[2]         = {force_g, force_s};

      for (unsigned int i = 0; i < n_dofs; ++i)
      {
        phi[i]      = fe_values.shape_value (i, q);
        grad_phi[i] = fe_values.shape_grad (i, q);
      }
      // Streamline diffusion: the convective part of the SUPG residual, weighted by
      // tau_k alpha_k rho_k (u_k*.grad v). tau_k includes the time, convection,
      // viscous and drag rates, so it vanishes where drag dominates (the bed) and
      // acts like upwinding in the freeboard. Symmetric, so the AMG keeps working
      // (the full SUPG residual with its pressure and drag terms did not).
      double tau[2] = {0, 0};
      if (stabilized)
      {
        for (unsigned int k = 0; k < 2; ++k)
        {
          const double density = std::max (inertia[k], 1e-12);
          const double nu      = viscosity[k] / density;
          const double h_node  = 0.5 * h;
          tau[k]               = 1.0 / std::sqrt (std::pow (2.0 * bdf.a0 / dt, 2) +
                                    std::pow (2.0 * advecting[k].norm () / h_node, 2) +
                                    std::pow (12.0 * nu / (h_node * h_node), 2) +
                                    std::pow (beta / density, 2));
        }
      }

      for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const unsigned int ci = component[i];
        if (ci < 2 * dim)
        {
          const unsigned int k = ci / dim, d = ci % dim;
          const double       supg = tau[k] * inertia[k] * (advecting[k] * grad_phi[i]);
          cell_rhs (i) += force[k][d] * phi[i] * JxW;
          if (k == 1)
            cell_rhs (i) += (pressure_interpolant[q] + stress.kinetic_pressure) *
                            grad_phi[i][d] * JxW;
          for (unsigned int j = 0; j < n_dofs; ++j)
          {
            const unsigned int cj    = component[j];
            double             value = 0;
            if (cj < 2 * dim)
            {
              const unsigned int l = cj / dim, e = cj % dim;
              if (k == l)
              {
                if (d == e)
                  value += (mass[k] + continuity_mass[k] + beta) * phi[i] * phi[j] +
                           inertia[k] * (advecting[k] * grad_phi[j]) * phi[i] +
                           viscosity[k] * (grad_phi[i] * grad_phi[j]);
                value += viscosity[k] * grad_phi[j][d] * grad_phi[i][e] +
                         bulk[k] * grad_phi[j][e] * grad_phi[i][d];
                if (d == e && supg != 0)
                  value += supg * inertia[k] * (advecting[k] * grad_phi[j]);
              }
              else if (d == e)
                value -= beta * phi[i] * phi[j];
            }
            else // pressure trial: -(p', div(alpha_k v))
              value -=
                  phi[j] * (fraction[k] * grad_phi[i][d] + phi[i] * grad_fraction[k][d]);
            cell_matrix (i, j) += value * JxW;
          }
        }
        else
        {
          cell_rhs (i) -= volume_source * phi[i] * JxW;
          for (unsigned int j = 0; j < n_dofs; ++j)
          {
            const unsigned int cj = component[j];
            if (cj < 2 * dim)
            {
              const unsigned int l = cj / dim, e = cj % dim;
              cell_matrix (i, j) -=
                  phi[i] * (fraction[l] * grad_phi[j][e] + phi[j] * grad_fraction[l][e]) *
                  JxW;
            }
            else
              cell_schur (i, j) += mobility * (grad_phi[i] * grad_phi[j]) * JxW;
          }
        }
      }
    }

    // boundary terms: solids partial slip on walls, verification tractions on the outlet
    for (const auto &face : cell->face_iterators ())
    {
      if (!face->at_boundary ())
        continue;
      const auto id                 = face->boundary_id ();
      const bool wall_friction_face = partial_slip && boundary_ids.is_wall (id);
      const bool moving_face        = id == boundary_ids.moving_wall;
      const bool traction_face      = manufactured && id == boundary_ids.outlet;
      const bool backflow_face      = stabilized && id == boundary_ids.outlet;
      const bool nitsche_face = boundary_ids.is_wall (id) && (nitsche[0] || nitsche[1]);
      const bool source_face  = wall_source && id == boundary_ids.wall;
      if (!wall_friction_face && !traction_face && !backflow_face && !nitsche_face &&
          !source_face)
        continue;
      face_values.reinit (cell, face);
      face_values[gas].get_function_values (flow_solution, ug_face);
      if (nitsche_face)
      {
        face_values[solids].get_function_values (flow_solution, us_face);
        face_values[solids].get_function_gradients (flow_solution, grad_us_face);
      }
      if ((wall_friction_face && johnson_jackson_wall) || nitsche_face)
      {
        alpha_face_values.reinit (alpha_cell, face);
        alpha_face_values.get_function_values (alpha, alpha_face);
        alpha_face_values.get_function_values (theta, theta_face);
      }
      for (unsigned int q = 0; q < face_quadrature.size (); ++q)
      {
        const Tensor<1, dim> n   = face_values.normal_vector (q);
        const double         JxW = face_values.JxW (q);
        // directional do-nothing: gas flowing back in through the outlet is
        // treated as inflow, rho_g |u_g.n|_- u_g.v (alpha_g ~ 1 in the freeboard)
        const double backflow =
            backflow_face ? rho_g * std::max (-(ug_face[q] * n), 0.0) : 0.0;
        // Johnson-Jackson: the Robin coefficient C_JJ(alpha_s, g0, Theta) of the
        // tangential traction -C_JJ u_slip (lagged); partial slip: a constant C
        double friction = wall_friction;
        if (wall_friction_face && johnson_jackson_wall)
        {
          const double a = std::max (alpha_face[q], 0.0);
          friction       = kinetic_theory->wall ().shear_coefficient (
              a, kinetic_theory->radial_distribution (a), std::max (theta_face[q], 0.0));
        }
        if (nitsche_face)
        {
          // the phase coefficients as in the volume terms, at the face point
          const double a    = alpha_face[q];
          const double slip = (ug_face[q] - us_face[q]).norm ();
          const double beta = drag->coefficient (
              std::max (a, pp.residual_solids_fraction), slip, gas_particle);
          const SymmetricTensor<2, dim> deviator =
              deviator_tensor<dim> () * symmetrize (grad_us_face[q]);
          const closures::SolidsStress stress = solids_stress->evaluate (
              {a, theta_face[q], std::sqrt (2.0 * deviator * deviator)});
          double compaction = 0;
          for (unsigned int j = 0; j < alpha_nodal.size (); ++j)
            compaction += pressure_nodal[j] * alpha_face_values.shape_value (j, q);
          const double h_wall = h;
          auto         scale = [&] (const double mu, const double inertia, const double u)
          {
            return mu + inertia * u * h_wall + inertia * h_wall * h_wall * bdf.a0 / dt +
                   beta * h_wall * h_wall;
          };
          const std::array<NitschePhase, 2> phases = {
              {NitschePhase{nitsche[0],
                            0,
                            1 - a,
                            (1 - a) * mu_g,
                            -2.0 / 3.0 * (1 - a) * mu_g,
                            scale ((1 - a) * mu_g, (1 - a) * rho_g, ug_face[q].norm ()),
                            0.0},
               NitschePhase{nitsche[1],
                            dim,
                            a,
                            stress.shear_viscosity,
                            stress.bulk_viscosity - 2.0 / 3.0 * stress.shear_viscosity,
                            scale (stress.shear_viscosity,
                                   std::max (a, pp.residual_solids_fraction) * rho_s,
                                   us_face[q].norm ()),
                            compaction + stress.kinetic_pressure}}};
          // the wall's own normal where the wall is curved (a manifold other than
          // flat), oriented as the mapped one
          Tensor<1, dim> wall_normal = n;
          if (face->manifold_id () != numbers::flat_manifold_id)
          {
            wall_normal = face->get_manifold ().normal_vector (
                face, face_values.quadrature_point (q));
            wall_normal /= wall_normal.norm ();
            if (wall_normal * n < 0)
              wall_normal *= -1.0;
          }
          add_nitsche_no_penetration (face_values,
                                      q,
                                      wall_normal,
                                      component,
                                      phases,
                                      nitsche_gamma,
                                      h,
                                      cell_matrix,
                                      cell_rhs);
        }
        // the slip is relative to a moving wall: C P_t (u - u_w), P_t u_w on the rhs
        Tensor<1, dim> wall_motion;
        if (moving_face && wall_friction_face)
          wall_motion = wall_velocity - (wall_velocity * n) * n;
        Tensor<1, dim> traction[2];
        if (traction_face)
        {
          traction[0] = manufactured->gas_traction (face_values.quadrature_point (q), n);
          traction[1] =
              manufactured->solids_traction (face_values.quadrature_point (q), n);
        }
        if (source_face)
          for (unsigned int k = 0; k < 2; ++k)
            traction[k] = manufactured->wall_traction_source (
                face_values.quadrature_point (q), n, k);
        for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const unsigned int ci = component[i];
          if (ci >= 2 * dim)
            continue;
          const unsigned int k = ci / dim, d = ci % dim;
          const double       phi_i = face_values.shape_value (i, q);
          if (traction_face || source_face)
            cell_rhs (i) += traction[k][d] * phi_i * JxW;
          if (backflow > 0 && k == 0)
            for (unsigned int j = 0; j < n_dofs; ++j)
              if (component[j] == ci)
                cell_matrix (i, j) +=
                    backflow * phi_i * face_values.shape_value (j, q) * JxW;
          if (wall_friction_face && k == 1)
            for (unsigned int j = 0; j < n_dofs; ++j)
            {
              const unsigned int cj = component[j];
              if (cj < dim || cj >= 2 * dim)
                continue;
              const unsigned int e = cj % dim;
              // C (P_t u).(P_t v) with P_t = I - n n
              const double projector = (d == e ? 1.0 : 0.0) - n[d] * n[e];
              cell_matrix (i, j) +=
                  friction * projector * phi_i * face_values.shape_value (j, q) * JxW;
            }
          if (wall_friction_face && k == 1)
            cell_rhs (i) += friction * wall_motion[d] * phi_i * JxW;
        }
      }
    }

    cell->get_dof_indices (dofs);
    // the weighted unconstrained rows of boundary velocity DoFs (the reactions)
    if (cell->at_boundary ())
    {
      BoundaryCellSystem system{dofs, {}, {{0, 0, 0}}};
      bool               any = false;
      for (unsigned int i = 0; i < n_dofs; ++i)
        for (unsigned int b = 0; b < 3 && component[i] < 2 * dim; ++b)
          if (boundary_velocity_dofs[b].is_element (dofs[i]))
          {
            const double weight = up[component[i] % dim];
            if (weight != 0)
            {
              system.row[b].resize (n_dofs, 0.0);
              for (unsigned int j = 0; j < n_dofs; ++j)
                system.row[b][j] += weight * cell_matrix (i, j);
              system.rhs[b] += weight * cell_rhs (i);
              any = true;
            }
            break;
          }
      if (any)
        boundary_cell_systems.push_back (std::move (system));
    }
    flow_constraints.distribute_local_to_global (
        cell_matrix, cell_rhs, dofs, flow_matrix, flow_rhs);
    schur_constraints.distribute_local_to_global (cell_schur, dofs, schur_matrix);
    ++alpha_cell;
  }
  flow_matrix.compress (VectorOperation::add);
  schur_matrix.compress (VectorOperation::add);
  flow_rhs.compress (VectorOperation::add);
}

template void TwoFluidSolver<2>::assemble_flow_system (const BDFCoefficients &, double);
template void TwoFluidSolver<3>::assemble_flow_system (const BDFCoefficients &, double);
} // namespace wetbed
