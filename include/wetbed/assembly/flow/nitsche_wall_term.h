#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/assembly/nitsche_wall.h>

#include <array>
#include <map>

namespace wetbed
{
/**
 * Weak no-penetration u_k.n = 0 on the walls by symmetric Nitsche for each phase that
 * slips there (per wall group) (add_nitsche_no_penetration, assembly/nitsche_wall.h),
 * with the phase coefficients of the volume terms evaluated at the face points by the
 * ClosureEvaluator; on a curved wall the manifold's normal.
 */
template <int dim>
class NitscheWallTerm : public FlowTerm<dim>
{
public:
  /** phases: for each wall id, whether the gas and the solids slip there. */
  NitscheWallTerm (std::map<dealii::types::boundary_id, std::array<bool, 2>> phases,
                   double                                                    gamma,
                   const FlowMaterial<dim>                                  &material,
                   const closures::ClosureEvaluator                         &closures)
      : phases (std::move (phases)), gamma (gamma), material (material),
        evaluator (closures)
  {
  }
  std::string name () const override { return "Nitsche no-penetration"; }
  bool        acts_on_boundary (dealii::types::boundary_id id) const override
  {
    return phases.count (id) > 0;
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
  /** The phases' Nitsche data and the wall's own normal at face point q. */
  std::array<NitschePhase, 2>
  phase_data (const typename FlowTerm<dim>::CellIterator &cell,
              const FlowCellScratch<dim>                 &scratch,
              const FlowAssemblyState<dim>               &state,
              unsigned int                                q,
              dealii::Tensor<1, dim>                     &wall_normal) const;

private:
  // gas, solids slip (weakly) on each wall
  std::map<dealii::types::boundary_id, std::array<bool, 2>> phases;
  double                                                    gamma;
  FlowMaterial<dim>                                         material;
  const closures::ClosureEvaluator                         &evaluator;
};
} // namespace wetbed
