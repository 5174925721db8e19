#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/mesh/boundaries.h>

#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <string>

namespace wetbed
{
/**
 * Reads the gmsh mesh named in `mesh/file` into `triangulation` (meshing a .geo with
 * the gmsh executable into `output_folder` first), maps the physical-group names of
 * `mesh/inlet`, `outlet`, `wall`, `periodic boundaries` (and `moving_wall_name`, unless
 * empty) to boundary groups, one per name, makes the periodic boundaries
 * periodic, attaches manifolds and refines. Throws InputError naming the parameter or
 * file on failure.
 */
template <int dim>
Boundaries read_mesh (const MeshParameters       &parameters,
                      const std::string          &moving_wall_name,
                      const std::string          &parameter_directory,
                      const std::string          &output_folder,
                      const dealii::Tensor<1, 3> &gravity,
                      dealii::parallel::distributed::Triangulation<dim> &triangulation);

/** Resolves `file` relative to `directory` unless it is absolute. */
std::string resolve_path (const std::string &file, const std::string &directory);
} // namespace wetbed
