#include <wetbed/solvers/component_table.h>
#include <wetbed/solvers/velocity_multigrid.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <unordered_map>

namespace wetbed
{
using namespace dealii;

template <int dim>
VelocityMultigrid<dim>::VelocityMultigrid (const LinearSolverParameters &parameters)
    : parameters (parameters), exact_coarse (parameters.inner_solves == "exact coarse"),
      coarse_fe (FE_Q<dim> (1), 2 * dim), fine_scalar (2),
      jacobi (std::make_shared<NodeBlockJacobi> ())
{
}

template <int dim>
void VelocityMultigrid<dim>::reinit (const MatrixFreeFlowOperator<dim> &op_)
{
  op                          = &op_;
  block.op                    = op;
  coarse_components           = component_to_system_table (coarse_fe);
  fine_components             = component_to_system_table (op->velocity_element ());
  const DoFHandler<dim> &fine = op->velocity_dofs ();
  coarse_dofs.reinit (fine.get_triangulation ());
  coarse_dofs.distribute_dofs (coarse_fe);
  coarse_owned            = coarse_dofs.locally_owned_dofs ();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs (coarse_dofs);
  const MPI_Comm comm     = coarse_dofs.get_communicator ();
  make_coarse_constraints ();
  {
    DynamicSparsityPattern dsp (relevant);
    DoFTools::make_sparsity_pattern (coarse_dofs, dsp, coarse_constraints, false);
    SparsityTools::distribute_sparsity_pattern (dsp, coarse_owned, comm, relevant);
    coarse_matrix.reinit (coarse_owned, coarse_owned, dsp, comm);
  }
  transfer.reinit_polynomial_transfer (
      fine, coarse_dofs, op->velocity_dof_constraints (), coarse_constraints);
  entries.resize (2 * dim);
  for (auto &v : entries)
    op->initialize_velocity_vector (v);
  op->initialize_velocity_vector (residual);
  coarse_residual.reinit (coarse_owned, relevant, comm);
  coarse_solution.reinit (coarse_owned, relevant, comm);
  coarse_rhs_t.reinit (coarse_owned, comm);
  coarse_solution_t.reinit (coarse_owned, comm);

  // the 2 dim velocity DoFs (gas and solids components) of each owned Q2 node
  jacobi->nodes.clear ();
  jacobi->singles.clear ();
  const auto                          &partitioner = *entries[0].get_partitioner ();
  const IndexSet                       owned       = fine.locally_owned_dofs ();
  std::vector<bool>                    seen (partitioner.locally_owned_size (), false);
  const FESystem<dim>                 &fe = op->velocity_element ();
  std::vector<types::global_dof_index> indices (fe.n_dofs_per_cell ());
  for (const auto &cell : fine.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (indices);
      for (unsigned int a = 0; a < fine_scalar.n_dofs_per_cell (); ++a)
      {
        std::array<unsigned int, 2 * dim> node;
        bool                              all_owned = true;
        for (unsigned int c = 0; c < 2 * dim; ++c)
        {
          const auto global = indices[fine_components[c][a]];
          all_owned         = all_owned && owned.is_element (global);
          node[c]           = all_owned ? partitioner.global_to_local (global) : 0;
        }
        if (!all_owned || seen[node[0]])
          continue;
        for (const unsigned int i : node)
          seen[i] = true;
        jacobi->nodes.push_back (node);
      }
    }
  for (unsigned int i = 0; i < seen.size (); ++i)
    if (!seen[i])
      jacobi->singles.push_back (i);
  jacobi->inverse.assign (jacobi->nodes.size () * 4 * dim * dim, 0.0);
}

template <int dim>
void VelocityMultigrid<dim>::make_coarse_constraints ()
{
  // hanging nodes of Q1, and the Q2 constraints that tie vertex DoFs to vertex DoFs
  // (prescribed velocities, no normal flux, periodicity) carried over to the vertices
  coarse_constraints.clear ();
  coarse_constraints.reinit (DoFTools::extract_locally_relevant_dofs (coarse_dofs));
  DoFTools::make_hanging_node_constraints (coarse_dofs, coarse_constraints);
  const DoFHandler<dim> &fine = op->velocity_dofs ();
  std::unordered_map<types::global_dof_index, types::global_dof_index> at_vertex;
  for (const auto &cell : coarse_dofs.active_cell_iterators ())
  {
    if (!cell->is_locally_owned () && !cell->is_ghost ())
      continue;
    const typename DoFHandler<dim>::active_cell_iterator fine_cell (
        &cell->get_triangulation (), cell->level (), cell->index (), &fine);
    for (const unsigned int v : cell->vertex_indices ())
      for (unsigned int c = 0; c < 2 * dim; ++c)
        at_vertex[fine_cell->vertex_dof_index (v, c)] = cell->vertex_dof_index (v, c);
  }
  for (const auto &line : op->velocity_dof_constraints ().get_lines ())
  {
    const auto target = at_vertex.find (line.index);
    if (target == at_vertex.end () || coarse_constraints.is_constrained (target->second))
      continue;
    bool vertices_only = true;
    for (const auto &entry : line.entries)
      vertices_only = vertices_only && at_vertex.count (entry.first) > 0;
    if (!vertices_only)
      continue;
    coarse_constraints.add_line (target->second);
    for (const auto &entry : line.entries)
      coarse_constraints.add_entry (
          target->second, at_vertex.at (entry.first), entry.second);
  }
  coarse_constraints.close ();
}

template <int dim>
void VelocityMultigrid<dim>::begin_update (const bool with_coarse_matrix)
{
  // (the diagnostic exact coarse solve is of the latest coarse matrix)
  coarse_pending = with_coarse_matrix || exact_coarse;
  coarse_current = false;
  if (coarse_pending)
    coarse_matrix = 0;
  for (auto &v : entries)
  {
    v = 0;
    v.zero_out_ghost_values ();
  }
}

namespace
{
/** The boundary bilinear form of phase k between phi_a e_d and phi_b e_e, [d][e], with
 * the mapped normal n_h: friction, backflow (gas) and the Nitsche terms of a slipping
 * phase. */
template <int dim>
Tensor<2, dim> face_block (const FlowFacePointCoefficients<dim> &c,
                           const unsigned int                    k,
                           const Tensor<1, dim>                 &n_h,
                           const double                          phi_a,
                           const double                          phi_b,
                           const Tensor<1, dim>                 &ga,
                           const Tensor<1, dim>                 &gb)
{
  const Tensor<1, dim> &nw = c.wall_normal;
  Tensor<2, dim>        block;
  for (unsigned int d = 0; d < dim; ++d)
    for (unsigned int e = 0; e < dim; ++e)
    {
      double value =
          c.friction[k] * ((d == e ? 1.0 : 0.0) - n_h[d] * n_h[e]) * phi_a * phi_b;
      if (k == 0 && d == e)
        value += c.backflow * phi_a * phi_b;
      if (c.slips[k])
      {
        const double stress_b =
            2 * c.viscosity[k] * nw[e] * (gb * nw) + c.bulk[k] * gb[e];
        const double stress_a =
            2 * c.viscosity[k] * nw[d] * (ga * nw) + c.bulk[k] * ga[d];
        value += -stress_b * phi_a * nw[d] - stress_a * phi_b * nw[e] +
                 c.penalty[k] * phi_a * nw[d] * phi_b * nw[e];
      }
      block[d][e] = value;
    }
  return block;
}
/** The point sums of a cell's coarse (Q1) bilinear form, per phase k: the gradient
 * products G_c[(a, i), (b, j)] = sum_q c_q d_i phi_a d_j phi_b for c = mu_k (shear) and
 * lambda_k (bulk), the scalar part S_k(a, b), and the drag D(a, b). */
template <int dim>
struct CoarseCellSums
{
  static constexpr unsigned int max_n1 = GeometryInfo<dim>::vertices_per_cell,
                                max_g  = max_n1 * dim;
  std::array<std::array<double, max_g * max_g>, 2>   shear{}, bulk{};
  std::array<std::array<double, max_n1 * max_n1>, 2> scalar{};
  std::array<double, max_n1 * max_n1>                drag{};

