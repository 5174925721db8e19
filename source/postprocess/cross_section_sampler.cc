#include <wetbed/postprocess/cross_section_sampler.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <cmath>
#include <limits>

namespace wetbed
{
using namespace dealii;

template <int dim>
CrossSectionSampler<dim>::CrossSectionSampler (const std::vector<double> &heights,
                                               const unsigned int         resolution)
    : heights (heights), resolution (resolution),
      per_height (dim == 3 ? resolution * resolution : resolution)
{
}

template <int dim>
void CrossSectionSampler<dim>::locate (const SolverState<dim> &s)
{
  // the vertical axis is the coordinate axis gravity points along (the meshes are
  // checked for it); the others span the pixels
  const Tensor<1, dim> up       = upward_direction<dim> (s.parameters.physical.gravity);
  unsigned int         vertical = 0;
  for (unsigned int d = 1; d < dim; ++d)
    if (std::abs (up[d]) > std::abs (up[vertical]))
      vertical = d;
  std::vector<unsigned int> across;
  for (unsigned int d = 0; d < dim; ++d)
    if (d != vertical)
      across.push_back (d);
  const auto box = GridTools::compute_bounding_box (s.triangulation);
  Point<dim> lo  = box.get_boundary_points ().first,
             hi  = box.get_boundary_points ().second;
  for (unsigned int d = 0; d < dim; ++d)
  {
    lo[d] = Utilities::MPI::min (lo[d], s.communicator);
    hi[d] = Utilities::MPI::max (hi[d], s.communicator);
  }
  std::vector<Point<dim>> where;
  where.reserve (heights.size () * per_height);
  for (const double height : heights)
    for (unsigned int k = 0; k < per_height; ++k)
    {
      Point<dim> p;
      p[vertical]                 = height * up[vertical];
      const unsigned int index[2] = {k % resolution, k / resolution};
      for (unsigned int a = 0; a < across.size (); ++a)
        p[across[a]] = lo[across[a]] +
                       (index[a] + 0.5) * (hi[across[a]] - lo[across[a]]) / resolution;
      where.push_back (p);
    }
  points.reinit (where, s.triangulation, s.mapping);
  found.resize (where.size ());
  for (unsigned int i = 0; i < where.size (); ++i)
    found[i] = points.point_found (i);
}

template <int dim>
std::vector<double> CrossSectionSampler<dim>::alpha_s (const SolverState<dim> &s)
{
  if (!points.is_ready ())
    locate (s);
  std::vector<double> values =
      VectorTools::point_values<1> (points, s.alpha_dof_handler, s.alpha);
  for (unsigned int i = 0; i < values.size (); ++i)
    if (!found[i])
      values[i] = std::numeric_limits<double>::quiet_NaN ();
  return values;
}

template <int dim>
std::vector<double> CrossSectionSampler<dim>::pressure (const SolverState<dim> &s)
{
  if (!points.is_ready ())
    locate (s);
  const auto flow = VectorTools::point_values<2 * dim + 1> (
      points, s.flow_dof_handler, s.flow_solution);
  std::vector<double> values (flow.size ());
  for (unsigned int i = 0; i < values.size (); ++i)
    values[i] = found[i] ? flow[i][2 * dim] : std::numeric_limits<double>::quiet_NaN ();
  return values;
}

template <int dim>
double CrossSectionSampler<dim>::mean (const std::vector<double> &values)
{
  double       sum   = 0;
  unsigned int count = 0;
  for (const double v : values)
    if (!std::isnan (v))
    {
      sum += v;
      ++count;
    }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN ();
}

template class CrossSectionSampler<2>;
template class CrossSectionSampler<3>;
} // namespace wetbed
