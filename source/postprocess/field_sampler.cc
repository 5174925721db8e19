#include <wetbed/postprocess/field_sampler.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <cmath>
#include <limits>

namespace wetbed
{
using namespace dealii;

template <int dim>
Point<dim> HorizontalFrame<dim>::at (const double               height,
                                     const std::vector<double> &horizontal) const
{
  Point<dim> p;
  p[vertical] = height * up;
  for (unsigned int a = 0; a < across.size (); ++a)
    p[across[a]] = horizontal[a];
  return p;
}

template <int dim>
HorizontalFrame<dim> horizontal_frame (const SolverState<dim> &s)
{
  // the meshes are checked to have gravity along a coordinate axis
  const Tensor<1, dim> g = upward_direction<dim> (s.parameters.physical.gravity);
  HorizontalFrame<dim> frame;
  frame.vertical = 0;
  for (unsigned int d = 1; d < dim; ++d)
    if (std::abs (g[d]) > std::abs (g[frame.vertical]))
      frame.vertical = d;
  frame.up = g[frame.vertical] > 0 ? 1 : -1;
  for (unsigned int d = 0; d < dim; ++d)
    if (d != frame.vertical)
      frame.across.push_back (d);
  const auto box = GridTools::compute_bounding_box (s.triangulation);
  for (unsigned int d = 0; d < dim; ++d)
  {
    frame.lower[d] =
        Utilities::MPI::min (box.get_boundary_points ().first[d], s.communicator);
    frame.upper[d] =
        Utilities::MPI::max (box.get_boundary_points ().second[d], s.communicator);
  }
  return frame;
}

template <int dim>
FieldSampler<dim>::FieldSampler (Locator where) : where (std::move (where))
{
}

template <int dim>
void FieldSampler<dim>::locate (const SolverState<dim> &s)
{
  located = where (s);
  evaluated.clear ();
  // (a locator that returns another number of points is located afresh)
  located_before = located_before && located.size () == found.size ();
  if (located_before)
    evaluated = inside;
  else
    for (unsigned int i = 0; i < located.size (); ++i)
      evaluated.push_back (i);
  std::vector<Point<dim>> points;
  for (const unsigned int i : evaluated)
    points.push_back (located[i]);
  evaluation.reinit (points, s.triangulation, s.mapping);
  found.assign (located.size (), false);
  for (unsigned int j = 0; j < evaluated.size (); ++j)
    found[evaluated[j]] = evaluation.point_found (j);
  if (!located_before)
  {
    inside.clear ();
    for (unsigned int i = 0; i < located.size (); ++i)
      if (found[i])
        inside.push_back (i);
  }
  located_before = true;
}

template <int dim>
template <typename Value>
std::vector<Value> FieldSampler<dim>::expand (const std::vector<Value> &values,
                                              const Value              &nan) const
{
  std::vector<Value> all (located.size (), nan);
  for (unsigned int j = 0; j < evaluated.size (); ++j)
    if (found[evaluated[j]])
      all[evaluated[j]] = values[j];
  return all;
}

template <int dim>
const std::vector<Point<dim>> &FieldSampler<dim>::points (const SolverState<dim> &s)
{
  // RemotePointEvaluation forgets the points when the triangulation changes
  if (!evaluation.is_ready ())
    locate (s);
  return located;
}

template <int dim>
std::vector<double> FieldSampler<dim>::scalar (const SolverState<dim> &s,
                                               const AlphaVector      &field)
{
  points (s);
  return expand (VectorTools::point_values<1> (evaluation, s.alpha_dof_handler, field),
                 std::numeric_limits<double>::quiet_NaN ());
}

template <int dim>
std::vector<typename FieldSampler<dim>::FlowValue>
FieldSampler<dim>::flow (const SolverState<dim> &s, const BlockVector &field)
{
  points (s);
  FlowValue nan;
  for (unsigned int c = 0; c < 2 * dim + 1; ++c)
    nan[c] = std::numeric_limits<double>::quiet_NaN ();
  return expand (
      VectorTools::point_values<2 * dim + 1> (evaluation, s.flow_dof_handler, field),
      nan);
}

template struct HorizontalFrame<2>;
template struct HorizontalFrame<3>;
template HorizontalFrame<2> horizontal_frame (const SolverState<2> &);
template HorizontalFrame<3> horizontal_frame (const SolverState<3> &);
template class FieldSampler<2>;
template class FieldSampler<3>;
} // namespace wetbed