  /** Into the 2 dim n1 x 2 dim n1 matrix: row (o + d, a), column (o + e, b) of phase k
   * gets G_mu[(a, e), (b, d)] + G_lambda[(a, d), (b, e)], its diagonal blocks d = e
   * also S_k(a, b) + sum_i G_mu[(a, i), (b, i)], the other phase's block -D(a, b). */
  void scatter (const unsigned int n1, FullMatrix<double> &coarse) const
  {
    const unsigned int ng = n1 * dim;
    for (unsigned int k = 0; k < 2; ++k)
    {
      const unsigned int o = k * dim, other = (1 - k) * dim;
      for (unsigned int a = 0; a < n1; ++a)
        for (unsigned int b = 0; b < n1; ++b)
        {
          double same = scalar[k][a * n1 + b];
          for (unsigned int i = 0; i < dim; ++i)
            same += shear[k][(a * dim + i) * ng + b * dim + i];
          for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int row = (o + d) * n1 + a;
            for (unsigned int e = 0; e < dim; ++e)
              coarse (row, (o + e) * n1 + b) +=
                  shear[k][(a * dim + e) * ng + b * dim + d] +
                  bulk[k][(a * dim + d) * ng + b * dim + e];
            coarse (row, (o + d) * n1 + b) += same;
            coarse (row, (other + d) * n1 + b) -= drag[a * n1 + b];
          }
        }
    }
  }
};
} // namespace

