#pragma once

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace wetbed
{
/**
 * What the rest of a case places in the domain, checked by read_mesh() against the
 * mesh as soon as it is read (before anything is written): Parameters::parse_parameters
 * fills it from the other subsections.
 */
struct DomainChecks
{
  struct Height
  {
    std::string parameter; // `subsection/name`
    double      value;     // m along -gravity from the coordinate origin
    bool        top_only;  // only not above the top (the bed height may be 0)
  };
  std::vector<Height>                heights;      // bed height, probe heights, planes
  std::vector<std::array<double, 3>> point_probes; // bed monitors/point probes
  bool        gravity_from_outlet_to_inlet = true; // check gravity against the groups
  std::string held_solids_velocity; // u_s(x, y, z, t) sampled in the domain; empty: none
  double      end_time = 0;         // the time span [0, end time] of the samples
  // uniform refinement levels that every cell reaches, and the parameter that asks
  std::vector<std::pair<std::string, unsigned int>> refinement_levels;
  bool assembled_operator = false; // linear solver/operator: the memory per cell
};

/** `subsection mesh`: the gmsh geometry and how its physical groups are used. */
struct MeshParameters
{
  std::string file; // .geo (meshed with gmsh at start) or .msh
  // (name, value) of the .geo's DefineConstant numbers set with gmsh -setnumber
  std::vector<std::pair<std::string, double>> geometry_parameters;
  unsigned int initial_refinement; // uniform refinements after reading
  // physical-group names of the inlets, outlets and walls; inlets/outlets empty: none
  std::vector<std::string> inlet_names, outlet_names, wall_names;
  // two physical groups whose faces are identified, low and high; empty: none
  std::string  periodic_low_name, periodic_high_name;
  unsigned int periodic_direction; // 0, 1, 2: the axis from the low to the high group
  bool         cylindrical_wall;   // attach a cylinder manifold (axis = gravity) to walls
  unsigned int mapping_degree;
  double       wall_face_weight; // partition cost of a wall face, relative to a cell's
  DomainChecks checks;           // filled by Parameters::parse_parameters

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
