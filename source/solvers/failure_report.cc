#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <sstream>

/*
 * What a user needs when the time step cannot be made small enough: the cause of the
 * last rejection and, in the state that failed, where the solids fraction, the granular
 * temperature and the velocities are extreme (or not finite), with the solids-stress
 * closures at the worst alpha_s node.
 */
namespace wetbed
{
using namespace dealii;

namespace
{
/** (value, x, y, z) of the extreme over all ranks: the largest of `sign` * value. */
std::array<double, 4> global_extreme (const std::array<double, 4> &local,
                                      const double                 sign,
                                      const MPI_Comm               communicator)
{
  std::array<double, 4> best = local;
  for (const auto &other : Utilities::MPI::all_gather (communicator, local))
    if (sign * other[0] > sign * best[0] ||
        (std::isnan (other[0]) && !std::isnan (best[0])))
      best = other;
  return best;
}

std::string
at (const std::array<double, 4> &e, const unsigned int dim, const std::string &unit = "")
{
  std::ostringstream s;
  s << e[0] << unit << " at (" << e[1];
  for (unsigned int d = 1; d < dim; ++d)
    s << ", " << e[1 + d];
  s << ") m";
  return s.str ();
}
} // namespace

template <int dim>
std::string TwoFluidSolver<dim>::describe_failed_state (const double       dt,
                                                        const std::string &where) const
{
  const double          big = std::numeric_limits<double>::max ();
  std::array<double, 4> alpha_lo{{big, 0, 0, 0}}, alpha_hi{{-big, 0, 0, 0}},
      theta_lo{{big, 0, 0, 0}}, theta_hi{{-big, 0, 0, 0}}, ug{{-big, 0, 0, 0}},
      us{{-big, 0, 0, 0}};
  double theta_at_alpha_hi = 0;
  auto record = [] (std::array<double, 4> &e, double v, const Point<dim> &x, double sign)
  {
    if (sign * v > sign * e[0] || (std::isnan (v) && !std::isnan (e[0])))
    {
      e[0] = v;
      for (unsigned int d = 0; d < dim; ++d)
        e[1 + d] = x[d];
    }
  };
  std::vector<types::global_dof_index> dofs (alpha_fe.n_dofs_per_cell ());
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      for (const unsigned int v : cell->vertex_indices ())
      {
        const double a = fields.alpha (dofs[v]), t = fields.theta (dofs[v]);
        if (a > alpha_hi[0] || std::isnan (a))
          theta_at_alpha_hi = t;
        record (alpha_lo, a, cell->vertex (v), -1);
        record (alpha_hi, a, cell->vertex (v), 1);
        record (theta_lo, t, cell->vertex (v), -1);
        record (theta_hi, t, cell->vertex (v), 1);
      }
    }
  // velocities at the cell centres
  const QMidpoint<dim> centre;
  FEValues<dim>        values (
      mapping, flow_fe, centre, update_values | update_quadrature_points);
  std::vector<Tensor<1, dim>>      u (1);
  const FEValuesExtractors::Vector gas (0), solids (dim);
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      values.reinit (cell);
      values[gas].get_function_values (fields.flow, u);
      record (ug, u[0].norm (), values.quadrature_point (0), 1);
      values[solids].get_function_values (fields.flow, u);
      record (us, u[0].norm (), values.quadrature_point (0), 1);
    }
  const auto worst_alpha = global_extreme (alpha_hi, 1, communicator);
  // the Theta at that node travels with it: the rank that owns it says
  const double theta_there = Utilities::MPI::max (
      worst_alpha == alpha_hi ? theta_at_alpha_hi : -big, communicator);

  std::ostringstream report;
  report << "wetbed failure report\n"
         << "time " << stepping.time << " s, step " << stepping.step_number
         << ", last attempted dt " << dt
         << " s (time stepping/minimum time step = " << parameters.time.minimum_time_step
         << " s)\n"
         << "cause of the last rejection: " << rejection_reason << "\n"
         << where << "in the state that failed:\n"
         << "  alpha_s min " << at (global_extreme (alpha_lo, -1, communicator), dim)
         << "\n  alpha_s max " << at (worst_alpha, dim) << " (maximum packing "
         << parameters.physical.maximum_packing << ")\n"
         << "  Theta min "
         << at (global_extreme (theta_lo, -1, communicator), dim, " m^2/s^2")
         << "\n  Theta max "
         << at (global_extreme (theta_hi, 1, communicator), dim, " m^2/s^2")
         << "\n  |u_g| max " << at (global_extreme (ug, 1, communicator), dim, " m/s")
         << " (cell centres)\n  |u_s| max "
         << at (global_extreme (us, 1, communicator), dim, " m/s") << " (cell centres)\n";
  if (std::isfinite (worst_alpha[0]))
  {
    const auto stress = closure_evaluator.stress (
        std::min (worst_alpha[0], parameters.physical.maximum_packing), theta_there, 0.0);
    report << "closures at the alpha_s max node (Theta " << theta_there
           << ", zero shear): P_s " << stress.pressure << " Pa, dP_s/dalpha "
           << stress.pressure_derivative << " Pa, mu_s " << stress.shear_viscosity
           << " Pa s, frictional mu " << stress.frictional_viscosity << " Pa s, wet mu "
           << stress.wet_viscosity << " Pa s\n";
  }
  report << solve_history.describe ();
  report << "the last accepted state (t = " << stepping.time << " s, step "
         << stepping.step_number
         << ") is in checkpoint/ (resume with --resume after changing the case) and in "
            "the last field output\n";
  return report.str ();
}

template std::string TwoFluidSolver<2>::describe_failed_state (double,
                                                               const std::string &) const;
template std::string TwoFluidSolver<3>::describe_failed_state (double,
                                                               const std::string &) const;
} // namespace wetbed
