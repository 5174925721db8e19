#pragma once

#include <wetbed/assembly/flow/flow_coefficient_sink.h>
#include <wetbed/assembly/flow/flow_term.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <memory>
#include <vector>

namespace wetbed
{
/**
 * Assembles the Oseen-linearised two-fluid system at t_{n+1} (doc/theory.md, "Discrete
 * flow system") from a list of terms, cell by cell on threads (WorkStream): for each
 * cell the fields and, once, every closure at the quadrature points (ClosureEvaluator)
 * go into the scratch, then each term adds its part to the local system, and the copier
 * distributes it into what the solve path asks for (a Target): the system matrix (if
 * it has one), the Schur mobility Laplacian L_c and the right-hand side, and in the
 * same pass the bilinear form's coefficients at the quadrature points for its
 * coefficient sinks (FlowCoefficientSink: the matrix-free operator, the p-multigrid's
 * coarse matrix): the fields and closures of a cell are evaluated once per assembly.
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

  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;
  using Sinks        = std::vector<FlowCoefficientSink<dim> *>;
  using Matrix       = dealii::TrilinosWrappers::BlockSparseMatrix;

  /** Where a pass writes besides the rhs. `system`: the system matrix, or none (a
   * matrix-free operator applies the system and carries the inhomogeneous constraints
   * into the rhs afterwards, MatrixFreeFlowOperator::subtract_lifting; the capture then
   * keeps only the rhs part of the boundary rows). `schur`: L_c in block (1, 1).
   * `sinks`: the coefficients of every cell and of its boundary faces (from the same
   * fields and closures) go to each: its local work on the worker threads, its
   * distribute() in the copier. */
  struct Target
  {
    Matrix *system = nullptr;
    Matrix *schur  = nullptr;
    Sinks   sinks;
  };

  /** The system linearised about `state` into `target` and `rhs`. */
  void assemble (const FlowAssemblyState<dim>            &state,
                 const dealii::AffineConstraints<double> &flow_constraints,
                 const dealii::AffineConstraints<double> &schur_constraints,
                 const Target                            &target,
                 BlockVector                             &rhs,
                 const BoundaryRowCapture                &capture) const;

  /** The name of a term that contributes to the matrix but gives no coefficients (the
   * matrix-free operator cannot apply it), or an empty string. */
  std::string term_without_coefficients () const;

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
  /** What the pass over the cells hands from a worker to the copier: the local system,
   * and with sinks the cell's coefficients and each sink's local work. */
  struct CellCopy
  {
    CellCopy (unsigned int n_dofs, unsigned int n_pressure_dofs, unsigned int n_sinks);

    CellIterator                                              cell;
    FlowCellCopy                                              system;
    CellCoefficients<dim>                                     coefficients;
    std::vector<typename FlowCoefficientSink<dim>::LocalData> sink_data;
  };
  void local_system (const CellIterator           &cell,
                     const FlowAssemblyState<dim> &state,
                     const Sinks                  &sinks,
                     FlowCellScratch<dim>         &scratch,
                     CellCopy                     &copy) const;
  /** The volume coefficients of the prepared cell, into `values` ([q]). */
  void point_coefficients (const FlowCellScratch<dim>              &scratch,
                           const FlowAssemblyState<dim>            &state,
                           std::vector<FlowPointCoefficients<dim>> &values) const;
  /** The coefficients of the boundary terms on the prepared face f. */
  void face_coefficients (const CellIterator           &cell,
                          unsigned int                  f,
                          const FlowCellScratch<dim>   &scratch,
                          const FlowAssemblyState<dim> &state,
                          FaceCoefficients<dim>        &face) const;
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
