#pragma once

#include <wetbed/assembly/flow/flow_assembly_data.h>
#include <wetbed/assembly/flow/flow_point_coefficients.h>

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
 *
 * A term that contributes to the matrix also says what it contributes as coefficients
 * at a quadrature point (FlowPointCoefficients, FlowFacePointCoefficients), from which
 * the matrix-free operator applies the same bilinear form; terms that only contribute
 * to the right-hand side say has_matrix() == false.
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

  /** Whether cell() or face() contribute to the matrix (not only to the rhs). */
  virtual bool has_matrix () const { return true; }
  /** Whether coefficients() / face_coefficients() give this term's matrix part. */
  virtual bool has_coefficients () const { return false; }

  /** Adds this term's part of the bilinear form at cell quadrature point q. */
  virtual void coefficients (const FlowCellScratch<dim> & /*scratch*/,
                             const FlowAssemblyState<dim> & /*state*/,
                             unsigned int /*q*/,
                             FlowPointCoefficients<dim> & /*coefficients*/) const
  {
  }

  /** Adds this term's part of the boundary bilinear form at face quadrature point q
   * (the scratch's face values initialised on that face). */
  virtual void face_coefficients (const CellIterator & /*cell*/,
                                  unsigned int /*face_number*/,
                                  const FlowCellScratch<dim> & /*scratch*/,
                                  const FlowAssemblyState<dim> & /*state*/,
                                  unsigned int /*q*/,
                                  FlowFacePointCoefficients<dim> & /*coefficients*/) const
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
