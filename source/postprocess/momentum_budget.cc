#include <wetbed/assembly/inertial_fraction.h>
#include <wetbed/postprocess/momentum_budget.h>
#include <wetbed/solvers/flow_system.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <array>

/*
 * The inertial part of the vertical momentum budget of monitors.csv, the part that
 * closes what the boundary forces (wall_forces.cc) and the consistent boundary
 * reactions (FlowSystem::boundary_reactions) leave open.
 *
 * The momentum equations are assembled (BDF1 written; alpha*, u* the volume fraction
 * and velocity the last outer iteration linearised about, D_k = div(alpha_k* u_k*)) in
 *   advective form:     A_k = alpha_k* rho_k (u^{n+1} - u^n)/dt
 *                             + alpha_k* rho_k (u_k* . grad) u_k^{n+1},
 *   conservative form:  A_k = rho_k (alpha* u^{n+1} - alpha^n u^n)/dt
 *                             + alpha_k* rho_k (u_k* . grad) u_k^{n+1}
 *                             + rho_k (max(D_k, 0) u^{n+1} + min(D_k, 0) u*),
 *   skew-symmetric:     A_k = rho_k ((alpha* + alpha^n)/2 u^{n+1} - alpha^n u^n)/dt
 *                             + alpha_k* rho_k (u_k* . grad) u_k^{n+1} + rho_k D_k
 * u^{n+1}/2. The conservative momentum change C_k = rho_k (alpha^{n+1} u^{n+1} - alpha^n
 * u^n)/dt
 * + div(alpha_k* rho_k u_k* u_k^{n+1}) differs from A_k by
 *   advective:     rho_k [((alpha^{n+1} - alpha*) u^{n+1} + (alpha* - alpha^n) u^n)/dt
 *                         + D_k u^{n+1}],
 *   conservative:  rho_k [(alpha^{n+1} - alpha*) u^{n+1}/dt + min(D_k, 0)(u^{n+1} - u*)],
 *   skew-symmetric: rho_k [(alpha^{n+1} - alpha*) u^{n+1}/dt
 *                          + ((alpha* - alpha^n)/dt + D_k) u^{n+1}/2],
 * the velocity times the continuity residual of the volume fractions the flow solve saw
 * and the velocities it produced: large in the advective form (the alpha_s transport
 * conserves the solids mass in its own space, but the residual tested with the vertical
 * unit vector does not vanish), small in the conservative one. It is a force: over
 * the domain the boundary forces satisfy
 *   FI + supports - 1 + continuity_defect = d(mixture_momentum)/dt + momentum_outflow
 * (all as shares of the buoyant bed weight W), with
 *   mixture_momentum  = sum_k int alpha_k rho_k u_k . e / W   (seconds),
 *   continuity_defect = sum_k int (C_k - A_k) . e / W,
 *   momentum_outflow  = sum_k int_{inlet, outlet} alpha_k rho_k (u_k . e)(u_k . n) / W,
 * e = -g/|g|. In a statistically steady bed the time mean of the momentum derivative
 * vanishes, so the mean of FI + supports + continuity_defect - momentum_outflow is 1.
 * The solids inertia uses alpha_s no less than the residual solids fraction, as in the
 * assembly.
 */
