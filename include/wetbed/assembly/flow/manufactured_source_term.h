#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/core/manufactured_solution.h>

#include <memory>
#include <set>

namespace wetbed
{
/**
 * The sources of a manufactured solution (verification runs only: registered by
 * TwoFluidSolver::set_manufactured_solution): momentum and mixture-volume sources in the
 * volume, the exact tractions on the outlet and, with slip walls, the wall traction
 * source that makes the wall conditions hold for the manufactured fields.
 */
template <int dim>
class ManufacturedSourceTerm : public FlowTerm<dim>
{
public:
  ManufacturedSourceTerm (std::shared_ptr<const ManufacturedSolution<dim>> solution,
                          std::set<dealii::types::boundary_id>             outlets,
                          std::set<dealii::types::boundary_id>             walls)
      : solution (std::move (solution)), outlets (std::move (outlets)),
        walls (this->solution->slip_walls () ? std::move (walls)
                                             : std::set<dealii::types::boundary_id> ())
  {
  }
  std::string name () const override { return "manufactured sources"; }
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
  std::shared_ptr<const ManufacturedSolution<dim>> solution;
  std::set<dealii::types::boundary_id>             outlets, walls;
};
} // namespace wetbed
