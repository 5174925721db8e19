#pragma once

#include <wetbed/assembly/flow/flow_term.h>

#include <set>

namespace wetbed
{
/**
 * Weak no-penetration u_k.n = 0 on the walls by symmetric Nitsche for each phase that
 * slips there (add_nitsche_no_penetration, assembly/nitsche_wall.h), with the phase
 * coefficients of the volume terms evaluated at the face points by the
 * ClosureEvaluator; on a curved wall the manifold's normal.
 */
template <int dim>
class NitscheWallTerm : public FlowTerm<dim>
{
public:
  NitscheWallTerm (std::set<dealii::types::boundary_id> walls,
                   const std::array<bool, 2>           &phases,
                   double                               gamma,
                   const FlowMaterial<dim>             &material,
                   const closures::ClosureEvaluator    &closures)
      : walls (std::move (walls)), phases (phases), gamma (gamma), material (material),
        evaluator (closures)
  {
  }
  std::string name () const override { return "Nitsche no-penetration"; }
  bool        acts_on_boundary (dealii::types::boundary_id id) const override
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
  std::array<bool, 2>                  phases; // gas, solids slip (weakly)
  double                               gamma;
  FlowMaterial<dim>                    material;
  const closures::ClosureEvaluator    &evaluator;
};
} // namespace wetbed