namespace wetbed
{
using namespace dealii;

namespace
{
/** C - A at a point for the momentum form `form`: the inertia the discrete momentum
 * equation's form leaves out of d(alpha rho u)/dt + div(alpha rho u u) along e, per unit
 * density (fractions at t_{n+1}, t_n and the linearisation point; D = div(alpha* u*);
 * u_up = u^{n+1} . e, u_old_up = u^n . e, u_change = u^{n+1} - u*). */
template <int dim>
double continuity_defect (const MomentumForm          form,
                          const std::array<double, 3> fractions,
                          const double                divergence,
                          const double                u_up,
                          const double                u_old_up,
                          const Tensor<1, dim>       &u_change,
                          const Tensor<1, dim>       &up,
                          const double                dt)
{
  const auto [fraction_new, fraction_old, fraction_lag] = fractions;
  double defect = (fraction_new - fraction_lag) * u_up / dt;
  if (form == MomentumForm::conservative)
    defect += std::min (divergence, 0.0) * u_change * up;
  else if (form == MomentumForm::advective)
    defect += (fraction_lag - fraction_old) * u_old_up / dt + divergence * u_up;
  else
    defect += 0.5 * ((fraction_lag - fraction_old) * u_up / dt + divergence * u_up);
  return defect;
}

/** sum_k int alpha_k rho_k (u_k . e)(u_k . n) over the inlet and outlet faces of `cell`
 * (`alpha_cell` the same cell of the alpha_s space), added to `outflow`. */
template <int dim, typename CellIterator>
void add_momentum_outflow (const SolverState<dim> &s,
                           const CellIterator     &cell,
                           const CellIterator     &alpha_cell,
                           FEFaceValues<dim>      &flow_face,
                           FEFaceValues<dim>      &alpha_face,
                           double                 &outflow)
{
  const auto                      &pp          = s.parameters.physical;
  const Tensor<1, dim>             up          = upward_direction<dim> (pp.gravity);
  const double                     density[2]  = {pp.gas_density, pp.particle_density};
  const FEValuesExtractors::Vector velocity[2] = {FEValuesExtractors::Vector (0),
                                                  FEValuesExtractors::Vector (dim)};
  const unsigned int               n_q         = flow_face.n_quadrature_points;
  std::vector<double>              a_face (n_q);
  std::vector<Tensor<1, dim>>      u_face (n_q);
  for (const auto &face : cell->face_iterators ())
  {
    if (!face->at_boundary () ||
        !(s.boundaries.is (face->boundary_id (), BoundaryType::inlet) ||
          s.boundaries.is (face->boundary_id (), BoundaryType::outlet)))
      continue;
    flow_face.reinit (cell, face);
    alpha_face.reinit (alpha_cell, face);
    alpha_face.get_function_values (s.alpha, a_face);
    for (unsigned int k = 0; k < 2; ++k)
    {
      flow_face[velocity[k]].get_function_values (s.flow_solution, u_face);
      for (unsigned int q = 0; q < n_q; ++q)
        outflow += density[k] *
                   inertial_fraction (k, a_face[q], pp.residual_solids_fraction) *
                   (u_face[q] * up) * (u_face[q] * flow_face.normal_vector (q)) *
                   flow_face.JxW (q);
    }
  }
}
} // namespace

template <int dim>
InertialBudget evaluate_inertial_budget (const SolverState<dim> &s)
{
  const double          dt         = s.time_step;
  const auto           &pp         = s.parameters.physical;
  const Tensor<1, dim>  up         = upward_direction<dim> (pp.gravity);
  const double          density[2] = {pp.gas_density, pp.particle_density};
  const QGauss<dim>     quadrature (3);
  const QGauss<dim - 1> face_quadrature (3);
  FEValues<dim>         flow_values (s.mapping,
                             s.flow_fe,
                             quadrature,
                             update_values | update_gradients | update_JxW_values);
  FEValues<dim>         alpha_values (
      s.mapping, s.alpha_fe, quadrature, update_values | update_gradients);
  FEFaceValues<dim> flow_face (s.mapping,
                               s.flow_fe,
                               face_quadrature,
                               update_values | update_normal_vectors | update_JxW_values);
  FEFaceValues<dim> alpha_face (s.mapping, s.alpha_fe, face_quadrature, update_values);
  const FEValuesExtractors::Vector velocity[2] = {FEValuesExtractors::Vector (0),
                                                  FEValuesExtractors::Vector (dim)};
  const unsigned int               n_q         = quadrature.size ();
  std::vector<double>              a_new (n_q), a_old (n_q), a_lag (n_q);
  std::vector<Tensor<1, dim>> grad_a_lag (n_q), u_new (n_q), u_old (n_q), u_lag (n_q);
  std::vector<Tensor<2, dim>> grad_u_lag (n_q);
  // each flow vector's values on the cell, read once (a read from a Trilinos vector
  // looks every DoF up by its global index)
  Vector<double> now (s.flow_fe.n_dofs_per_cell ()), before (now.size ()),
      lag (now.size ());
  const auto view = [] (Vector<double> &v)
  { return make_array_view (v.begin (), v.end ()); };
  const MomentumForm form = s.parameters.momentum_form;

  const double residual = pp.residual_solids_fraction;
  auto         fraction = [&] (const unsigned int k, const double alpha_s)
  { return inertial_fraction (k, alpha_s, residual); };

  InertialBudget budget;
  auto           alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      flow_values.reinit (cell);
      alpha_values.reinit (alpha_cell);
      alpha_values.get_function_values (s.alpha, a_new);
      alpha_values.get_function_values (s.alpha_previous, a_old);
      alpha_values.get_function_values (s.flow_system.linearisation_alpha (), a_lag);
      alpha_values.get_function_gradients (s.flow_system.linearisation_alpha (),
                                           grad_a_lag);
      cell->get_dof_values (s.flow_solution, now);
      cell->get_dof_values (s.flow_previous, before);
      cell->get_dof_values (s.flow_system.linearisation_flow (), lag);
      for (unsigned int k = 0; k < 2; ++k)
      {
        const auto &values = flow_values[velocity[k]];
        values.get_function_values_from_local_dof_values (view (now), u_new);
        values.get_function_values_from_local_dof_values (view (before), u_old);
        values.get_function_values_from_local_dof_values (view (lag), u_lag);
        values.get_function_gradients_from_local_dof_values (view (lag), grad_u_lag);
        for (unsigned int q = 0; q < n_q; ++q)
        {
          const double JxW          = flow_values.JxW (q);
          const double fraction_new = fraction (k, a_new[q]),
                       fraction_old = fraction (k, a_old[q]),
                       fraction_lag = fraction (k, a_lag[q]);
          // D = div(alpha* u*), as in the assembly
          const double divergence = inertial_flux_divergence<dim> (
              k, a_lag[q], grad_a_lag[q], u_lag[q], grad_u_lag[q], residual);
          const double u_up = u_new[q] * up;
          // C - A, A the assembled form (see above)
          const double defect =
              continuity_defect<dim> (form,
                                      {{fraction_new, fraction_old, fraction_lag}},
                                      divergence,
                                      u_up,
                                      u_old[q] * up,
                                      u_new[q] - u_lag[q],
                                      up,
                                      dt);
          budget.momentum += density[k] * fraction_new * u_up * JxW;
          if (dt > 0)
            budget.continuity_defect += density[k] * defect * JxW;
        }
      }
      add_momentum_outflow (
          s, cell, alpha_cell, flow_face, alpha_face, budget.momentum_outflow);
    }
    ++alpha_cell;
  }
  budget.momentum = Utilities::MPI::sum (budget.momentum, s.communicator);
  budget.continuity_defect =
      Utilities::MPI::sum (budget.continuity_defect, s.communicator);
  budget.momentum_outflow = Utilities::MPI::sum (budget.momentum_outflow, s.communicator);
  return budget;
}

template InertialBudget evaluate_inertial_budget (const SolverState<2> &);
template InertialBudget evaluate_inertial_budget (const SolverState<3> &);
} // namespace wetbed
