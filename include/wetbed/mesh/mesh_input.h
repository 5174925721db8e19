#pragma once

#include <wetbed/core/parameters.h>

#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <string>

namespace wetbed
{
/** Boundary ids of the physical groups the solver uses. */
struct BoundaryIds
{
  dealii::types::boundary_id inlet, outlet, wall;
};

/**
 * Reads the gmsh mesh named in `mesh/file` into `triangulation` (meshing a .geo with
 * the gmsh executable into `output_folder` first), maps physical-group names to
 * boundary ids, attaches manifolds and refines. Throws InputError naming the
 * parameter or file on failure.
 */
template <int dim>
BoundaryIds read_mesh (const MeshParameters       &parameters,
                       const std::string          &parameter_directory,
                       const std::string          &output_folder,
                       const dealii::Tensor<1, 3> &gravity,
                       dealii::parallel::distributed::Triangulation<dim> &triangulation);

/** Resolves `file` relative to `directory` unless it is absolute. */
std::string resolve_path (const std::string &file, const std::string &directory);
} // namespace wetbed