template <int dim>
void VelocityMultigrid<dim>::cell_dof_indices (const FlowCell    &cell,
                                               const unsigned int n1,
                                               const unsigned int n2,
                                               LocalData         &local) const
{
  local.local_dof_indices[0].resize (2 * dim * n1);
  local.local_dof_indices[1].resize (2 * dim * n2);
  const typename DoFHandler<dim>::active_cell_iterator coarse_cell (
      &cell->get_triangulation (), cell->level (), cell->index (), &coarse_dofs);
  const typename DoFHandler<dim>::active_cell_iterator fine_cell (
      &cell->get_triangulation (), cell->level (), cell->index (), &op->velocity_dofs ());
  std::vector<types::global_dof_index> coarse_system (2 * dim * n1),
      fine_system (2 * dim * n2);
  coarse_cell->get_dof_indices (coarse_system);
  fine_cell->get_dof_indices (fine_system);
  for (unsigned int c = 0; c < 2 * dim; ++c)
  {
    for (unsigned int a = 0; a < n1; ++a)
      local.local_dof_indices[0][c * n1 + a] = coarse_system[coarse_components[c][a]];
    for (unsigned int a = 0; a < n2; ++a)
      local.local_dof_indices[1][c * n2 + a] = fine_system[fine_components[c][a]];
  }
}

