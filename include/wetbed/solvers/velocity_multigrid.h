#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/matrix_free_flow_operator.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
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
 */
template <int dim>
class VelocityMultigrid
{
public:
  using LocalVector = dealii::LinearAlgebra::distributed::Vector<double>;
  using FlowCell    = typename MatrixFreeFlowOperator<dim>::FlowCell;

  explicit VelocityMultigrid (const LinearSolverParameters &parameters);

  /** For a new mesh (after the operator's reinit): the Q1 space and its constraints,
   * the coarse sparsity, the transfer, the node pairs of the block Jacobi. */
  void reinit (const dealii::Mapping<dim>        &mapping,
               const MatrixFreeFlowOperator<dim> &op);

  /** The coarse matrix and the Q2 diagonal blocks for new coefficients: begin, then
   * add_cell on every locally owned cell (the operator's update observer), then end. */
  void begin_update ();
  void add_cell (const FlowCell                                &cell,
                 const FlowCellScratch<dim>                    &scratch,
                 const std::vector<FlowPointCoefficients<dim>> &values,
                 const std::vector<typename FlowAssembler<dim>::FaceCoefficients> &faces);
  void end_update ();

  /** The coarse AMG and the smoother's eigenvalue estimate (expensive: by the reuse
   * policy); otherwise the last ones are reused with the new diagonal blocks. */
  void rebuild ();

  /** dst = one V-cycle applied to src (velocity layout of the operator). */
  void vmult (LocalVector &dst, const LocalVector &src) const;

  unsigned int builds = 0;

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

  void assemble_coarse_cell (
      const FlowCell                                                   &cell,
      const std::vector<FlowPointCoefficients<dim>>                    &values,
      const std::vector<typename FlowAssembler<dim>::FaceCoefficients> &faces);
  void add_fine_diagonal (
      const FlowCell                                                   &cell,
      const FlowCellScratch<dim>                                       &scratch,
      const std::vector<FlowPointCoefficients<dim>>                    &values,
      const std::vector<typename FlowAssembler<dim>::FaceCoefficients> &faces);
  void make_coarse_constraints ();

  const LinearSolverParameters                &parameters;
  const MatrixFreeFlowOperator<dim>           *op      = nullptr;
  const dealii::Mapping<dim>                  *mapping = nullptr;
  dealii::FESystem<dim>                        coarse_fe;
  dealii::FE_Q<dim>                            fine_scalar, coarse_scalar;
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
  std::unique_ptr<dealii::FEValues<dim>>     coarse_values;
  std::unique_ptr<dealii::FEFaceValues<dim>> coarse_face_values, fine_face_values;
  mutable LocalVector                        residual, coarse_residual, coarse_solution;
  mutable dealii::TrilinosWrappers::MPI::Vector coarse_rhs_t, coarse_solution_t;
};
} // namespace wetbed
