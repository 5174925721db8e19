#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace wetbed
{
/** `subsection mesh`: the gmsh geometry and how its physical groups are used. */
struct MeshParameters
{
  std::string  file;               // .geo (meshed with gmsh at start) or .msh
  unsigned int initial_refinement; // uniform refinements after reading
  // physical-group names of the inlets, outlets and walls; inlets/outlets empty: none
  std::vector<std::string> inlet_names, outlet_names, wall_names;
  // two physical groups whose faces are identified, low and high; empty: none
  std::string  periodic_low_name, periodic_high_name;
  unsigned int periodic_direction; // 0, 1, 2: the axis from the low to the high group
  bool         cylindrical_wall;   // attach a cylinder manifold (axis = gravity) to walls
  unsigned int mapping_degree;
  double       wall_face_weight; // partition cost of a wall face, relative to a cell's

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
