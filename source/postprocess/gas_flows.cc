#include <wetbed/postprocess/gas_flows.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace wetbed
{
using namespace dealii;

template <int dim>
GasFlows evaluate_gas_flows (const SolverState<dim> &s)
{
  const QGauss<dim - 1> quadrature (s.flow_fe.degree + 1);
  FEFaceValues<dim>     flow_values (s.mapping,
                                 s.flow_fe,
                                 quadrature,
                                 update_values | update_JxW_values |
                                     update_normal_vectors);
  FEFaceValues<dim>     alpha_values (s.mapping, s.alpha_fe, quadrature, update_values);
  const FEValuesExtractors::Vector gas (0);
  std::vector<Tensor<1, dim>>      u (quadrature.size ());
  std::vector<double>              alpha (quadrature.size ());
  double                           flows[2]   = {0, 0}; // in, out
  auto                             alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned () && cell->at_boundary ())
      for (const unsigned int f : cell->face_indices ())
      {
        if (!cell->face (f)->at_boundary ())
          continue;
        const auto id    = cell->face (f)->boundary_id ();
        const bool inlet = s.boundaries.is (id, BoundaryType::inlet);
        if (!inlet && !s.boundaries.is (id, BoundaryType::outlet))
          continue;
        flow_values.reinit (cell, f);
        alpha_values.reinit (alpha_cell, f);
        flow_values[gas].get_function_values (s.flow_solution, u);
        alpha_values.get_function_values (s.alpha, alpha);
        for (unsigned int q = 0; q < quadrature.size (); ++q)
        {
          const double outward = (1 - alpha[q]) * (u[q] * flow_values.normal_vector (q)) *
                                 flow_values.JxW (q);
          flows[inlet ? 0 : 1] += inlet ? -outward : outward;
        }
      }
    ++alpha_cell;
  }
  const double rho = s.parameters.physical.gas_density;
  return {rho * Utilities::MPI::sum (flows[0], s.communicator),
          rho * Utilities::MPI::sum (flows[1], s.communicator)};
}

template GasFlows evaluate_gas_flows (const SolverState<2> &);
template GasFlows evaluate_gas_flows (const SolverState<3> &);
} // namespace wetbed
