#pragma once

#include <wetbed/assembly/flow/flow_term.h>

#include <set>

namespace wetbed
{
/** Directional do-nothing on the outlet: gas flowing back in is treated as inflow,
 * rho_g |u_g.n|_- u_g.v (alpha_g ~ 1 in the freeboard). */
template <int dim>
class OutletBackflowTerm : public FlowTerm<dim>
{
public:
  OutletBackflowTerm (std::set<dealii::types::boundary_id> outlets, double gas_density)
      : outlets (std::move (outlets)), gas_density (gas_density)
  {
  }
  std::string name () const override { return "outlet backflow"; }
  bool        acts_on_boundary (dealii::types::boundary_id id) const override
  {
    return outlets.count (id) > 0;
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
  std::set<dealii::types::boundary_id> outlets;
  double                               gas_density;
};
} // namespace wetbed