template <int dim>
void VelocityMultigrid<dim>::local_cell (
    const FlowCell                                &cell,
    const FlowCellScratch<dim>                    &s,
    const std::vector<FlowPointCoefficients<dim>> &values,
    LocalData                                     &local) const
{
  // the coarse basis is the assembly's Q1 pressure basis, the fine one its Q2 velocity
  // basis (the same mapping and quadrature); DoF (c, a) of either at c * n + a
  const unsigned int n1 = s.indices.n_pressure_basis, n2 = s.indices.n_velocity_basis;
  local.matrices[0].reinit (coarse_pending ? 2 * dim * n1 : 0,
                            coarse_pending ? 2 * dim * n1 : 0);
  local.vectors[0].reinit (2 * dim * 2 * dim * n2);
  cell_dof_indices (cell, n1, n2, local);

  // the cell bilinear form within phase k between phi_a e_d (test) and phi_b e_e
  // (trial): [(mass_k + drag) phi_a phi_b + inertia_k phi_a (a_k.grad phi_b)
  // + supg_k (a_k.grad phi_a)(a_k.grad phi_b) + mu_k grad phi_a.grad phi_b] delta_de
  // + mu_k d_d phi_b d_e phi_a + lambda_k d_e phi_b d_d phi_a, and -drag phi_a phi_b to
  // the other phase's component d; the weight folded into the coefficients.
  // On the coarse (Q1) basis the point sums are taken first, into dense arrays whose
  // inner loops vectorise (CoarseCellSums), scattered into the 2 dim n1 x 2 dim n1
  // matrix once per cell
  Vector<double>        &blocks = local.vectors[0];
  constexpr unsigned int max_n1 = GeometryInfo<dim>::vertices_per_cell,
                         max_g  = max_n1 * dim;
  AssertThrow (n1 == max_n1 && n2 <= 27, ExcInternalError ());
  const unsigned int         ng = n1 * dim;
  CoarseCellSums<dim>        sums;
  auto                      &shear = sums.shear, &bulk_sum = sums.bulk;
  auto                      &scalar   = sums.scalar;
  auto                      &drag_sum = sums.drag;
  std::array<double, max_g>  gradients;
  std::array<double, max_n1> advective_p;
  std::array<double, 27>     advective_v;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const FlowPointCoefficients<dim> &c     = values[q];
    const double                      w     = s.JxW[q];
    const double                      drag  = c.drag * w;
    const std::vector<double>        &phi_p = s.phi_p[q];
    if (coarse_pending)
    {
      for (unsigned int a = 0; a < n1; ++a)
        for (unsigned int i = 0; i < dim; ++i)
          gradients[a * dim + i] = s.grad_phi_p[q][a][i];
      for (unsigned int a = 0; a < n1; ++a)
        for (unsigned int b = 0; b < n1; ++b)
          drag_sum[a * n1 + b] += drag * phi_p[a] * phi_p[b];
    }
    for (unsigned int k = 0; k < 2; ++k)
    {
      const unsigned int o = k * dim, other = (1 - k) * dim;
      const double       mass = (c.mass[k] + c.drag) * w, inertia = c.inertia[k] * w,
                   supg = c.supg[k] * w, viscosity = c.viscosity[k] * w,
                   bulk = c.bulk[k] * w;
      for (unsigned int r = 0; r < ng && coarse_pending; ++r)
      {
        const double shear_r = viscosity * gradients[r], bulk_r = bulk * gradients[r];
        double      *shear_row = &shear[k][r * ng], *bulk_row = &bulk_sum[k][r * ng];
        for (unsigned int t = 0; t < ng; ++t)
        {
          shear_row[t] += shear_r * gradients[t];
          bulk_row[t] += bulk_r * gradients[t];
        }
      }
      if (coarse_pending)
      {
        for (unsigned int a = 0; a < n1; ++a)
          advective_p[a] = c.advection[k] * s.grad_phi_p[q][a];
        for (unsigned int a = 0; a < n1; ++a)
          for (unsigned int b = 0; b < n1; ++b)
            scalar[k][a * n1 + b] += mass * phi_p[a] * phi_p[b] +
                                     inertia * phi_p[a] * advective_p[b] +
                                     supg * advective_p[a] * advective_p[b];
      }
      // the node blocks: entry ((o + d, a), ((o + d + offset) mod 2 dim, a)) at
      // offset * 2 dim n2 + (o + d) n2 + a
      for (unsigned int a = 0; a < n2; ++a)
        advective_v[a] = c.advection[k] * s.grad_phi[q][a];
      for (unsigned int a = 0; a < n2; ++a)
      {
        const double          phi = s.phi[q][a], adv = advective_v[a];
        const Tensor<1, dim> &g = s.grad_phi[q][a];
        const double same = mass * phi * phi + inertia * phi * adv + supg * adv * adv +
                            viscosity * (g * g);
        for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int row = (o + d) * n2 + a;
          for (unsigned int e = 0; e < dim; ++e)
            blocks[((e + 2 * dim - d) % (2 * dim)) * 2 * dim * n2 + row] +=
                (viscosity + bulk) * g[d] * g[e] + (d == e ? same : 0.0);
          blocks[((other + 2 * dim - o) % (2 * dim)) * 2 * dim * n2 + row] -=
              drag * phi * phi;
        }
      }
    }
  }
  if (coarse_pending)
    sums.scatter (n1, local.matrices[0]);
}

template <int dim>
void VelocityMultigrid<dim>::local_face (const FlowCell &,
                                         const unsigned int,
                                         const FlowCellScratch<dim>  &s,
                                         const FaceCoefficients<dim> &face,
                                         LocalData                   &local) const
{
  const unsigned int  n1 = s.indices.n_pressure_basis, n2 = s.indices.n_velocity_basis;
  const auto         &ff     = s.face_values;
  FullMatrix<double> &coarse = local.matrices[0];
  Vector<double>     &blocks = local.vectors[0];
  for (unsigned int q = 0; q < ff.n_quadrature_points; ++q)
  {
    const FlowFacePointCoefficients<dim> &c   = face.values[q];
    const Tensor<1, dim>                  n_h = ff.normal_vector (q);
    const double                          w   = ff.JxW (q);
    for (unsigned int k = 0; k < 2; ++k)
    {
      const unsigned int o = k * dim;
      for (unsigned int a = 0; a < n1 && coarse_pending; ++a)
        for (unsigned int b = 0; b < n1; ++b)
        {
          const unsigned int   i = s.indices.pressure[a], j = s.indices.pressure[b];
          const Tensor<2, dim> block = face_block (c,
                                                   k,
                                                   n_h,
                                                   ff.shape_value (i, q),
                                                   ff.shape_value (j, q),
                                                   ff.shape_grad (i, q),
                                                   ff.shape_grad (j, q));
          for (unsigned int d = 0; d < dim; ++d)
            for (unsigned int e = 0; e < dim; ++e)
              coarse ((o + d) * n1 + a, (o + e) * n1 + b) += block[d][e] * w;
        }
      for (unsigned int a = 0; a < n2; ++a)
      {
        const unsigned int   i     = s.indices.velocity[0][a];
        const double         phi   = ff.shape_value (i, q);
        const Tensor<1, dim> grad  = ff.shape_grad (i, q);
        const Tensor<2, dim> block = face_block (c, k, n_h, phi, phi, grad, grad);
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int e = 0; e < dim; ++e)
            blocks[((e + 2 * dim - d) % (2 * dim)) * 2 * dim * n2 + (o + d) * n2 + a] +=
                block[d][e] * w;
      }
    }
  }
}

