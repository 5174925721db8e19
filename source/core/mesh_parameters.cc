#include <wetbed/core/input_error.h>
#include <wetbed/core/mesh_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

namespace
{
/** 'name: value, name: value' as (name, value) pairs; an InputError naming
 * `mesh/geometry parameters` for anything else. */
std::vector<std::pair<std::string, double>>
parse_geometry_parameters (const std::string &text)
{
  const std::string                           where = "mesh/geometry parameters";
  std::vector<std::pair<std::string, double>> result;
  for (const auto &item : dealii::Utilities::split_string_list (text, ','))
  {
    const auto colon = item.find (':');
    require (colon != std::string::npos, where, "'" + item + "' is not 'name: value'");
    const std::string name  = dealii::Utilities::trim (item.substr (0, colon));
    const std::string value = dealii::Utilities::trim (item.substr (colon + 1));
    const bool        identifier =
        !name.empty () && !std::isdigit (static_cast<unsigned char> (name[0])) &&
        std::all_of (name.begin (),
                     name.end (),
                     [] (const char c) {
                       return std::isalnum (static_cast<unsigned char> (c)) || c == '_';
                     });
    require (identifier, where, "'" + name + "' is not a gmsh constant name");
    for (const auto &earlier : result)
      require (earlier.first != name, where, "'" + name + "' is given twice");
    char        *end    = nullptr;
    const double number = std::strtod (value.c_str (), &end);
    require (!value.empty () && end == value.c_str () + value.size (),
             where,
             "the value of '" + name + "' ('" + value + "') is not a number");
    require (std::isfinite (number),
             where,
             "the value of '" + name + "' ('" + value + "') is not finite");
    result.emplace_back (name, number);
  }
  return result;
}
} // namespace

void MeshParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("mesh");
  prm.declare_entry ("file",
                     "../meshes/column_2d.geo",
                     Anything (),
                     "gmsh geometry (.geo, meshed with the gmsh executable at start) or "
                     "mesh (.msh). A relative path is taken relative to the .prm file.");
  prm.declare_entry (
      "geometry parameters",
      "",
      Anything (),
      "Numbers of a .geo file given to gmsh ('name: value, name: value', e.g. "
      "'radius: 0.075, height: 1.5, n_layers: 120'): each name must be a "
      "DefineConstant of the .geo, whose value it replaces (gmsh -setnumber). One .geo "
      "then serves every size of a geometry. Empty: the .geo's own values.");
  prm.declare_entry ("initial refinement",
                     "1",
                     Integer (0, 10),
                     "Uniform refinements of the gmsh mesh after reading.");
  prm.declare_entry ("inlet",
                     "inlet",
                     Anything (),
                     "Physical group name of the gas inlet, or a comma-separated list "
                     "of names (several inlet groups, each with the inlet velocity); "
                     "empty: no inlet (a closed or periodic domain).");
  prm.declare_entry ("outlet",
                     "outlet",
                     Anything (),
                     "Physical group name of the outlet, or a comma-separated list of "
                     "names (several traction-free outlet groups); empty: no outlet "
                     "(then no inlet either; the pressure is fixed at one node).");
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
  prm.declare_entry ("wall",
                     "wall",
                     Anything (),
                     "Physical group name of the walls, or a comma-separated list of "
                     "names (every group gets the wall conditions of `boundary "
                     "conditions`).");
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
      "adaptation with p4est). 0: the cells are balanced by count, right in 2D; a "
      "Johnson-Jackson wall face in 3D adds a sizeable part of a cell's cost "
      "(doc/benchmarks.md \"What a cell costs: the load-balancing model\").");
  prm.leave_subsection ();
}

void MeshParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("mesh");
  file                       = prm.get ("file");
  initial_refinement         = prm.get_integer ("initial refinement");
  const std::string inlet    = prm.get ("inlet");
  const std::string outlet   = prm.get ("outlet");
  const std::string wall     = prm.get ("wall");
  cylindrical_wall           = prm.get_bool ("cylindrical wall");
  mapping_degree             = prm.get_integer ("mapping degree");
  wall_face_weight           = prm.get_double ("wall face weight");
  const std::string periodic = prm.get ("periodic boundaries");
  periodic_direction         = std::string ("xyz").find (prm.get ("periodic direction"));
  const std::string geometry = prm.get ("geometry parameters");
  prm.leave_subsection ();
  require (!file.empty (), "mesh/file", "is empty");
  geometry_parameters = parse_geometry_parameters (geometry);
  // each group once, in one role
  std::vector<std::string> named;
  auto group_list = [&] (const std::string &value, const std::string &key)
  {
    const auto list = dealii::Utilities::split_string_list (value, ',');
    for (const auto &name : list)
    {
      require (!name.empty (),
               "mesh/" + key,
               "has an empty physical group name in the list '" + value + "'");
      require (std::find (named.begin (), named.end (), name) == named.end (),
               "mesh/" + key,
               "'" + name + "' is named twice (each group is one inlet, outlet or wall)");
      named.push_back (name);
    }
    return list;
  };
  inlet_names  = group_list (inlet, "inlet");
  outlet_names = group_list (outlet, "outlet");
  wall_names   = group_list (wall, "wall");
  require (!wall_names.empty (), "mesh/wall", "is empty");
  require (!outlet_names.empty () || inlet_names.empty (),
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
      require (std::find (named.begin (), named.end (), name) == named.end (),
               "mesh/periodic boundaries",
               "'" + name + "' is already the inlet, outlet or wall");
    periodic_low_name  = names[0];
    periodic_high_name = names[1];
  }
}
} // namespace wetbed
