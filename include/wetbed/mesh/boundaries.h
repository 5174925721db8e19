#pragma once

#include <deal.II/base/types.h>

#include <initializer_list>
#include <set>
#include <string>
#include <vector>

namespace wetbed
{
/** What the solver does on a boundary group. */
enum class BoundaryType
{
  inlet,         // gas enters at U(t)/alpha_g, solids held at the distributor
  outlet,        // traction-free gas outlet, solids retained
  wall,          // fixed wall (the `boundary conditions` wall conditions)
  moving_wall,   // a wall that slides tangentially (`boundary conditions/moving wall`)
  periodic_low,  // the low side of the periodic pair
  periodic_high, // the high side of the periodic pair
};

/** The name of a type as the parameter file says it ("inlet", "moving wall", ...). */
std::string to_string (BoundaryType type);

/** One named physical group of the mesh and what it is. */
struct Boundary
{
  std::string                name; // the gmsh physical-group name
  BoundaryType               type;
  dealii::types::boundary_id id;
};

/**
 * The boundary groups of a case, in the order they were added (read_mesh: inlets,
 * outlets, walls, the periodic pair, the moving wall). Several groups may have the same
 * type (several inlets, outlets or walls); a boundary id belongs to one group at most.
 * Faces whose id is in no group have no boundary condition of their own.
 */
class Boundaries
{
public:
  static constexpr dealii::types::boundary_id none = dealii::numbers::invalid_boundary_id;

  /** Adds a group; throws std::invalid_argument if `id` is already a group's. */
  void add (const std::string &name, BoundaryType type, dealii::types::boundary_id id);

  const std::vector<Boundary> &all () const { return groups; }
  /** The ids of every group of `type` (empty: the case has none). */
  std::set<dealii::types::boundary_id> ids (BoundaryType type) const;
  /** The ids of every group of any of `types`. */
  std::set<dealii::types::boundary_id>
  ids (std::initializer_list<BoundaryType> types) const;
  /** The id of the only group of `type` (the periodic pair); `none` if there is none. */
  dealii::types::boundary_id id_of (BoundaryType type) const;
  bool                       has (BoundaryType type) const;
  bool                       is (dealii::types::boundary_id id, BoundaryType type) const;
  /** A fixed or a moving wall. */
  bool is_wall (dealii::types::boundary_id id) const;
  /** The ids of the fixed and the moving walls. */
  std::set<dealii::types::boundary_id> walls () const;
  /** The group of `id`; nullptr if `id` is in none. */
  const Boundary *find (dealii::types::boundary_id id) const;
  /** The type of the group of `id`; throws std::out_of_range if it is in none. */
  BoundaryType type_of (dealii::types::boundary_id id) const;

private:
  std::vector<Boundary> groups;
};
} // namespace wetbed
