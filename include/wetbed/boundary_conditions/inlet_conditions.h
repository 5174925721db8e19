#pragma once

#include <wetbed/core/boundary_condition_parameters.h>
#include <wetbed/mesh/boundaries.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <map>
#include <memory>
#include <vector>

namespace wetbed
{
/**
 * The inflow of every inlet group: a superficial gas velocity U(x, t) along a direction
 * (`boundary conditions/inlet velocities`, `inlet directions`), a mass flow rate m(t)
 * turned into U = m / (rho_g A) with the group's area projected on its direction
 * (`inlet mass flow rates`), or the common `inlet superficial velocity` U(t) against
 * gravity; and the solids a group feeds (`inlet solids`: a fraction alpha_in and a
 * speed along the direction). The faces of the inlets (their quadrature points and
 * weights) are gathered on every rank after each mesh change, so that the inflow's means
 * and peaks need no communication (source/boundary_conditions/inlet_conditions.cc).
 */
template <int dim>
class InletConditions
{
public:
  /** `end_time`: the velocities are checked finite over [0, end_time]. */
  InletConditions (const BoundaryConditionParameters &parameters,
                   double                             gas_density,
                   const dealii::Tensor<1, dim>      &upward,
                   double                             end_time);

  /** The inlet faces of this mesh; collective. InputError naming `boundary
   * conditions/inlet mass flow rates` for a mass flow on a group of zero (projected)
   * area, `inlet directions` for a direction out of the domain, or `inlet velocities`
   * (`inlet mass flow rates`) for a velocity that is not finite at a quadrature point of
   * a face at one of 51 times over [0, end_time]. */
  void reinit (const dealii::Triangulation<dim> &triangulation,
               const dealii::Mapping<dim>       &mapping,
               const Boundaries                 &boundaries,
               MPI_Comm                          communicator);

  /** The superficial gas velocity vector entering through the group `id` at `x`. */
  dealii::Tensor<1, dim> superficial_velocity (dealii::types::boundary_id id,
                                               const dealii::Point<dim>  &x,
                                               double                     t) const;

  /** The gas volume flow over the inlet area, all inlets together (m/s). */
  double mean_superficial_velocity (double t) const;

  /** The largest superficial speed on an inlet face (m/s). */
  double peak_superficial_velocity (double t) const;

  /** The area of each inlet group (m^2; m per metre depth in 2D), by name. */
  std::map<std::string, double> areas () const;

  /** The solids velocity on the faces of the group `id`: its feed speed along its
   * direction, zero for a group that feeds no solids. */
  dealii::Tensor<1, dim> solids_velocity (dealii::types::boundary_id id) const;

  /** Whether the group `id` feeds solids. */
  bool feeds_solids (dealii::types::boundary_id id) const;

  /** The solids volume fed per second through all inlets, sum of alpha_in times the
   * speed times the area projected on the direction (m^3/s; m^2/s in 2D). */
  double solids_volume_flow () const;

  /**
   * The solids feed as a source of the alpha_s transport (doc/theory.md, "Solids
   * fraction transport"): rates_i = int_inlet phi_i alpha_in u_in.(-n) ds over the
   * faces of the feeding groups (m^3/s per node; condensed with the hanging-node
   * `constraints`). `rates` is reinitialised to the layout of `layout`; left empty
   * (size 0) when no group feeds solids. Collective.
   */
  void
  solids_inflow_rates (const dealii::DoFHandler<dim>           &alpha_dofs,
                       const dealii::Mapping<dim>              &mapping,
                       const dealii::AffineConstraints<double> &constraints,
                       const dealii::LinearAlgebra::distributed::Vector<double> &layout,
                       dealii::LinearAlgebra::distributed::Vector<double> &rates) const;

private:
  struct Group
  {
    std::string                                  name;
    dealii::types::boundary_id                   id;
    dealii::Tensor<1, dim>                       direction;
    std::unique_ptr<dealii::FunctionParser<dim>> velocity;  // U(x, t)
    std::unique_ptr<dealii::FunctionParser<1>>   mass_flow; // m(t)
    double                                       area = 0, projected_area = 0;
    double solids_fraction = 0, solids_speed = 0; // the solids feed; 0: none
    bool   uniform = true; // the same speed on all its faces (no U(x, t) of its own)
    std::vector<dealii::Point<dim>> points; // quadrature points of its faces
    std::vector<double>             weights;
  };

  const Group &group (dealii::types::boundary_id id) const;
  double       speed (const Group &g, const dealii::Point<dim> &x, double t) const;
  /** The inlet group of boundary `b` with its direction and its velocity U(x, t) or
   * mass flow m(t) from the parameters (the common U(t) where it has none). */
  Group make_group (const Boundary &b) const;
  /** An InputError naming the group and its parameter where its speed is not finite at
   * one of 51 times up to the end time on its faces' points. */
  void check_speeds (const Group &g) const;

  const BoundaryConditionParameters &parameters;
  double                             gas_density, end_time;
  dealii::Tensor<1, dim>             upward;
  std::vector<Group>                 groups;
};
} // namespace wetbed
