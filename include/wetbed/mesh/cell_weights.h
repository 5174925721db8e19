#pragma once

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <boost/signals2/connection.hpp>

#include <functional>

namespace wetbed
{
/** The faces of `cell` on a boundary for which `is_weighted_boundary` holds. */
template <int dim>
unsigned int weighted_boundary_faces (
    const typename dealii::Triangulation<dim>::cell_iterator &cell,
    const std::function<bool (dealii::types::boundary_id)>   &is_weighted_boundary);

/**
 * Load balancing by cost: connects a cost model to the triangulation's `weight`
 * signal, which p4est's partitioning sums and balances over the MPI ranks (at the
 * start and at every adaptation). A cell costs 1, plus `wall_face_weight` for each of
 * its faces on a boundary for which `is_weighted_boundary` holds (walls, whose face
 * integrals the assembly adds). A cell about to be refined hands each child half its
 * parent's wall faces (each face splits into 2^(dim-1) of 2^dim children), a family
 * about to be coarsened is weighed as its parent. With wall_face_weight = 0 nothing is
 * connected and the cells are balanced by count. The returned connection is
 * disconnected when it goes out of scope.
 */
template <int dim>
boost::signals2::scoped_connection connect_cell_weights (
    dealii::Triangulation<dim>                      &triangulation,
    double                                           wall_face_weight,
    std::function<bool (dealii::types::boundary_id)> is_weighted_boundary);
} // namespace wetbed
