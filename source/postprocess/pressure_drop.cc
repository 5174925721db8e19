#include <wetbed/postprocess/pressure_drop.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace wetbed
{
using namespace dealii;

template <int dim>
PressureDrop evaluate_pressure_drop (const SolverState<dim> &s, const double solids_mass)
{
  const QGauss<dim - 1> face_quadrature (3);
  FEFaceValues<dim>     face_values (
      s.mapping, s.flow_fe, face_quadrature, update_values | update_JxW_values);
  const FEValuesExtractors::Scalar pressure (2 * dim);
  std::vector<double>              p (face_quadrature.size ());
  // inlet integral, inlet area, outlet integral, outlet area
  std::array<double, 4> sums{{0, 0, 0, 0}};
  for (const auto &cell : s.flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
      for (const auto &face : cell->face_iterators ())
        if (face->at_boundary ())
        {
          const bool inlet = s.boundaries.is (face->boundary_id (), BoundaryType::inlet);
          if (!inlet && !s.boundaries.is (face->boundary_id (), BoundaryType::outlet))
            continue;
          face_values.reinit (cell, face);
          face_values[pressure].get_function_values (s.flow_solution, p);
          const unsigned int k = inlet ? 0 : 2;
          for (unsigned int q = 0; q < face_quadrature.size (); ++q)
          {
            sums[k] += p[q] * face_values.JxW (q);
            sums[k + 1] += face_values.JxW (q);
          }
        }
  for (double &sum : sums)
    sum = Utilities::MPI::sum (sum, s.communicator);
  PressureDrop result;
  result.inlet_area = sums[1];
  if (sums[3] > 0)
    result.outlet_pressure = sums[2] / sums[3];
  if (sums[1] > 0 && sums[3] > 0)
    result.pressure_drop = sums[0] / sums[1] - sums[2] / sums[3];
  const auto  &pp = s.parameters.physical;
  const double weight =
      solids_mass * (1 - pp.gas_density / pp.particle_density) * pp.gravity.norm ();
  result.fluidization =
      weight > 0 ? result.pressure_drop * result.inlet_area / weight : 0;
  return result;
}

template PressureDrop evaluate_pressure_drop (const SolverState<2> &, double);
template PressureDrop evaluate_pressure_drop (const SolverState<3> &, double);
} // namespace wetbed
