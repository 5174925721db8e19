#include <wetbed/postprocess/bed_profile.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace wetbed
{
using namespace dealii;

namespace
{
/** alpha_s and p' at `bed monitors/point probes`: the owner of the cell around the point
 * evaluates, the others add 0 (a point on a partition boundary is found by two ranks:
 * averaged). */
template <int dim>
void evaluate_point_probes (const SolverState<dim> &s, MonitorRow &row)
{
  const auto                      &bed = s.parameters.bed_monitors;
  const FEValuesExtractors::Scalar pressure (2 * dim);
  row.probe_alpha.assign (bed.point_probes.size (), 0.0);
  row.probe_pressure.assign (bed.point_probes.size (), 0.0);
  std::vector<double> found (bed.point_probes.size (), 0.0);
  for (unsigned int i = 0; i < bed.point_probes.size (); ++i)
  {
    Point<dim> point;
    for (unsigned int d = 0; d < dim; ++d)
      point[d] = bed.point_probes[i][d];
    for (const auto &cell : s.alpha_dof_handler.active_cell_iterators ())
      if (cell->is_locally_owned () && cell->point_inside (point))
      {
        const Point<dim>      unit = s.mapping.transform_real_to_unit_cell (cell, point);
        const Quadrature<dim> at_point (GeometryInfo<dim>::project_to_unit_cell (unit));
        FEValues<dim>         a_point (s.mapping, s.alpha_fe, at_point, update_values);
        FEValues<dim>         p_point (s.mapping, s.flow_fe, at_point, update_values);
        a_point.reinit (cell);
        p_point.reinit (typename DoFHandler<dim>::active_cell_iterator (
            &s.triangulation, cell->level (), cell->index (), &s.flow_dof_handler));
        std::vector<double> a (1), p (1);
        a_point.get_function_values (s.alpha, a);
        p_point[pressure].get_function_values (s.flow_solution, p);
        row.probe_alpha[i]    = a[0];
        row.probe_pressure[i] = p[0];
        found[i]              = 1;
        break;
      }
  }
  Utilities::MPI::sum (found, s.communicator, found);
  Utilities::MPI::sum (row.probe_alpha, s.communicator, row.probe_alpha);
  Utilities::MPI::sum (row.probe_pressure, s.communicator, row.probe_pressure);
  for (unsigned int i = 0; i < found.size (); ++i)
    if (found[i] > 1)
    {
      row.probe_alpha[i] /= found[i];
      row.probe_pressure[i] /= found[i];
    }
}
} // namespace

/**
 * The height-resolved monitors: alpha_s (and p') averaged over the cell layer that
 * contains each probe plane and each plane of `bed monitors/pressure drop between`
 * (the cells straddling the height, volume-weighted); the bed surface, the top of the
 * highest of 200 horizontal slices (quadrature points binned by height) whose mean
 * alpha_s exceeds `surface solids fraction`; and alpha_s, p' at the point probes.
 * Heights are along -g from the coordinate origin (the inlet plane of the shipped
 * meshes).
 */
template <int dim>
void evaluate_bed_profile (const SolverState<dim> &s, MonitorRow &row)
{
  const auto          &pp     = s.parameters.physical;
  const Tensor<1, dim> up     = upward_direction<dim> (pp.gravity);
  const auto          &bed    = s.parameters.bed_monitors;
  std::vector<double>  planes = s.parameters.output.probe_heights;
  planes.insert (
      planes.end (), bed.pressure_drop_planes.begin (), bed.pressure_drop_planes.end ());

  // the extent of the domain along `up`, for the slices
  double bottom = std::numeric_limits<double>::max (), top = -bottom;
  for (const auto &cell : s.triangulation.active_cell_iterators ())
    if (cell->is_locally_owned ())
      for (const unsigned int v : cell->vertex_indices ())
      {
        bottom = std::min (bottom, cell->vertex (v) * up);
        top    = std::max (top, cell->vertex (v) * up);
      }
  bottom                          = Utilities::MPI::min (bottom, s.communicator);
  top                             = Utilities::MPI::max (top, s.communicator);
  constexpr unsigned int n_slices = 200;
  const double           slice    = (top - bottom) / n_slices;

  const QGauss<dim>                quadrature (2);
  const FEValuesExtractors::Scalar pressure (2 * dim);
  FEValues<dim>                    alpha_values (s.mapping,
                              s.alpha_fe,
                              quadrature,
                              update_values | update_JxW_values |
                                  update_quadrature_points);
  FEValues<dim>       flow_values (s.mapping, s.flow_fe, quadrature, update_values);
  std::vector<double> a_q (quadrature.size ()), p_q (quadrature.size ());
  // per plane: integral of alpha_s, of p', volume; then per slice: alpha_s, volume
  std::vector<double> sums (3 * planes.size () + 2 * n_slices, 0.0);
  auto                flow_cell = s.flow_dof_handler.begin_active ();
  for (const auto &cell : s.alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      alpha_values.reinit (cell);
      alpha_values.get_function_values (s.alpha, a_q);
      double lowest = std::numeric_limits<double>::max (), highest = -lowest;
      for (const unsigned int v : cell->vertex_indices ())
      {
        lowest  = std::min (lowest, cell->vertex (v) * up);
        highest = std::max (highest, cell->vertex (v) * up);
      }
      bool pressure_evaluated = false;
      for (unsigned int k = 0; k < planes.size (); ++k)
        if (lowest <= planes[k] && planes[k] < highest)
        {
          if (!pressure_evaluated)
          {
            flow_values.reinit (flow_cell);
            flow_values[pressure].get_function_values (s.flow_solution, p_q);
            pressure_evaluated = true;
          }
          for (unsigned int q = 0; q < quadrature.size (); ++q)
          {
            sums[3 * k] += a_q[q] * alpha_values.JxW (q);
            sums[3 * k + 1] += p_q[q] * alpha_values.JxW (q);
            sums[3 * k + 2] += alpha_values.JxW (q);
          }
        }
      for (unsigned int q = 0; q < quadrature.size (); ++q)
      {
        const unsigned int s = std::min<unsigned int> (
            (alpha_values.quadrature_point (q) * up - bottom) / slice, n_slices - 1);
        sums[3 * planes.size () + 2 * s] += a_q[q] * alpha_values.JxW (q);
        sums[3 * planes.size () + 2 * s + 1] += alpha_values.JxW (q);
      }
    }
    ++flow_cell;
  }
  Utilities::MPI::sum (sums, s.communicator, sums);

  const auto average = [&] (const unsigned int k, const unsigned int which)
  { return sums[3 * k + 2] > 0 ? sums[3 * k + which] / sums[3 * k + 2] : 0.0; };
  const unsigned int n_probes = s.parameters.output.probe_heights.size ();
  row.plane_alpha.resize (n_probes);
  for (unsigned int k = 0; k < n_probes; ++k)
    row.plane_alpha[k] = average (k, 0);
  row.plane_pressure_drop.clear ();
  if (bed.pressure_drop_planes.size () == 2)
    row.plane_pressure_drop.push_back (average (n_probes, 1) - average (n_probes + 1, 1));
  row.bed_surface_height = 0;
  for (unsigned int s = 0; s < n_slices; ++s)
  {
    const double *slice_sums = &sums[3 * planes.size () + 2 * s];
    if (slice_sums[1] > 0 && slice_sums[0] > bed.surface_solids_fraction * slice_sums[1])
      row.bed_surface_height = bottom + (s + 1) * slice;
  }
  const double initial_height = s.parameters.initial.bed_height;
  row.expansion_ratio = initial_height > 0 ? row.bed_surface_height / initial_height : 0;
  evaluate_point_probes (s, row);
}

template void evaluate_bed_profile (const SolverState<2> &, MonitorRow &);
template void evaluate_bed_profile (const SolverState<3> &, MonitorRow &);
} // namespace wetbed
