#include <wetbed/core/input_error.h>
#include <wetbed/core/mesh_parameters.h>

#include <deal.II/base/utilities.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void MeshParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("mesh");
  prm.declare_entry ("file",
                     "../meshes/column_2d.geo",
                     Anything (),
                     "gmsh geometry (.geo, meshed with the gmsh executable at start) or "
                     "mesh (.msh). A relative path is taken relative to the .prm file.");
  prm.declare_entry ("initial refinement",
                     "1",
                     Integer (0, 10),
                     "Uniform refinements of the gmsh mesh after reading.");
  prm.declare_entry ("inlet",
                     "inlet",
                     Anything (),
                     "Physical group name of the gas inlet; empty: no inlet (a closed "
                     "or periodic domain).");
  prm.declare_entry ("outlet",
                     "outlet",
                     Anything (),
                     "Physical group name of the outlet; empty: no outlet (then no "
                     "inlet either; the pressure is fixed at one node).");
  prm.declare_entry ("periodic boundaries",
                     "",
                     Anything (),
                     "Two physical group names 'low, high' whose faces are identified: "
                     "every field is periodic between them (a fully developed channel, "
                     "a shear cell). Empty: none.");
  prm.declare_entry ("periodic direction",
                     "y",
                     Selection ("x|y|z"),
                     "The axis along which the high group is the low group translated.");
  prm.declare_entry ("wall", "wall", Anything (), "Physical group name of the walls.");
  prm.declare_entry ("cylindrical wall",
                     "false",
                     Bool (),
                     "Attach a cylindrical manifold (axis along gravity through the mesh "
                     "centre) to the walls, for curved 3D columns.");
  prm.declare_entry ("mapping degree",
                     "2",
                     Integer (1, 4),
                     "Polynomial degree of the geometry mapping (2 for curved walls).");
  prm.declare_entry (
      "wall face weight",
      "0",
      Double (0, 100),
      "Load balancing: the cost of a cell face on a wall, relative to the cost of a "
      "cell (1), when the MPI ranks' partition is made (at the start, and at every "
      "adaptation with p4est). 0: the cells are balanced by count. Measured "
      "(doc/benchmarks.md): a Johnson-Jackson wall face adds ~0.7 of a cell's flow "
      "assembly in 3D (~0.3 of its whole step) and nothing measurable in 2D.");
  prm.leave_subsection ();
}

void MeshParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("mesh");
  file                       = prm.get ("file");
  initial_refinement         = prm.get_integer ("initial refinement");
  inlet_name                 = prm.get ("inlet");
  outlet_name                = prm.get ("outlet");
  wall_name                  = prm.get ("wall");
  cylindrical_wall           = prm.get_bool ("cylindrical wall");
  mapping_degree             = prm.get_integer ("mapping degree");
  wall_face_weight           = prm.get_double ("wall face weight");
  const std::string periodic = prm.get ("periodic boundaries");
  periodic_direction         = std::string ("xyz").find (prm.get ("periodic direction"));
  prm.leave_subsection ();
  require (!file.empty (), "mesh/file", "is empty");
  require (!wall_name.empty (), "mesh/wall", "is empty");
  require (!outlet_name.empty () || inlet_name.empty (),
           "mesh/outlet",
           "is empty, but an inlet needs an outlet for the gas to leave");
  const auto names = dealii::Utilities::split_string_list (periodic, ',');
  require (names.size () == 0 || names.size () == 2,
           "mesh/periodic boundaries",
           "needs two physical group names 'low, high' (got '" + periodic + "')");
  if (names.size () == 2)
  {
    require (names[0] != names[1] && !names[0].empty () && !names[1].empty (),
             "mesh/periodic boundaries",
             "needs two different physical group names (got '" + periodic + "')");
    for (const auto &name : names)
      require (name != wall_name && name != inlet_name && name != outlet_name,
               "mesh/periodic boundaries",
               "'" + name + "' is already the inlet, outlet or wall");
    periodic_low_name  = names[0];
    periodic_high_name = names[1];
  }
}
} // namespace wetbed
