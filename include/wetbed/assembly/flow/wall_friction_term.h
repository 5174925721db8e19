#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>

#include <set>

namespace wetbed
{
/**
 * The tangential solids traction on slipping walls, -C (P_t (u_s - u_w)), P_t = I - n n:
 * partial slip with a constant C, or Johnson-Jackson with the Robin coefficient
 * C_JJ(alpha_s, g0, Theta) of doc/theory.md, "Johnson-Jackson walls" (lagged). u_w is
 * the velocity of a moving wall (zero on fixed walls).
 */
template <int dim>
class WallFrictionTerm : public FlowTerm<dim>
{
public:
  /** kinetic_theory: the Johnson-Jackson coefficient; null: the constant `friction`. */
  WallFrictionTerm (std::set<dealii::types::boundary_id> walls,
                    std::set<dealii::types::boundary_id> moving_walls,
                    const dealii::Tensor<1, dim>        &wall_velocity,
                    double                               friction,
                    const closures::KineticTheory       *kinetic_theory)
      : walls (std::move (walls)), moving_walls (std::move (moving_walls)),
        wall_velocity (wall_velocity), friction (friction),
        kinetic_theory (kinetic_theory)
  {
  }
  std::string name () const override
  {
    return kinetic_theory ? "Johnson-Jackson wall friction" : "partial slip";
  }
  bool acts_on_boundary (dealii::types::boundary_id id) const override
  {
    return walls.count (id) > 0;
  }
  void face (const typename FlowTerm<dim>::CellIterator &cell,
             unsigned int                                face_number,
             const FlowCellScratch<dim>                 &scratch,
             const FlowAssemblyState<dim>               &state,
             FlowCellCopy                               &copy) const override;

private:
  std::set<dealii::types::boundary_id> walls;
  std::set<dealii::types::boundary_id> moving_walls; // a subset of walls
  dealii::Tensor<1, dim>               wall_velocity;
  double                               friction;
  const closures::KineticTheory       *kinetic_theory;
};
} // namespace wetbed
