#pragma once

#include <wetbed/assembly/flow/flow_term.h>
#include <wetbed/solvers/assembled_flow_operator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>
#include <vector>

namespace wetbed
{
/**
 * Assembles the Oseen-linearised two-fluid system at t_{n+1} (doc/theory.md, "Discrete
 * flow system") from a list of terms, cell by cell on threads (WorkStream): for each
 * cell the fields and, once, every closure at the quadrature points (ClosureEvaluator)
 * go into the scratch, then each term adds its part to the local system, and the copier
 * distributes it into the assembled operator (the system and the Schur mobility
 * Laplacian) and the right-hand side.
 */
template <int dim>
class FlowAssembler
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

  FlowAssembler (const dealii::Mapping<dim>       &mapping,
                 const dealii::DoFHandler<dim>    &flow_dof_handler,
                 const dealii::DoFHandler<dim>    &alpha_dof_handler,
                 const closures::ClosureEvaluator &closures,
                 const FlowMaterial<dim>          &material);

  void add_term (std::unique_ptr<FlowTerm<dim>> term);
  /** The names of the terms, in the order they are applied. */
  std::vector<std::string> term_names () const;

  /** Where the boundary rows of the momentum budget are captured: the velocity DoFs of
   * the inlet, the walls and the outlet, and the upward direction. */
  struct BoundaryRowCapture
  {
    const std::array<dealii::IndexSet, 3> *velocity_dofs;
    dealii::Tensor<1, dim>                 up;
    std::vector<BoundaryCellSystem>       *systems;
  };

  /** The system (with `matrix`; without it only the rhs and L_c: the matrix-free
   * operator applies the system, and the cells with inhomogeneous constraints build
   * their local matrix only to carry the constraints into the rhs; the capture then
   * keeps only the rhs part of the boundary rows). */
  void assemble (const FlowAssemblyState<dim>            &state,
                 const dealii::AffineConstraints<double> &flow_constraints,
                 const dealii::AffineConstraints<double> &schur_constraints,
                 AssembledFlowOperator                   &flow_operator,
                 BlockVector                             &rhs,
                 const BoundaryRowCapture                &capture,
                 bool                                     matrix = true) const;

  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;

  /** The coefficients of the boundary terms on one boundary face of a cell, with the
   * points they belong to (empty where no term acts on the face). */
  struct FaceCoefficients
  {
    std::vector<FlowFacePointCoefficients<dim>> values;
    std::vector<dealii::Point<dim>>             points;
  };

  /** A scratch for cell_coefficients() (the quadrature of assemble()). */
  FlowCellScratch<dim> make_scratch () const;
  /** The name of a term that contributes to the matrix but gives no coefficients (the
   * matrix-free operator cannot apply it), or an empty string. */
  std::string term_without_coefficients () const;
  /** The bilinear form's coefficients at the quadrature points of a (flow DoF handler)
   * cell and of its boundary faces, from the same fields and closures as assemble(). */
  void cell_coefficients (const CellIterator                      &cell,
                          const FlowAssemblyState<dim>            &state,
                          FlowCellScratch<dim>                    &scratch,
                          std::vector<FlowPointCoefficients<dim>> &values,
                          std::vector<FaceCoefficients>           &faces) const;

private:
  /** The fields, the closures and the shared point quantities of a cell. */
  void prepare_cell (const CellIterator           &cell,
                     const FlowAssemblyState<dim> &state,
                     FlowCellScratch<dim>         &scratch) const;
  /** Whether face f of the cell is a boundary face on which some term acts. */
  bool face_has_terms (const CellIterator &cell, unsigned int f) const;
  /** The fields at the points of one boundary face. */
  void prepare_face (const CellIterator           &cell,
                     unsigned int                  face,
                     const FlowAssemblyState<dim> &state,
                     FlowCellScratch<dim>         &scratch) const;
  void local_system (const CellIterator           &cell,
                     const FlowAssemblyState<dim> &state,
                     FlowCellScratch<dim>         &scratch,
                     FlowCellCopy                 &copy) const;
  /** The weighted boundary rows of a cell (with `rows`; else only their rhs part). */
  static void capture_boundary_rows (const FlowCellCopy              &copy,
                                     const std::vector<unsigned int> &component,
                                     const BoundaryRowCapture        &capture,
                                     bool                             rows);

  const dealii::Mapping<dim>                 &mapping;
  const dealii::DoFHandler<dim>              &flow_dof_handler, &alpha_dof_handler;
  const closures::ClosureEvaluator           &evaluator;
  FlowMaterial<dim>                           material;
  std::vector<std::unique_ptr<FlowTerm<dim>>> terms;
};
} // namespace wetbed
