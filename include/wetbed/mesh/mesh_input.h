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
 * the gmsh executable, run without a shell, into a temporary file of `output_folder`
 * that becomes mesh.msh only once the mesh is accepted), checks that it is all
 * quadrilaterals/hexahedra, that the refinement fits the memory and the case fits it
 * (parameters.checks: gravity, heights, probes), maps the physical-group names of
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

/**
 * While an object of this class lives, read_mesh() leaves the mesh it generated from a
 * .geo pending (a temporary file, not yet mesh.msh) until commit(): the application
 * commits once the solver has accepted the whole case, so that a check made after the
 * mesh is read (the moving wall velocity, the dofs) still leaves a previous run's
 * mesh.msh byte-identical. Destroyed uncommitted, it removes the pending mesh. Without
 * one, read_mesh() commits the accepted mesh itself. commit() is collective.
 */
class DeferredMeshCommit
{
public:
  DeferredMeshCommit ();
  ~DeferredMeshCommit ();
  DeferredMeshCommit (const DeferredMeshCommit &)            = delete;
  DeferredMeshCommit &operator= (const DeferredMeshCommit &) = delete;
  void                commit ();
  /** Removes the pending mesh (the case was refused). */
  void discard ();
};

/**
 * The mesh file of `mesh/file` resolved against `parameter_directory`: an existing
 * .geo or .msh, else an InputError naming `mesh/file` (checked before the output
 * folder is created).
 */
std::string check_mesh_file (const MeshParameters &parameters,
                             const std::string    &parameter_directory);

/** Resolves `file` relative to `directory` unless it is absolute. */
std::string resolve_path (const std::string &file, const std::string &directory);
} // namespace wetbed
