#include <wetbed/core/input_error.h>
#include <wetbed/mesh/mesh_input.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace wetbed
{
namespace
{
/** Physical names of dimension `group_dim` in a MSH file: name -> tag. */
std::map<std::string, int> read_physical_names (const std::string &msh_file,
                                                const int          group_dim)
{
  std::ifstream              in (msh_file);
  std::map<std::string, int> names;
  std::string                line;
  while (std::getline (in, line))
    if (line.rfind ("$PhysicalNames", 0) == 0)
    {
      int count = 0;
      in >> count;
      for (int i = 0; i < count; ++i)
      {
        int         d, tag;
        std::string quoted;
        in >> d >> tag;
        std::getline (in, quoted);
        const auto first = quoted.find ('"'), last = quoted.rfind ('"');
        if (d == group_dim && first != std::string::npos && last > first)
          names[quoted.substr (first + 1, last - first - 1)] = tag;
      }
      break;
    }
  return names;
}

std::string
mesh_with_gmsh (const std::string &geo, const int dim, const std::string &output_folder)
{
  const std::string msh    = output_folder + "/mesh.msh";
  int               status = 0;
  if (dealii::Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0)
  {
    const std::string command = "gmsh -" + std::to_string (dim) + " -format msh41 \"" +
                                geo + "\" -o \"" + msh + "\" > \"" + output_folder +
                                "/gmsh.log\" 2>&1";
    status = std::system (command.c_str ());
  }
  status = dealii::Utilities::MPI::max (status, MPI_COMM_WORLD);
  require (status == 0,
           "mesh/file",
           "gmsh failed to mesh '" + geo + "' (see " + output_folder + "/gmsh.log)");
  return msh;
}
} // namespace

std::string resolve_path (const std::string &file, const std::string &directory)
{
  const std::filesystem::path path (file);
  if (path.is_absolute () || directory.empty ())
    return file;
  return (std::filesystem::path (directory) / path).lexically_normal ().string ();
}

template <int dim>
BoundaryIds read_mesh (const MeshParameters       &parameters,
                       const std::string          &moving_wall_name,
                       const std::string          &parameter_directory,
                       const std::string          &output_folder,
                       const dealii::Tensor<1, 3> &gravity,
                       dealii::parallel::distributed::Triangulation<dim> &triangulation)
{
  const std::string file = resolve_path (parameters.file, parameter_directory);
  require (std::filesystem::is_regular_file (file),
           "mesh/file",
           "file '" + file + "' not found");
  const std::string extension = std::filesystem::path (file).extension ().string ();
  require (extension == ".geo" || extension == ".msh",
           "mesh/file",
           "'" + file + "' is neither a .geo nor a .msh file");
  const std::string msh =
      extension == ".geo" ? mesh_with_gmsh (file, dim, output_folder) : file;

  const auto names = read_physical_names (msh, dim - 1);
  auto       id_of = [&] (const std::string &name, const std::string &parameter)
  {
    const auto it = names.find (name);
    require (it != names.end (),
             parameter,
             "physical group '" + name + "' is not in the mesh '" + msh + "'");
    return static_cast<dealii::types::boundary_id> (it->second);
  };
  BoundaryIds ids;
  if (!parameters.inlet_name.empty ())
    ids.inlet = id_of (parameters.inlet_name, "mesh/inlet");
  if (!parameters.outlet_name.empty ())
    ids.outlet = id_of (parameters.outlet_name, "mesh/outlet");
  ids.wall = id_of (parameters.wall_name, "mesh/wall");
  if (!parameters.periodic_low_name.empty ())
  {
    ids.periodic_low  = id_of (parameters.periodic_low_name, "mesh/periodic boundaries");
    ids.periodic_high = id_of (parameters.periodic_high_name, "mesh/periodic boundaries");
  }
  if (!moving_wall_name.empty ())
  {
    ids.moving_wall = id_of (moving_wall_name, "boundary conditions/moving wall");
    require (ids.moving_wall != ids.wall && ids.moving_wall != ids.inlet &&
                 ids.moving_wall != ids.outlet && ids.moving_wall != ids.periodic_low &&
                 ids.moving_wall != ids.periodic_high,
             "boundary conditions/moving wall",
             "'" + moving_wall_name + "' is already another boundary of the case");
  }

  dealii::GridIn<dim> grid_in (triangulation);
  std::ifstream       in (msh);
  try
  {
    grid_in.read_msh (in);
  }
  catch (const dealii::ExceptionBase &e)
  {
    throw InputError ("mesh/file", "cannot read '" + msh + "' as a gmsh quad/hex mesh");
  }

  if (parameters.cylindrical_wall)
  {
    require (dim == 3, "mesh/cylindrical wall", "needs a 3D mesh");
    if constexpr (dim == 3)
    {
      dealii::Tensor<1, 3> axis = gravity / gravity.norm ();
      const auto           box  = dealii::GridTools::compute_bounding_box (triangulation);
      const dealii::Point<3> centre = box.center ();
      triangulation.set_all_manifold_ids (2);
      triangulation.set_all_manifold_ids_on_boundary (ids.wall, 1);
      triangulation.set_manifold (1, dealii::CylindricalManifold<3> (axis, centre));
      dealii::TransfiniteInterpolationManifold<3> transfinite;
      transfinite.initialize (triangulation);
      triangulation.set_manifold (2, transfinite);
    }
  }
  if (ids.periodic_low != BoundaryIds::none)
  {
    std::vector<dealii::GridTools::PeriodicFacePair<
        typename dealii::parallel::distributed::Triangulation<dim>::cell_iterator>>
                      pairs;
    const std::string mismatch = "the faces of '" + parameters.periodic_high_name +
                                 "' are not those of '" + parameters.periodic_low_name +
                                 "' translated along the periodic direction";
    try
    {
      dealii::GridTools::collect_periodic_faces (triangulation,
                                                 ids.periodic_low,
                                                 ids.periodic_high,
                                                 parameters.periodic_direction,
                                                 pairs);
    }
    catch (const std::exception &)
    {
      throw InputError ("mesh/periodic boundaries", mismatch);
    }
    std::size_t low_faces = 0;
    for (const auto &cell : triangulation.active_cell_iterators ())
      for (const auto &face : cell->face_iterators ())
        low_faces += face->at_boundary () && face->boundary_id () == ids.periodic_low;
    require (parameters.periodic_direction < dim && !pairs.empty () &&
                 pairs.size () == low_faces,
             "mesh/periodic boundaries",
             "the faces of '" + parameters.periodic_high_name + "' are not those of '" +
                 parameters.periodic_low_name +
                 "' translated along the periodic direction");
    triangulation.add_periodicity (pairs);
  }
  triangulation.refine_global (parameters.initial_refinement);
  return ids;
}

template BoundaryIds read_mesh<2> (const MeshParameters &,
                                   const std::string &,
                                   const std::string &,
                                   const std::string &,
                                   const dealii::Tensor<1, 3> &,
                                   dealii::parallel::distributed::Triangulation<2> &);
template BoundaryIds read_mesh<3> (const MeshParameters &,
                                   const std::string &,
                                   const std::string &,
                                   const std::string &,
                                   const dealii::Tensor<1, 3> &,
                                   dealii::parallel::distributed::Triangulation<3> &);
} // namespace wetbed
