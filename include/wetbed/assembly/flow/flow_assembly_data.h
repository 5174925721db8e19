#pragma once

#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/core/time_integration.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace wetbed
{
/** The material data the flow terms read. */
template <int dim>
struct FlowMaterial
{
  double                 gas_density, particle_density, gas_viscosity;
  double                 residual_solids_fraction;
  dealii::Tensor<1, dim> gravity;
};

/** What one flow assembly linearises about: the time step and the fields. */
template <int dim>
struct FlowAssemblyState
{
  using FlowVector   = dealii::TrilinosWrappers::MPI::BlockVector;
  using ScalarVector = dealii::LinearAlgebra::distributed::Vector<double>;

  BDFCoefficients     bdf;
  double              dt;
  const FlowVector   *flow, *flow_old, *flow_old2; // ghosted
  const ScalarVector *alpha, *alpha_old, *alpha_old2, *theta;
};

/**
 * The local index structure of the flow element (Q2^{2 dim} x Q1): the cell DoF of
 * velocity component c (gas 0..dim-1, solids dim..2dim-1) at Q2 basis function a, and
 * of the pressure at Q1 basis function b. The flow terms write their contributions
 * component block by component block through it.
 */
struct FlowElementIndices
{
  template <int dim>
  explicit FlowElementIndices (const dealii::FESystem<dim> &fe);

  unsigned int                           n_dofs, n_velocity_basis, n_pressure_basis;
  std::vector<std::vector<unsigned int>> velocity;  // [component][a]
  std::vector<unsigned int>              pressure;  // [b]
  std::vector<unsigned int>              component; // of each cell DoF
};

/**
 * Per-cell data of the flow assembly (ScratchData for WorkStream): the FE values, the
 * fields at the quadrature points, the closures there (evaluated once by the
 * ClosureEvaluator) and the point quantities the terms share.
 */
template <int dim>
struct FlowCellScratch
{
  FlowCellScratch (const dealii::Mapping<dim>        &mapping,
                   const dealii::FESystem<dim>       &flow_fe,
                   const dealii::FiniteElement<dim>  &alpha_fe,
                   const dealii::Quadrature<dim>     &quadrature,
                   const dealii::Quadrature<dim - 1> &face_quadrature);
  FlowCellScratch (const FlowCellScratch &other);

  // FE values of the flow element's scalar Q2 (velocity) and Q1 (pressure) bases: the
  // terms read the bases as phi/phi_p (one basis per component), so the system's
  // 2 dim + 1 copies are not evaluated on cells (face_values: the flow element)
  dealii::FEValues<dim>     velocity_values, pressure_values, alpha_values;
  dealii::FEFaceValues<dim> face_values, alpha_face_values;
  FlowElementIndices        indices;

  std::vector<double> JxW;
  // the Q2 and Q1 basis at the quadrature points, [q][a]
  std::vector<std::vector<double>>                 phi, phi_p;
  std::vector<std::vector<dealii::Tensor<1, dim>>> grad_phi, grad_phi_p;

  // the fields at the quadrature points; phase k = 0 gas, 1 solids
  std::vector<double>                 alpha_s, alpha_s_old, alpha_s_old2, theta, slip;
  std::vector<dealii::Tensor<1, dim>> grad_alpha_s;
  std::array<std::vector<dealii::Tensor<1, dim>>, 2> u, u_old, u_old2;
  std::array<std::vector<dealii::Tensor<2, dim>>, 2> grad_u;
  dealii::Vector<double>                             alpha_nodal;
  // the cell's flow DoF values of the current, previous and second previous solution,
  // read once per cell (the Trilinos vectors' element access is slow)
  dealii::Vector<double> flow_local, flow_old_local, flow_old2_local;
  closures::CellClosures closures;

  // point quantities several terms read
  std::vector<double> compaction_pressure; // Q1 interpolant of P_s(alpha_j)
  std::array<std::vector<double>, 2> fraction, inertia, viscosity, bulk, bdf_mass;
  double                             h, alpha_mean;

  // the face being assembled (filled by the assembler when a face term acts on it)
  unsigned int                                       face_number;
  std::vector<double>                                face_alpha_s, face_theta;
  std::array<std::vector<dealii::Tensor<1, dim>>, 2> face_u;
  std::vector<dealii::Tensor<2, dim>>                face_grad_u_s;
};

/**
 * On a cell that holds velocity DoFs on the inlet, the walls or the outlet (b = 0, 1,
 * 2; a DoF on two: the first): the sum of its unconstrained rows of boundary b weighted
 * by the component of -g/|g| along each DoF's direction, w_b^T K (row[b]) and w_b^T f
 * (rhs[b]), for the consistent boundary reactions of the momentum budget.
 */
struct BoundaryCellSystem
{
  std::vector<dealii::types::global_dof_index> dofs;
  std::array<std::vector<double>, 3>           row;
  std::array<double, 3>                        rhs;
};

/** The local system of one cell (CopyData for WorkStream). */
struct FlowCellCopy
{
  FlowCellCopy (unsigned int n_dofs, unsigned int n_pressure_dofs);

  dealii::FullMatrix<double> matrix;
  // L_c between the cell's pressure basis functions (FlowElementIndices::pressure)
  dealii::FullMatrix<double> schur;
  // false: the terms add only to the rhs (and L_c), not to `matrix`
  bool                                         with_matrix = true;
  dealii::Vector<double>                       rhs;
  std::vector<dealii::types::global_dof_index> dofs, pressure_dofs;
  bool                                         owned = false;
  // the weighted unconstrained rows of the boundary velocity DoFs (the reactions)
  bool               captured = false;
  BoundaryCellSystem boundary_system;
};
} // namespace wetbed
