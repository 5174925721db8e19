#include <wetbed/postprocess/wall_forces.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

/*
 * The vertical forces that hold the bed up besides the gas pressure drop, for the
 * momentum budget of monitors.csv: in the time mean of a statistically steady bed,
 *   FI + wall_support_solids + wall_support_gas + distributor_support
 *      + outlet_support ~ 1,
 * the remainder being the change of the phases' momentum, the gas momentum flux and
 * pressure forces on walls that are not vertical. Each force is the one the boundary
 * exerts on a phase, along -g, divided by the buoyant bed weight:
 *   - walls on each phase: the friction -C (u_k - u_w)_t of the wall's condition
 *     (Johnson-Jackson, partial slip, ...), with C as the assembly takes it from the
 *     condition; a phase that takes the wall's velocity (no slip): its viscous traction
 *     tau_k n, from the velocity gradient;
 *   - the inlet (distributor) on the solids held there: (-(P_s + P_kin) I + tau_s) n;
 *   - the outlet (a grid that retains the solids) on the solids, the same stress: it
 *     pushes a bed that reaches the top down (negative).
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
WallForces evaluate_wall_forces (const SolverState<dim> &s)
{
  const auto           &pp            = s.parameters.physical;
  const Tensor<1, dim>  up            = upward_direction<dim> (pp.gravity);
  const Tensor<1, dim>  wall_velocity = s.moving_wall_velocity;
  const QGauss<dim - 1> quadrature (3);
  FEFaceValues<dim>     flow_values (s.mapping,
                                 s.flow_fe,
                                 quadrature,
                                 update_values | update_gradients |
                                     update_normal_vectors | update_JxW_values);
  FEFaceValues<dim>     alpha_values (s.mapping, s.alpha_fe, quadrature, update_values);
  const FEValuesExtractors::Vector gas (0), solids (dim);
  std::vector<Tensor<1, dim>>      u_g (quadrature.size ()), u_s (quadrature.size ());
  std::vector<Tensor<2, dim>>      grad_u_g (quadrature.size ()),
      grad_u_s (quadrature.size ());
  std::vector<double> a (quadrature.size ()), theta_q (quadrature.size ());
  // the viscous stress 2 mu D + (lambda - 2/3 mu) div u I of a velocity gradient
  auto viscous = [] (const Tensor<2, dim> &grad, const double mu, const double lambda)
  {
    const SymmetricTensor<2, dim> strain = symmetrize (grad);
    return Tensor<2, dim> (2 * mu * strain + (lambda - 2.0 / 3.0 * mu) * trace (strain) *
                                                 unit_symmetric_tensor<dim> ());
  };
  WallForces forces;
  auto       alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
      for (const auto &face : cell->face_iterators ())
      {
        if (!face->at_boundary ())
          continue;
        const auto id     = face->boundary_id ();
        const bool wall   = s.boundaries.is_wall (id),
                   inlet  = s.boundaries.is (id, BoundaryType::inlet),
                   outlet = s.boundaries.is (id, BoundaryType::outlet);
        if (!wall && !inlet && !outlet)
          continue;
        flow_values.reinit (cell, face);
        alpha_values.reinit (alpha_cell, face);
        flow_values[gas].get_function_values (s.flow_solution, u_g);
        flow_values[solids].get_function_values (s.flow_solution, u_s);
        flow_values[gas].get_function_gradients (s.flow_solution, grad_u_g);
        flow_values[solids].get_function_gradients (s.flow_solution, grad_u_s);
        alpha_values.get_function_values (s.alpha, a);
        alpha_values.get_function_values (s.theta, theta_q);
        for (unsigned int q = 0; q < quadrature.size (); ++q)
        {
          const Tensor<1, dim>         n      = flow_values.normal_vector (q);
          const double                 JxW    = flow_values.JxW (q);
          const double                 a_s    = std::max (a[q], 0.0);
          const closures::SolidsStress stress = s.closures.stress (
              a_s,
              theta_q[q],
              closures::ClosureEvaluator::shear_rate<dim> (grad_u_s[q]),
              trace (grad_u_s[q]));
          // MFIX convention: mu_s, lambda_s carry alpha_s (doc/theory.md, "Conventions")
          const Tensor<2, dim> tau_s =
              viscous (grad_u_s[q], stress.shear_viscosity, stress.bulk_viscosity);
          if (inlet || outlet)
          {
            const double pressure = stress.pressure + stress.kinetic_pressure;
            (inlet ? forces.distributor : forces.outlet) +=
                (-pressure * n + tau_s * n) * up * JxW;
            continue;
          }
          // the force of the wall on each phase: the friction of its condition, or
          // the viscous traction where the phase takes the wall's velocity
          const Tensor<2, dim> tau_g =
              viscous (grad_u_g[q], (1 - a_s) * pp.gas_viscosity, 0.0);
          for (const Phase phase : {Phase::gas, Phase::solids})
          {
            const WallCondition &condition = s.wall_conditions.at (id, phase);
            double &force = phase == Phase::gas ? forces.gas_wall : forces.solids_wall;
            if (condition.has_friction ())
            {
              Tensor<1, dim> slip =
                  (phase == Phase::gas ? u_g[q] : u_s[q]) -
                  (s.boundaries.is (id, BoundaryType::moving_wall) ? wall_velocity
                                                                   : Tensor<1, dim> ());
              slip -= (slip * n) * n;
              force += -condition.friction ({a_s, theta_q[q]}) * (slip * up) * JxW;
            }
            else if (condition.prescribes_velocity ())
              force += ((phase == Phase::gas ? tau_g : tau_s) * n) * up * JxW;
          }
        }
      }
    ++alpha_cell;
  }
  forces.solids_wall = Utilities::MPI::sum (forces.solids_wall, s.communicator);
  forces.gas_wall    = Utilities::MPI::sum (forces.gas_wall, s.communicator);
  forces.distributor = Utilities::MPI::sum (forces.distributor, s.communicator);
  forces.outlet      = Utilities::MPI::sum (forces.outlet, s.communicator);
  return forces;
}

template WallForces evaluate_wall_forces (const SolverState<2> &);
template WallForces evaluate_wall_forces (const SolverState<3> &);
} // namespace wetbed