template <int dim>
void VelocityMultigrid<dim>::distribute (const FlowCell &,
                                         const CellCoefficients<dim> &,
                                         const LocalData &local)
{
  if (coarse_pending)
    coarse_constraints.distribute_local_to_global (
        local.matrices[0], local.local_dof_indices[0], coarse_matrix);
  // node-block entries between unconstrained DoFs as they are; a constrained DoF adds
  // w^2 times its diagonal to each master's diagonal (the diagonal of C^T A C with one
  // entry per row, cross terms left out): w, not w^2, would make the masters of a
  // no-normal-flux constraint (w = -n_x/n_y < 0) lose diagonal
  const AffineConstraints<double> &constraints       = op->velocity_dof_constraints ();
  const std::vector<types::global_dof_index> &dofs   = local.local_dof_indices[1];
  const Vector<double>                       &blocks = local.vectors[0];
  const unsigned int                          n = dofs.size (), n2 = n / (2 * dim);
  for (unsigned int c = 0; c < 2 * dim; ++c)
    for (unsigned int a = 0; a < n2; ++a)
    {
      const unsigned int i = c * n2 + a;
      if (constraints.is_constrained (dofs[i]))
      {
        if (const auto *masters = constraints.get_constraint_entries (dofs[i]))
          for (const auto &[master, weight] : *masters)
            entries[0](master) += weight * weight * blocks[i];
        continue;
      }
      for (unsigned int o = 0; o < 2 * dim; ++o)
        if (o == 0 || !constraints.is_constrained (dofs[((c + o) % (2 * dim)) * n2 + a]))
          entries[o](dofs[i]) += blocks[o * n + i];
    }
}

template <int dim>
void VelocityMultigrid<dim>::end_update ()
{
  if (coarse_pending)
    coarse_matrix.compress (VectorOperation::add);
  coarse_current = coarse_pending;
  for (auto &v : entries)
    v.compress (VectorOperation::add);
  const auto            &constraints = op->velocity_dof_constraints ();
  const auto            &partitioner = *entries[0].get_partitioner ();
  constexpr unsigned int m           = 2 * dim;
  FullMatrix<double>     block (m, m), inverse (m, m);
  for (unsigned int p = 0; p < jacobi->nodes.size (); ++p)
  {
    const auto         &node = jacobi->nodes[p];
    std::array<bool, m> fixed;
    for (unsigned int c = 0; c < m; ++c)
      fixed[c] = constraints.is_constrained (partitioner.local_to_global (node[c]));
    for (unsigned int c = 0; c < m; ++c)
      for (unsigned int o = 0; o < m; ++o)
      {
        const unsigned int column = (c + o) % m;
        block (c, column)         = (fixed[c] || fixed[column])
                                        ? (c == column ? 1.0 : 0.0)
                                        : entries[o].local_element (node[c]);
      }
    inverse.invert (block);
    for (unsigned int c = 0; c < m; ++c)
      for (unsigned int d = 0; d < m; ++d)
        jacobi->inverse[p * m * m + c * m + d] = inverse (c, d);
  }
}

template <int dim>
void VelocityMultigrid<dim>::NodeBlockJacobi::vmult (LocalVector       &dst,
                                                     const LocalVector &src) const
{
  constexpr unsigned int m = 2 * dim;
  for (unsigned int p = 0; p < nodes.size (); ++p)
  {
    const auto &node = nodes[p];
    double      x[m];
    for (unsigned int c = 0; c < m; ++c)
      x[c] = src.local_element (node[c]);
    const double *row = &inverse[p * m * m];
    for (unsigned int c = 0; c < m; ++c, row += m)
    {
      double y = 0;
      for (unsigned int d = 0; d < m; ++d)
        y += row[d] * x[d];
      dst.local_element (node[c]) = y;
    }
  }
  for (const unsigned int i : singles)
    dst.local_element (i) = src.local_element (i);
}

