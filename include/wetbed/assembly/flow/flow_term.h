#pragma once

#include <wetbed/assembly/flow/flow_assembly_data.h>

#include <deal.II/dofs/dof_handler.h>

#include <string>

namespace wetbed
{
/**
 * One term of the flow system's weak form (an assembler in the sense of ASPECT and
 * Lethe): it adds its contributions to the local system of a cell from the per-cell
 * scratch, where the fields and the closures at the quadrature points are already
 * evaluated. Volume terms override cell(); boundary terms say where they act and
 * override face(), called with the scratch's face values initialised on that face.
 * The list of terms of a run is chosen from the parameters (flow_terms.h).
 */
template <int dim>
class FlowTerm
{
public:
  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;

  virtual ~FlowTerm ()              = default;
  virtual std::string name () const = 0;

  virtual void cell (const FlowCellScratch<dim> & /*scratch*/,
                     const FlowAssemblyState<dim> & /*state*/,
                     FlowCellCopy & /*copy*/) const
  {
  }

  /** Whether face() contributes on boundary faces with this id. */
  virtual bool acts_on_boundary (dealii::types::boundary_id /*id*/) const
  {
    return false;
  }

  /** The contributions of a boundary face on which acts_on_boundary() holds; the
   * scratch's face values and face fields are initialised on it. */
  virtual void face (const CellIterator & /*cell*/,
                     unsigned int /*face_number*/,
                     const FlowCellScratch<dim> & /*scratch*/,
                     const FlowAssemblyState<dim> & /*state*/,
                     FlowCellCopy & /*copy*/) const
  {
  }
};
} // namespace wetbed
