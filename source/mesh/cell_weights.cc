#include <wetbed/mesh/cell_weights.h>

#include <cmath>

namespace wetbed
{
template <int dim>
unsigned int weighted_boundary_faces (
    const typename dealii::Triangulation<dim>::cell_iterator &cell,
    const std::function<bool (dealii::types::boundary_id)>   &is_weighted_boundary)
{
  unsigned int faces = 0;
  for (const auto f : cell->face_indices ())
    if (cell->at_boundary (f) && is_weighted_boundary (cell->face (f)->boundary_id ()))
      ++faces;
  return faces;
}

namespace
{
/** The weight of one cell, in thousandths of a plain cell. */
template <int dim>
unsigned int
cell_weight (const typename dealii::Triangulation<dim>::cell_iterator &cell,
             const typename dealii::Triangulation<dim>::CellStatus     status,
             const double                                              wall_face_weight,
             const std::function<bool (dealii::types::boundary_id)> &is_weighted_boundary)
{
  const unsigned int wall_faces =
      weighted_boundary_faces<dim> (cell, is_weighted_boundary);
  // refinement: the signal is called once per child with the parent
  const double faces = status == dealii::Triangulation<dim>::CELL_REFINE
                           ? 0.5 * wall_faces
                           : static_cast<double> (wall_faces);
  return static_cast<unsigned int> (
      std::lround (1000.0 * (1.0 + wall_face_weight * faces)));
}
} // namespace

template <int dim>
boost::signals2::scoped_connection connect_cell_weights (
    dealii::Triangulation<dim>                      &triangulation,
    const double                                     wall_face_weight,
    std::function<bool (dealii::types::boundary_id)> is_weighted_boundary)
{
  if (wall_face_weight == 0)
    return {};
  return triangulation.signals.weight.connect (
      [wall_face_weight, is_weighted_boundary] (
          const typename dealii::Triangulation<dim>::cell_iterator &cell,
          const typename dealii::Triangulation<dim>::CellStatus     status) {
        return cell_weight<dim> (cell, status, wall_face_weight, is_weighted_boundary);
      });
}

template unsigned int
weighted_boundary_faces<2> (const dealii::Triangulation<2>::cell_iterator &,
                            const std::function<bool (dealii::types::boundary_id)> &);
template unsigned int
weighted_boundary_faces<3> (const dealii::Triangulation<3>::cell_iterator &,
                            const std::function<bool (dealii::types::boundary_id)> &);
template boost::signals2::scoped_connection connect_cell_weights<2> (
    dealii::Triangulation<2> &, double, std::function<bool (dealii::types::boundary_id)>);
template boost::signals2::scoped_connection connect_cell_weights<3> (
    dealii::Triangulation<3> &, double, std::function<bool (dealii::types::boundary_id)>);
} // namespace wetbed
