#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/core/manufactured_solution.h>

#include <memory>

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
                          dealii::types::boundary_id                       outlet,
                          dealii::types::boundary_id                       wall)
      : solution (std::move (solution)), outlet (outlet),
        wall (this->solution->slip_walls () ? wall : dealii::numbers::invalid_boundary_id)
  {
  }
  std::string name () const override { return "manufactured sources"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;
  bool        acts_on_boundary (dealii::types::boundary_id id) const override
  {
    return id == outlet || id == wall;
  }
  void face (const typename FlowTerm<dim>::CellIterator &cell,
             unsigned int                                face_number,
             const FlowCellScratch<dim>                 &scratch,
             const FlowAssemblyState<dim>               &state,
             FlowCellCopy                               &copy) const override;

private:
  std::shared_ptr<const ManufacturedSolution<dim>> solution;
  dealii::types::boundary_id                       outlet, wall;
};
} // namespace wetbed