template <int dim>
void VelocityMultigrid<dim>::rebuild ()
{
  AssertThrow (coarse_current,
               ExcMessage ("the p-multigrid's coarse AMG is built from a coarse matrix "
                           "that the last flow assembly left out"));
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic              = true;
  data.higher_order_elements = false;
  // one Chebyshev sweep on the coarse Q1 levels: 3D column on 2 ranks, 2 steps at 6,336
  // cells: 64 FGMRES iterations and 8.2 s of Krylov time against 70 and 9.7 s with 2
  // (3: 76, 11.4 s); at 792 cells the same 84 iterations, 1.44 against 1.50 s
  data.smoother_sweeps       = 1;
  data.aggregation_threshold = parameters.aggregation_threshold;
  DoFTools::extract_constant_modes (
      coarse_dofs, ComponentMask (2 * dim, true), data.constant_modes);
  Teuchos::ParameterList              ml;
  std::unique_ptr<Epetra_MultiVector> constant_modes; // (what ML's list points to)
  data.set_parameters (ml, constant_modes, coarse_matrix.trilinos_matrix ());
  // a coarsest ML level of at most 200 DoFs (deal.II's 2000 factorises a 3D Q1
  // vector Laplacian by KLU, gathered on one rank, at every rebuild and solves with it
  // in every V-cycle): 3D column at 792 cells, 2 ranks, 9 steps: 174 FGMRES iterations
  // against 172 and the preconditioner set-up 0.35 against 0.50 s
  ml.set ("coarse: max size", 200);
  coarse_amg.initialize (coarse_matrix, ml);

  typename Smoother::AdditionalData smoothing;
  smoothing.degree              = parameters.multigrid_degree;
  smoothing.smoothing_range     = 20;
  smoothing.eig_cg_n_iterations = 12;
  smoothing.preconditioner      = jacobi;
  smoother.initialize (block, smoothing);
  ++builds;
}

template <int dim>
void VelocityMultigrid<dim>::vmult (LocalVector &dst, const LocalVector &src) const
{
  smoother.vmult (dst, src);
  block.vmult (residual, dst);
  residual.sadd (-1.0, 1.0, src);
  coarse_residual = 0;
  transfer.restrict_and_add (coarse_residual, residual);
  std::copy (coarse_residual.begin (), coarse_residual.end (), coarse_rhs_t.begin ());
  if (exact_coarse)
  {
    // diagnosis (`inner solves = exact coarse`): the Q1 problem solved to 1e-10
    SolverControl control (10000, 1e-10 * coarse_rhs_t.l2_norm () + 1e-300);
    TrilinosWrappers::SolverGMRES gmres (control);
    coarse_solution_t = 0;
    gmres.solve (coarse_matrix, coarse_solution_t, coarse_rhs_t, coarse_amg);
    coarse_iterations += control.last_step ();
    ++coarse_solves;
  }
  else
    coarse_amg.vmult (coarse_solution_t, coarse_rhs_t);
  std::copy (
      coarse_solution_t.begin (), coarse_solution_t.end (), coarse_solution.begin ());
  transfer.prolongate_and_add (dst, coarse_solution);
  smoother.step (dst, src);
}

template <int dim>
std::size_t VelocityMultigrid<dim>::memory_consumption () const
{
  std::size_t bytes =
      coarse_dofs.memory_consumption () + coarse_constraints.memory_consumption () +
      coarse_matrix.memory_consumption () + transfer.memory_consumption ();
  if (jacobi)
    bytes += jacobi->nodes.size () * sizeof (jacobi->nodes[0]) +
             jacobi->inverse.size () * sizeof (double) +
             jacobi->singles.size () * sizeof (unsigned int);
  for (const auto &v : entries)
    bytes += v.memory_consumption ();
  for (const LocalVector *v : {&residual, &coarse_residual, &coarse_solution})
    bytes += v->memory_consumption ();
  return bytes + coarse_rhs_t.memory_consumption () +
         coarse_solution_t.memory_consumption ();
}

template class VelocityMultigrid<2>;
template class VelocityMultigrid<3>;
} // namespace wetbed
