#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/core/verification_hook.h>

#include <memory>
#include <set>

namespace wetbed
{
/**
 * The sources a verification run imposes (VerificationHook::has_flow_sources; only
 * verification runs register them): momentum and mixture-volume sources in the
 * volume, the exact tractions on the outlet and, where the walls keep their
 * conditions, the wall traction source that makes those conditions hold for the exact
 * fields.
 */
template <int dim>
class ImposedSourceTerm : public FlowTerm<dim>
{
public:
  ImposedSourceTerm (std::shared_ptr<const VerificationHook<dim>> hook,
                     std::set<dealii::types::boundary_id>         outlets,
                     std::set<dealii::types::boundary_id>         walls)
      : hook (std::move (hook)), outlets (std::move (outlets)),
        walls (this->hook->walls_keep_conditions ()
                   ? std::move (walls)
                   : std::set<dealii::types::boundary_id> ())
  {
  }
  std::string name () const override { return "imposed sources"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;
  bool        acts_on_boundary (dealii::types::boundary_id id) const override
  {
    return outlets.count (id) > 0 || walls.count (id) > 0;
  }
  void face (const typename FlowTerm<dim>::CellIterator &cell,
             unsigned int                                face_number,
             const FlowCellScratch<dim>                 &scratch,
             const FlowAssemblyState<dim>               &state,
             FlowCellCopy                               &copy) const override;

  bool has_matrix () const override { return false; }

private:
  std::shared_ptr<const VerificationHook<dim>> hook;
  std::set<dealii::types::boundary_id>         outlets, walls;
};
} // namespace wetbed
