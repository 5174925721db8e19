#pragma once

#include <wetbed/assembly/flow/flow_assembler.h>
#include <wetbed/assembly/flow/flow_coefficient_sink.h>
#include <wetbed/solvers/assembled_flow_operator.h>
#include <wetbed/solvers/flow_operator.h>

#include <deal.II/base/vectorization.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <array>
#include <functional>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace wetbed
{
/**
 * The flow operator [[A, B^T], [B, 0]] applied without a matrix (doc/theory.md,
 * "Matrix-free flow operator"): sum-factorised cell and boundary-face integrals
 * (deal.II MatrixFree, FEEvaluation / FEFaceEvaluation) of the bilinear form whose
 * coefficients the flow terms give at the quadrature points (FlowPointCoefficients,
 * FlowFacePointCoefficients), evaluated once per assembly: in the assembly's pass
 * over the cells, whose copier hands each cell's coefficients to distribute() (a
 * FlowCoefficientSink), which stores them at the cell's place in the cell batches and,
 * on boundary faces, at MatrixFree's face points.
 *
 * MatrixFree needs vectors whose locally owned range is contiguous, which the flow
 * DoF handler's block numbering (velocities | pressure) is not on several ranks; the
 * operator therefore works on its own velocity (Q2^{2 dim}) and pressure (Q1) DoF
 * handlers on the same mesh, with the flow constraints translated to them, and maps the
 * Krylov vectors' blocks onto them. Constrained rows act as diagonal_i x_i, with the
 * diagonal of the assembled operator's constrained rows (set_constrained_diagonal).
 */
template <int dim>
class MatrixFreeFlowOperator : public FlowOperator, public FlowCoefficientSink<dim>
{
public:
  using VA          = dealii::VectorizedArray<double>;
  using LocalVector = dealii::LinearAlgebra::distributed::Vector<double>;

  MatrixFreeFlowOperator ();

  std::string name () const override { return "matrix-free"; }

  /** For a new mesh: the velocity and pressure DoF handlers, their constraints (the
   * homogeneous part of `flow_constraints`), the maps from the flow blocks, MatrixFree.
   */
  void reinit (const dealii::Mapping<dim>              &mapping,
               const dealii::DoFHandler<dim>           &flow_dof_handler,
               const std::vector<dealii::IndexSet>     &owned,
               const dealii::AffineConstraints<double> &flow_constraints);

  using FlowCell = typename dealii::DoFHandler<dim>::active_cell_iterator;

  /** Before the assembly pass of a new linearisation: the coefficient storage cleared
   * (a term of `assembler` without coefficients is an error naming it). */
  void begin_update (const FlowAssembler<dim> &assembler);
  /** The coefficients of one locally owned (flow DoF handler) cell and of its boundary
   * faces, stored at its places in the cell and face batches (the assembly's copier). */
  void distribute (const FlowCell                                     &cell,
                   const CellCoefficients<dim>                        &coefficients,
                   const typename FlowCoefficientSink<dim>::LocalData &local) override;

  /** The diagonal entries of the constrained rows, taken from `assembled`. */
  void set_constrained_diagonal (const AssembledFlowOperator &assembled);

  void vmult (BlockVector &dst, const BlockVector &src) const override;

  /** The velocity space of the operator (Q2^{2 dim}, contiguous numbering). */
  const dealii::DoFHandler<dim> &velocity_dofs () const { return velocity_dof_handler; }
  const dealii::AffineConstraints<double> &velocity_dof_constraints () const
  {
    return velocity_constraints;
  }
  const dealii::FESystem<dim> &velocity_element () const { return velocity_fe; }
  void                         initialize_velocity_vector (LocalVector &v) const
  {
    matrix_free.initialize_dof_vector (v, 0);
  }
  /** dst = A src on the velocities alone, constrained rows as identity. */
  void vmult_velocity (LocalVector &dst, const LocalVector &src) const;
  /** dst = B^T p: the pressure's part of the momentum rows (velocity layout). */
  void vmult_gradient (LocalVector                                 &dst,
                       const dealii::TrilinosWrappers::MPI::Vector &p) const;
  /** The velocity block of a flow vector in the velocity layout, and back. */
  void to_velocity (LocalVector                                 &dst,
                    const dealii::TrilinosWrappers::MPI::Vector &src) const;
  void from_velocity (dealii::TrilinosWrappers::MPI::Vector &dst,
                      const LocalVector                     &src) const;
  /** Zeroes the constrained entries of a velocity-layout vector. */
  void zero_constrained_velocity (LocalVector &v) const
  {
    for (const unsigned int i : velocity_constrained_local)
      v.local_element (i) = 0;
  }
  /** The constrained rows of block b (positions among its owned elements) and their
   * diagonal entries. */
  const std::vector<unsigned int> &constrained_rows (unsigned int b) const
  {
    return constrained[b];
  }
  const std::vector<double> &constrained_row_diagonal (unsigned int b) const
  {
    return constrained_diagonal[b];
  }

  /** sum_i w_i (K x)_i over the (block-0 position, weight) lists of three boundaries,
   * K the unconstrained velocity rows (cell and face integrals without any constraint),
   * x = `solution` (ghosted, constraints distributed); this rank's part. */
  std::array<double, 3> weighted_row_sums (
      const BlockVector                                                 &solution,
      const std::array<std::vector<std::pair<unsigned int, double>>, 3> &weights) const;

  /** rhs -= C^T A u_D: the values of the inhomogeneous constraints (the inlet) carried
   * into the rhs by one application of the operator to them (unconstrained read,
   * constrained write), instead of local matrices of the cells that hold them
   * (doc/theory.md, "Matrix-free flow operator"). After the coefficients of an update;
   * collective. */
  void subtract_lifting (BlockVector                             &rhs,
                         const dealii::AffineConstraints<double> &flow_constraints) const;

  /** Bytes held: MatrixFree, the coefficients, the maps and work vectors. */
  std::size_t memory_consumption () const;

private:
  struct CellData
  {
    VA                         mass[2], viscosity[2], bulk[2], inertia[2], supg[2];
    VA                         drag, alpha_s;
    dealii::Tensor<1, dim, VA> advection[2], grad_alpha_s;
  };
  struct FaceData
  {
    VA                         friction[2], backflow, slips[2], viscosity[2], bulk[2];
    VA                         penalty[2], fraction[2];
    dealii::Tensor<1, dim, VA> wall_normal;
  };

  // which DoF indices of matrix_free the integrals read from and write to: 0, 1 with
  // the constraints, 2, 3 without
  enum class Layout
  {
    constrained, // read and write with the constraints (the operator)
    plain,       // neither (the unconstrained rows of the boundary reactions)
    lifting      // read without, write with (the inhomogeneous constraints' rhs)
  };
  // the velocity DoF index (the pressure's is the next) that `layout` reads from, and
  // the one it writes to
  static std::pair<unsigned int, unsigned int> dof_indices (Layout layout)
  {
    return {layout == Layout::constrained ? 0u : 2u, layout == Layout::plain ? 2u : 0u};
  }
  // the integrals; a null pointer leaves that block out (no input or no output)
  void apply_cells (LocalVector       *dst_u,
                    LocalVector       *dst_p,
                    const LocalVector *src_u,
                    const LocalVector *src_p,
                    Layout             layout = Layout::constrained) const;
  // apply_cells' kernel for the blocks in flags (velocity_in | pressure_in | ...)
  static constexpr unsigned int velocity_in = 8, pressure_in = 4, velocity_out = 2,
                                pressure_out = 1;
  template <unsigned int flags>
  void apply_cells_kernel (LocalVector       *dst_u,
                           LocalVector       *dst_p,
                           const LocalVector *src_u,
                           const LocalVector *src_p,
                           Layout             layout) const;
  using Kernel = void (MatrixFreeFlowOperator<dim>::*) (LocalVector *,
                                                        LocalVector *,
                                                        const LocalVector *,
                                                        const LocalVector *,
                                                        Layout) const;
  template <std::size_t... flags>
  static auto kernel_table (std::index_sequence<flags...>)
      -> std::array<Kernel, sizeof...(flags)>;
  void apply_boundary_faces (LocalVector       *dst_u,
                             LocalVector       *dst_p,
                             const LocalVector *src_u,
                             const LocalVector *src_p,
                             Layout             layout = Layout::constrained) const;
  /** Which boundary face batches any boundary term acts on (face_batch_active). */
  void mark_active_face_batches () const;
  /** Where each locally owned cell and boundary face sits in the batches. */
  void find_batch_places ();
  void build_maps (const dealii::DoFHandler<dim>           &flow_dof_handler,
                   const std::vector<dealii::IndexSet>     &owned,
                   const dealii::AffineConstraints<double> &flow_constraints);

  const dealii::DoFHandler<dim>      *flow_dof_handler = nullptr;
  dealii::FESystem<dim>               velocity_fe;
  dealii::FE_Q<dim>                   pressure_fe;
  dealii::DoFHandler<dim>             velocity_dof_handler, pressure_dof_handler;
  dealii::AffineConstraints<double>   velocity_constraints, pressure_constraints;
  dealii::AffineConstraints<double>   unconstrained; // (none: the boundary reactions)
  dealii::MatrixFree<dim, double, VA> matrix_free;
  bool                                pressure_coupling = false;
  std::vector<CellData>               cell_data; // [batch * n_q + q]
  std::vector<FaceData>               face_data; // [(face - inner) * n_face_q + q]
  // per boundary face batch: whether any of its coefficients is nonzero (a face
  // without friction, Nitsche slip or backflow adds nothing); found at the first
  // application after an update
  mutable std::vector<bool> face_batch_active;
  // batch * lanes + lane of each locally owned cell, by active cell index
  std::vector<unsigned int> cell_place;
  // (face - inner) * lanes + lane of each boundary face, by active cell index * faces
  // per cell + face number, and MatrixFree's points on it, [place * n_face_q + q]
  std::unordered_map<unsigned int, unsigned int> boundary_face_place;
  std::vector<dealii::Point<dim>>                boundary_face_points;
  // for block b, the local index in the MatrixFree vector of each locally owned
  // element of the block (in the order of the block's owned index set)
  std::array<std::vector<unsigned int>, 2> local_of_block;
  // the constrained owned elements of each block and their diagonal entries
  std::array<std::vector<unsigned int>, 2>                    constrained;
  std::array<std::vector<dealii::types::global_dof_index>, 2> constrained_global;
  std::array<std::vector<double>, 2>                          constrained_diagonal;
  std::vector<unsigned int>       velocity_constrained_local; // owned, MatrixFree layout
  dealii::types::global_dof_index n_velocity_flow_dofs = 0;   // block 0 of the flow
  mutable LocalVector src_u, src_p, dst_u, dst_p, plain_u, plain_p, plain_result;
};
} // namespace wetbed
