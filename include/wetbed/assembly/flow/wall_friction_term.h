#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/boundary_conditions/wall_conditions.h>

#include <set>

namespace wetbed
{
/**
 * The tangential traction of each phase on the walls whose condition has friction,
 * -C P_t (u_k - u_w), P_t = I - n n, with C the condition's coefficient at the face
 * point (a constant for partial slip, C_JJ(alpha_s, g0, Theta) of doc/theory.md,
 * "Johnson-Jackson walls", lagged). u_w is the velocity of a moving wall (zero on fixed
 * walls).
 */
template <int dim>
class WallFrictionTerm : public FlowTerm<dim>
{
public:
  WallFrictionTerm (WallConditions                       conditions,
                    std::set<dealii::types::boundary_id> moving_walls,
                    const dealii::Tensor<1, dim>        &wall_velocity);
  std::string name () const override { return "wall friction"; }
  bool        acts_on_boundary (dealii::types::boundary_id id) const override
  {
    return friction_walls.count (id) > 0;
  }
  void face (const typename FlowTerm<dim>::CellIterator &cell,
             unsigned int                                face_number,
             const FlowCellScratch<dim>                 &scratch,
             const FlowAssemblyState<dim>               &state,
             FlowCellCopy                               &copy) const override;

  bool has_coefficients () const override { return true; }
  void face_coefficients (const typename FlowTerm<dim>::CellIterator &cell,
                          unsigned int                                face_number,
                          const FlowCellScratch<dim>                 &scratch,
                          const FlowAssemblyState<dim>               &state,
                          unsigned int                                q,
                          FlowFacePointCoefficients<dim> &coefficients) const override;

private:
  WallConditions                       conditions;
  std::set<dealii::types::boundary_id> friction_walls; // of either phase
  std::set<dealii::types::boundary_id> moving_walls;
  dealii::Tensor<1, dim>               wall_velocity;
};
} // namespace wetbed
