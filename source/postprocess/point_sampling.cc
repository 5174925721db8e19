#include <wetbed/postprocess/point_sampling.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <limits>

/*
 * The fields at given points, for profiles and verification: each point is evaluated by
 * the rank that owns the cell around it and the values are summed over all ranks.
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
std::vector<std::vector<double>> sample_fields (const SolverState<dim>        &s,
                                                const std::vector<Point<dim>> &points)
{
  const Mapping<dim>       &mapping           = s.mapping;
  const FiniteElement<dim> &flow_fe           = s.flow_fe;
  const FiniteElement<dim> &alpha_fe          = s.alpha_fe;
  const DoFHandler<dim>    &flow_dof_handler  = s.flow_dof_handler;
  const DoFHandler<dim>    &alpha_dof_handler = s.alpha_dof_handler;
  const unsigned int        n_values = 2 * dim + 3; // u_g, u_s, p', alpha_s, Theta
  std::vector<double>       values (points.size () * n_values, 0.0),
      found (points.size (), 0.0);
  for (unsigned int k = 0; k < points.size (); ++k)
  {
    std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>> cell_point;
    try
    {
      cell_point =
          GridTools::find_active_cell_around_point (mapping, flow_dof_handler, points[k]);
    }
    catch (...)
    {
      continue; // not in this rank's part of the mesh
    }
    const auto &flow_cell = cell_point.first;
    if (flow_cell.state () != IteratorState::valid || !flow_cell->is_locally_owned ())
      continue;
    const Quadrature<dim> at_point (cell_point.second);
    FEValues<dim>         flow_values (mapping, flow_fe, at_point, update_values);
    FEValues<dim>         alpha_values (mapping, alpha_fe, at_point, update_values);
    flow_values.reinit (flow_cell);
    alpha_values.reinit (typename DoFHandler<dim>::active_cell_iterator (
        &s.triangulation, flow_cell->level (), flow_cell->index (), &alpha_dof_handler));
    std::vector<double>         scalar (1);
    std::vector<Vector<double>> flow_at (1, Vector<double> (2 * dim + 1));
    flow_values.get_function_values (s.flow_solution, flow_at);
    for (unsigned int c = 0; c < 2 * dim + 1; ++c)
      values[k * n_values + c] = flow_at[0][c];
    alpha_values.get_function_values (s.alpha, scalar);
    values[k * n_values + 2 * dim + 1] = scalar[0];
    alpha_values.get_function_values (s.theta, scalar);
    values[k * n_values + 2 * dim + 2] = scalar[0];
    found[k]                           = 1.0;
  }
  Utilities::MPI::sum (values, s.communicator, values);
  Utilities::MPI::sum (found, s.communicator, found);
  std::vector<std::vector<double>> result (points.size ());
  for (unsigned int k = 0; k < points.size (); ++k)
  {
    result[k].assign (values.begin () + k * n_values,
                      values.begin () + (k + 1) * n_values);
    // a point on a partition boundary may be owned twice: average; outside: NaN
    for (double &v : result[k])
      v = found[k] > 0 ? v / found[k] : std::numeric_limits<double>::quiet_NaN ();
  }
  return result;
}

template std::vector<std::vector<double>> sample_fields (const SolverState<2> &,
                                                         const std::vector<Point<2>> &);
template std::vector<std::vector<double>> sample_fields (const SolverState<3> &,
                                                         const std::vector<Point<3>> &);
} // namespace wetbed
