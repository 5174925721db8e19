#pragma once

#include <wetbed/assembly/flow/flow_assembly_data.h>
#include <wetbed/assembly/flow/flow_point_coefficients.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/meshworker/copy_data.h>

#include <vector>

namespace wetbed
{
/** The coefficients of the boundary terms on one boundary face of a cell, with the
 * points they belong to (empty where no term acts on the face). */
template <int dim>
struct FaceCoefficients
{
  std::vector<FlowFacePointCoefficients<dim>> values;
  std::vector<dealii::Point<dim>>             points;
};

/** The bilinear form's coefficients at the quadrature points of a cell ([q]) and of its
 * boundary faces ([face]). */
template <int dim>
struct CellCoefficients
{
  std::vector<FlowPointCoefficients<dim>> values;
  std::vector<FaceCoefficients<dim>>      faces;
};

/**
 * What takes the bilinear form's coefficients from the flow assembly's pass over the
 * cells (FlowAssembler::assemble), so that each cell's fields and closures are
 * evaluated once per outer iteration: the matrix-free operator stores them, the
 * velocity multigrid builds its coarse matrix and node blocks from them.
 *
 * The local functions run on the assembly's worker threads and write only their
 * LocalData (deal.II's MeshWorker::CopyData: one matrix, one vector, two index lists,
 * sized by the sink); distribute() runs in the assembly's copier, one cell at a time.
 */
template <int dim>
class FlowCoefficientSink
{
public:
  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;
  using LocalData    = dealii::MeshWorker::CopyData<1, 1, 2>;

  virtual ~FlowCoefficientSink () = default;

  /** After the cell's volume coefficients (the scratch holds its fields and FE values,
   * the assembly's quadrature): the local work of the cell, into `local`. */
  virtual void local_cell (const CellIterator & /*cell*/,
                           const FlowCellScratch<dim> & /*scratch*/,
                           const std::vector<FlowPointCoefficients<dim>> & /*values*/,
                           LocalData & /*local*/) const
  {
  }
  /** After the coefficients of boundary face f (the scratch's face values on it). */
  virtual void local_face (const CellIterator & /*cell*/,
                           unsigned int /*f*/,
                           const FlowCellScratch<dim> & /*scratch*/,
                           const FaceCoefficients<dim> & /*face*/,
                           LocalData & /*local*/) const
  {
  }
  /** The cell's coefficients and local work into the sink's storage (serial). */
  virtual void distribute (const CellIterator          &cell,
                           const CellCoefficients<dim> &coefficients,
                           const LocalData             &local) = 0;
};
} // namespace wetbed
