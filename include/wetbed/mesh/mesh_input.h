#pragma once

#include <wetbed/core/parameters.h>

#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <set>
#include <string>

namespace wetbed
{
/** Boundary ids of the physical groups the solver uses; invalid_boundary_id (never
 * the id of a boundary face) for those the case does not have. */
struct BoundaryIds
{
  static constexpr dealii::types::boundary_id none = dealii::numbers::invalid_boundary_id;
  dealii::types::boundary_id                  inlet = none, outlet = none, wall = none;
  dealii::types::boundary_id                  moving_wall  = none; // slides tangentially
  dealii::types::boundary_id                  periodic_low = none, periodic_high = none;

  /** The fixed or the moving wall. */
  bool is_wall (const dealii::types::boundary_id id) const
  {
    return id != none && (id == wall || id == moving_wall);
  }
  std::set<dealii::types::boundary_id> walls () const
  {
    std::set<dealii::types::boundary_id> ids{wall};
    if (moving_wall != none)
      ids.insert (moving_wall);
    return ids;
  }
};

/**
 * Reads the gmsh mesh named in `mesh/file` into `triangulation` (meshing a .geo with
 * the gmsh executable into `output_folder` first), maps physical-group names to
 * boundary ids (`moving_wall_name` too, unless empty), makes the periodic boundaries
 * periodic, attaches manifolds and refines. Throws InputError naming the parameter or
 * file on failure.
 */
template <int dim>
BoundaryIds read_mesh (const MeshParameters       &parameters,
                       const std::string          &moving_wall_name,
                       const std::string          &parameter_directory,
                       const std::string          &output_folder,
                       const dealii::Tensor<1, 3> &gravity,
                       dealii::parallel::distributed::Triangulation<dim> &triangulation);

/** Resolves `file` relative to `directory` unless it is absolute. */
std::string resolve_path (const std::string &file, const std::string &directory);
} // namespace wetbed
