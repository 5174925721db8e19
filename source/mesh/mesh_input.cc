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
Boundaries read_mesh (const MeshParameters       &parameters,
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
  Boundaries ids;
  auto       add = [&] (const std::string &name,
                  const BoundaryType type,
                  const std::string &parameter,
                  const std::string &taken)
  {
    const auto id = id_of (name, parameter);
    require (ids.find (id) == nullptr, parameter, "'" + name + "' " + taken);
    ids.add (name, type, id);
    return id;
  };
  const std::string twice = "is named twice (each group is one inlet, outlet or wall)";
  for (const auto &name : parameters.inlet_names)
    add (name, BoundaryType::inlet, "mesh/inlet", twice);
  for (const auto &name : parameters.outlet_names)
    add (name, BoundaryType::outlet, "mesh/outlet", twice);
  for (const auto &name : parameters.wall_names)
    add (name, BoundaryType::wall, "mesh/wall", twice);
  if (!parameters.periodic_low_name.empty ())
  {
    const std::string taken = "is already the inlet, outlet or wall";
    add (parameters.periodic_low_name,
         BoundaryType::periodic_low,
         "mesh/periodic boundaries",
         taken);
    add (parameters.periodic_high_name,
         BoundaryType::periodic_high,
         "mesh/periodic boundaries",
         taken);
  }
  if (!moving_wall_name.empty ())
    add (moving_wall_name,
         BoundaryType::moving_wall,
         "boundary conditions/moving wall",
         "is already another boundary of the case");

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
      for (const auto wall : ids.ids (BoundaryType::wall))
        triangulation.set_all_manifold_ids_on_boundary (wall, 1);
      triangulation.set_manifold (1, dealii::CylindricalManifold<3> (axis, centre));
      dealii::TransfiniteInterpolationManifold<3> transfinite;
      transfinite.initialize (triangulation);
      triangulation.set_manifold (2, transfinite);
    }
  }
  if (ids.has (BoundaryType::periodic_low))
  {
    const auto periodic_low  = ids.id_of (BoundaryType::periodic_low),
               periodic_high = ids.id_of (BoundaryType::periodic_high);
    std::vector<dealii::GridTools::PeriodicFacePair<
        typename dealii::parallel::distributed::Triangulation<dim>::cell_iterator>>
                      pairs;
    const std::string mismatch = "the faces of '" + parameters.periodic_high_name +
                                 "' are not those of '" + parameters.periodic_low_name +
                                 "' translated along the periodic direction";
    try
    {
      dealii::GridTools::collect_periodic_faces (triangulation,
                                                 periodic_low,
                                                 periodic_high,
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
        low_faces += face->at_boundary () && face->boundary_id () == periodic_low;
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

template Boundaries read_mesh<2> (const MeshParameters &,
                                  const std::string &,
                                  const std::string &,
                                  const std::string &,
                                  const dealii::Tensor<1, 3> &,
                                  dealii::parallel::distributed::Triangulation<2> &);
template Boundaries read_mesh<3> (const MeshParameters &,
                                  const std::string &,
                                  const std::string &,
                                  const std::string &,
                                  const dealii::Tensor<1, 3> &,
                                  dealii::parallel::distributed::Triangulation<3> &);
} // namespace wetbed
