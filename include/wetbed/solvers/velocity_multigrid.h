#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/matrix_free_flow_operator.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>

#include <memory>
#include <vector>

namespace wetbed
{
/**
 * One two-level V-cycle on the velocity block A of the matrix-free flow operator that
 * never assembles A (doc/theory.md, "Velocity p-multigrid"): Chebyshev smoothing on
 * the matrix-free Q2 operator, preconditioned by node-block Jacobi (at each Q2 node the
 * 2 dim x 2 dim block of both phases' velocity components inverted exactly), and a
 * coarse correction on the Q1 velocity space
 * (polynomial transfer, deal.II MGTwoLevelTransfer) by one ML V-cycle on the Q1 matrix
 * of the same bilinear form, assembled from the same quadrature-point coefficients.
 *
 * The coarse matrix and the node blocks are built in the flow assembly's pass over the
 * cells (a FlowCoefficientSink): the local matrices from the coefficients and the
 * assembly's FE values (the Q1 pressure basis is the coarse basis, the Q2 velocity
 * basis the fine one) on its worker threads, their distribution in its copier.
 */
template <int dim>
class VelocityMultigrid : public FlowCoefficientSink<dim>
{
public:
  using LocalVector = dealii::LinearAlgebra::distributed::Vector<double>;
  using FlowCell    = typename MatrixFreeFlowOperator<dim>::FlowCell;
  using LocalData   = typename FlowCoefficientSink<dim>::LocalData;

  explicit VelocityMultigrid (const LinearSolverParameters &parameters);

  /** For a new mesh (after the operator's reinit): the Q1 space and its constraints,
   * the coarse sparsity, the transfer, the node pairs of the block Jacobi. */
  void reinit (const MatrixFreeFlowOperator<dim> &op);

  /** The Q2 node blocks, and with `with_coarse_matrix` the coarse matrix, for new
   * coefficients: begin, then the flow assembly's pass with this sink, then end (the
   * node blocks inverted). The coarse matrix is only read by the coarse AMG's build
   * (rebuild()), which keeps seeing the matrix it was built from until the next one:
   * passes that precede no rebuild leave it out. */
  void begin_update (bool with_coarse_matrix);
  /** Whether the last update assembled the coarse matrix (what rebuild() needs). */
  bool coarse_matrix_current () const { return coarse_current; }
  /** The cell's part of the coarse matrix (matrices[0], its Q1 DoFs in
   * local_dof_indices[0]) and of the node blocks (vectors[0], its Q2 DoFs in
   * local_dof_indices[1]). */
  void local_cell (const FlowCell                                &cell,
                   const FlowCellScratch<dim>                    &scratch,
                   const std::vector<FlowPointCoefficients<dim>> &values,
                   LocalData                                     &local) const override;
  /** The boundary terms of face f added to the cell's local matrices. */
  void local_face (const FlowCell              &cell,
                   unsigned int                 f,
                   const FlowCellScratch<dim>  &scratch,
                   const FaceCoefficients<dim> &face,
                   LocalData                   &local) const override;
  void distribute (const FlowCell              &cell,
                   const CellCoefficients<dim> &coefficients,
                   const LocalData             &local) override;
  void end_update ();

  /** The coarse AMG and the smoother's eigenvalue estimate (expensive: by the reuse
   * policy); otherwise the last ones are reused with the new diagonal blocks. */
  void rebuild ();

  /** dst = one V-cycle applied to src (velocity layout of the operator). */
  void vmult (LocalVector &dst, const LocalVector &src) const;

  /** Bytes held: the Q1 space, its matrix, the transfer, the node blocks and the work
   * vectors (not ML's hierarchy, which Trilinos does not report). */
  std::size_t memory_consumption () const;

  unsigned int builds = 0;
  /** With `inner solves = exact coarse`: the coarse GMRES iterations and solves. */
  mutable unsigned int coarse_iterations = 0, coarse_solves = 0;

private:
  /** The operator's velocity block as the smoother sees it. */
  struct VelocityBlock : public dealii::Subscriptor
  {
    const MatrixFreeFlowOperator<dim> *op = nullptr;
    void vmult (LocalVector &dst, const LocalVector &src) const
    {
      op->vmult_velocity (dst, src);
    }
    void initialize_dof_vector (LocalVector &v) const
    {
      op->initialize_velocity_vector (v);
    }
  };
  /** The inverse (2 dim) x (2 dim) blocks of each Q2 node: all velocity components
   * of both phases at the node, which the drag (gas-solids), the viscous stress and
   * the Nitsche penalty n n^T (between directions) couple. */
  struct NodeBlockJacobi
  {
    std::vector<std::array<unsigned int, 2 * dim>> nodes;   // local indices
    std::vector<double>                            inverse; // row-major per node
    std::vector<unsigned int>                      singles; // unpaired: identity
    void vmult (LocalVector &dst, const LocalVector &src) const;
  };
  using Smoother =
      dealii::PreconditionChebyshev<VelocityBlock, LocalVector, NodeBlockJacobi>;

  void make_coarse_constraints ();
  /** The coarse (Q1) and fine (Q2) velocity DoFs of `cell` into `local`, DoF (c, a) of
   * either at c n + a (n: the scalar basis size). */
  void cell_dof_indices (const FlowCell &cell,
                         unsigned int    n1,
                         unsigned int    n2,
                         LocalData      &local) const;

  const LinearSolverParameters      &parameters;
  const bool                         exact_coarse;
  bool                               coarse_pending = false; // in this update
  bool                               coarse_current = false; // after it
  const MatrixFreeFlowOperator<dim> *op             = nullptr;
  dealii::FESystem<dim>              coarse_fe;
  // component_to_system_index of the coarse and the fine velocity element, as tables
  std::vector<std::vector<unsigned int>>       coarse_components, fine_components;
  dealii::FE_Q<dim>                            fine_scalar;
  dealii::DoFHandler<dim>                      coarse_dofs;
  dealii::AffineConstraints<double>            coarse_constraints;
  dealii::IndexSet                             coarse_owned;
  dealii::TrilinosWrappers::SparseMatrix       coarse_matrix;
  dealii::TrilinosWrappers::PreconditionAMG    coarse_amg;
  dealii::MGTwoLevelTransfer<dim, LocalVector> transfer;
  std::shared_ptr<NodeBlockJacobi>             jacobi;
  VelocityBlock                                block;
  Smoother                                     smoother;
  // the node blocks of the Q2 operator: entries[o](c, a) = A((c, a), ((c + o) mod
  // 2 dim, a)) at the DoF of component c and basis function a
  std::vector<LocalVector> entries;
  // work
  mutable LocalVector residual, coarse_residual, coarse_solution;
  mutable dealii::TrilinosWrappers::MPI::Vector coarse_rhs_t, coarse_solution_t;
};
} // namespace wetbed
