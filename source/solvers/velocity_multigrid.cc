#include <wetbed/solvers/velocity_multigrid.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <unordered_map>

namespace wetbed
{
using namespace dealii;

template <int dim>
VelocityMultigrid<dim>::VelocityMultigrid (const LinearSolverParameters &parameters)
    : parameters (parameters), coarse_fe (FE_Q<dim> (1), 2 * dim), fine_scalar (2),
      coarse_scalar (1), jacobi (std::make_shared<NodeBlockJacobi> ())
{
}

template <int dim>
void VelocityMultigrid<dim>::reinit (const Mapping<dim>                &mapping_,
                                     const MatrixFreeFlowOperator<dim> &op_)
{
  op                          = &op_;
  mapping                     = &mapping_;
  block.op                    = op;
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
  op->initialize_velocity_vector (diagonal);
  op->initialize_velocity_vector (coupling);
  op->initialize_velocity_vector (residual);
  coarse_residual.reinit (coarse_owned, relevant, comm);
  coarse_solution.reinit (coarse_owned, relevant, comm);
  coarse_rhs_t.reinit (coarse_owned, comm);
  coarse_solution_t.reinit (coarse_owned, comm);

  // the (gas, solids) pairs of each owned Q2 node and direction
  jacobi->pairs.clear ();
  jacobi->singles.clear ();
  const auto                          &partitioner = *diagonal.get_partitioner ();
  const IndexSet                       owned       = fine.locally_owned_dofs ();
  std::vector<bool>                    seen (partitioner.locally_owned_size (), false);
  const FESystem<dim>                 &fe = op->velocity_element ();
  std::vector<types::global_dof_index> indices (fe.n_dofs_per_cell ());
  for (const auto &cell : fine.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (indices);
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int a = 0; a < fine_scalar.n_dofs_per_cell (); ++a)
        {
          const auto g = indices[fe.component_to_system_index (d, a)];
          const auto s = indices[fe.component_to_system_index (dim + d, a)];
          if (!owned.is_element (g) || !owned.is_element (s))
            continue;
          const unsigned int lg = partitioner.global_to_local (g),
                             ls = partitioner.global_to_local (s);
          if (seen[lg])
            continue;
          seen[lg] = seen[ls] = true;
          jacobi->pairs.push_back ({{lg, ls}});
        }
    }
  for (unsigned int i = 0; i < seen.size (); ++i)
    if (!seen[i])
      jacobi->singles.push_back (i);
  jacobi->inverse.assign (jacobi->pairs.size (), {{1, 0, 0, 1}});

  const QGauss<dim>     quadrature (3);
  const QGauss<dim - 1> face_quadrature (3);
  const UpdateFlags     flags = update_values | update_gradients | update_JxW_values;
  coarse_values =
      std::make_unique<FEValues<dim>> (*mapping, coarse_scalar, quadrature, flags);
  coarse_face_values = std::make_unique<FEFaceValues<dim>> (
      *mapping, coarse_scalar, face_quadrature, flags | update_normal_vectors);
  fine_face_values = std::make_unique<FEFaceValues<dim>> (
      *mapping, fine_scalar, face_quadrature, flags | update_normal_vectors);
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
void VelocityMultigrid<dim>::begin_update ()
{
  coarse_matrix = 0;
  diagonal      = 0;
  coupling      = 0;
}

template <int dim>
void VelocityMultigrid<dim>::add_cell (
    const FlowCell                                                   &cell,
    const FlowCellScratch<dim>                                       &scratch,
    const std::vector<FlowPointCoefficients<dim>>                    &values,
    const std::vector<typename FlowAssembler<dim>::FaceCoefficients> &faces)
{
  assemble_coarse_cell (cell, values, faces);
  add_fine_diagonal (cell, scratch, values, faces);
}

template <int dim>
void VelocityMultigrid<dim>::assemble_coarse_cell (
    const FlowCell                                                   &cell,
    const std::vector<FlowPointCoefficients<dim>>                    &values,
    const std::vector<typename FlowAssembler<dim>::FaceCoefficients> &faces)
{
  const unsigned int n1 = coarse_scalar.n_dofs_per_cell (), n = 2 * dim * n1;
  FullMatrix<double> local (n, n);
  auto               at = [n1] (unsigned int c, unsigned int a) { return c * n1 + a; };
  const typename Triangulation<dim>::cell_iterator tria_cell (cell);
  coarse_values->reinit (tria_cell);
  const auto         &fv = *coarse_values;
  std::vector<double> advective (n1);
  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
  {
    const FlowPointCoefficients<dim> &c   = values[q];
    const double                      JxW = fv.JxW (q);
    for (unsigned int k = 0; k < 2; ++k)
    {
      for (unsigned int b = 0; b < n1; ++b)
        advective[b] = c.advection[k] * fv.shape_grad (b, q);
      for (unsigned int a = 0; a < n1; ++a)
        for (unsigned int b = 0; b < n1; ++b)
        {
          const double phi_ab = fv.shape_value (a, q) * fv.shape_value (b, q);
          const auto  &ga = fv.shape_grad (a, q), &gb = fv.shape_grad (b, q);
          const double same = (c.mass[k] + c.drag) * phi_ab +
                              c.inertia[k] * fv.shape_value (a, q) * advective[b] +
                              c.supg[k] * advective[a] * advective[b] +
                              c.viscosity[k] * (ga * gb);
          for (unsigned int d = 0; d < dim; ++d)
          {
            local (at (k * dim + d, a), at (k * dim + d, b)) += same * JxW;
            local (at (k * dim + d, a), at ((1 - k) * dim + d, b)) -=
                c.drag * phi_ab * JxW;
            for (unsigned int e = 0; e < dim; ++e)
              local (at (k * dim + d, a), at (k * dim + e, b)) +=
                  (c.viscosity[k] * gb[d] * ga[e] + c.bulk[k] * gb[e] * ga[d]) * JxW;
          }
        }
    }
  }
  for (unsigned int f = 0; f < faces.size (); ++f)
  {
    if (faces[f].values.empty ())
      continue;
    coarse_face_values->reinit (tria_cell, f);
    const auto &ff = *coarse_face_values;
    for (unsigned int q = 0; q < ff.n_quadrature_points; ++q)
    {
      const FlowFacePointCoefficients<dim> &c   = faces[f].values[q];
      const Tensor<1, dim>                  n_h = ff.normal_vector (q);
      const Tensor<1, dim>                 &nw  = c.wall_normal;
      const double                          JxW = ff.JxW (q);
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int a = 0; a < n1; ++a)
          for (unsigned int b = 0; b < n1; ++b)
          {
            const double phi_a = ff.shape_value (a, q), phi_b = ff.shape_value (b, q);
            const auto  &ga = ff.shape_grad (a, q), &gb = ff.shape_grad (b, q);
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int e = 0; e < dim; ++e)
              {
                double value = c.friction[k] * ((d == e ? 1.0 : 0.0) - n_h[d] * n_h[e]) *
                               phi_a * phi_b;
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
                local (at (k * dim + d, a), at (k * dim + e, b)) += value * JxW;
              }
          }
    }
  }
  const typename DoFHandler<dim>::active_cell_iterator coarse_cell (
      &cell->get_triangulation (), cell->level (), cell->index (), &coarse_dofs);
  std::vector<types::global_dof_index> system (n), dofs (n);
  coarse_cell->get_dof_indices (system);
  for (unsigned int c = 0; c < 2 * dim; ++c)
    for (unsigned int a = 0; a < n1; ++a)
      dofs[at (c, a)] = system[coarse_fe.component_to_system_index (c, a)];
  coarse_constraints.distribute_local_to_global (local, dofs, coarse_matrix);
}

template <int dim>
void VelocityMultigrid<dim>::add_fine_diagonal (
    const FlowCell                                                   &cell,
    const FlowCellScratch<dim>                                       &s,
    const std::vector<FlowPointCoefficients<dim>>                    &values,
    const std::vector<typename FlowAssembler<dim>::FaceCoefficients> &faces)
{
  const unsigned int n2 = fine_scalar.n_dofs_per_cell (), n = 2 * dim * n2;
  Vector<double>     local_diagonal (n), local_coupling (n);
  auto               at = [n2] (unsigned int c, unsigned int a) { return c * n2 + a; };
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const FlowPointCoefficients<dim> &c = values[q];
    const double                      w = s.JxW[q];
    for (unsigned int a = 0; a < n2; ++a)
    {
      const double          phi  = s.phi[q][a];
      const Tensor<1, dim> &grad = s.grad_phi[q][a];
      for (unsigned int k = 0; k < 2; ++k)
      {
        const double advective = c.advection[k] * grad;
        const double base =
            (c.mass[k] + c.drag) * phi * phi + c.inertia[k] * phi * advective +
            c.supg[k] * advective * advective + c.viscosity[k] * (grad * grad);
        for (unsigned int d = 0; d < dim; ++d)
          local_diagonal (at (k * dim + d, a)) +=
              (base + (c.viscosity[k] + c.bulk[k]) * grad[d] * grad[d]) * w;
      }
      for (unsigned int d = 0; d < dim; ++d)
        local_coupling (at (d, a)) -= c.drag * phi * phi * w;
    }
  }
  const typename Triangulation<dim>::cell_iterator tria_cell (cell);
  for (unsigned int f = 0; f < faces.size (); ++f)
  {
    if (faces[f].values.empty ())
      continue;
    fine_face_values->reinit (tria_cell, f);
    const auto &ff = *fine_face_values;
    for (unsigned int q = 0; q < ff.n_quadrature_points; ++q)
    {
      const FlowFacePointCoefficients<dim> &c   = faces[f].values[q];
      const Tensor<1, dim>                  n_h = ff.normal_vector (q);
      const Tensor<1, dim>                 &nw  = c.wall_normal;
      for (unsigned int a = 0; a < n2; ++a)
      {
        const double          phi  = ff.shape_value (a, q);
        const Tensor<1, dim> &grad = ff.shape_grad (a, q);
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int d = 0; d < dim; ++d)
          {
            double value = c.friction[k] * (1 - n_h[d] * n_h[d]) * phi * phi;
            if (k == 0)
              value += c.backflow * phi * phi;
            if (c.slips[k])
            {
              const double stress =
                  2 * c.viscosity[k] * nw[d] * (grad * nw) + c.bulk[k] * grad[d];
              value +=
                  -2 * stress * phi * nw[d] + c.penalty[k] * phi * phi * nw[d] * nw[d];
            }
            local_diagonal (at (k * dim + d, a)) += value * ff.JxW (q);
          }
      }
    }
  }
  const typename DoFHandler<dim>::active_cell_iterator fine_cell (
      &cell->get_triangulation (), cell->level (), cell->index (), &op->velocity_dofs ());
  const FESystem<dim>                 &fe = op->velocity_element ();
  std::vector<types::global_dof_index> system (n), dofs (n);
  fine_cell->get_dof_indices (system);
  for (unsigned int c = 0; c < 2 * dim; ++c)
    for (unsigned int a = 0; a < n2; ++a)
      dofs[at (c, a)] = system[fe.component_to_system_index (c, a)];
  // a constrained entry adds w^2 times its diagonal to each master (the diagonal of
  // C^T A C where C has one entry per row; cross terms left out): w, not w^2, would make
  // the masters of a no-normal-flux constraint (w = -n_x/n_y < 0) lose diagonal
  const AffineConstraints<double> &constraints = op->velocity_dof_constraints ();
  for (unsigned int i = 0; i < n; ++i)
  {
    const auto *entries = constraints.get_constraint_entries (dofs[i]);
    if (!constraints.is_constrained (dofs[i]))
    {
      diagonal (dofs[i]) += local_diagonal (i);
      coupling (dofs[i]) += local_coupling (i);
    }
    else if (entries != nullptr)
      for (const auto &[master, weight] : *entries)
        diagonal (master) += weight * weight * local_diagonal (i);
  }
}

template <int dim>
void VelocityMultigrid<dim>::end_update ()
{
  coarse_matrix.compress (VectorOperation::add);
  diagonal.compress (VectorOperation::add);
  coupling.compress (VectorOperation::add);
  const auto &constraints = op->velocity_dof_constraints ();
  const auto &partitioner = *diagonal.get_partitioner ();
  auto        constrained = [&] (const unsigned int local)
  { return constraints.is_constrained (partitioner.local_to_global (local)); };
  for (unsigned int p = 0; p < jacobi->pairs.size (); ++p)
  {
    const auto [g, s] = jacobi->pairs[p];
    double a = diagonal.local_element (g), b = diagonal.local_element (s),
           c = coupling.local_element (g);
    if (constrained (g) || constrained (s))
    {
      c = 0;
      a = constrained (g) ? 1.0 : a;
      b = constrained (s) ? 1.0 : b;
    }
    const double det = a * b - c * c;
    AssertThrow (std::isfinite (det) && det != 0,
                 ExcMessage ("velocity multigrid: a singular node block"));
    jacobi->inverse[p] = {{b / det, -c / det, -c / det, a / det}};
  }
}

template <int dim>
void VelocityMultigrid<dim>::NodeBlockJacobi::vmult (LocalVector       &dst,
                                                     const LocalVector &src) const
{
  for (unsigned int p = 0; p < pairs.size (); ++p)
  {
    const auto [g, s] = pairs[p];
    const double x = src.local_element (g), y = src.local_element (s);
    const auto  &m        = inverse[p];
    dst.local_element (g) = m[0] * x + m[1] * y;
    dst.local_element (s) = m[2] * x + m[3] * y;
  }
  for (const unsigned int i : singles)
    dst.local_element (i) = src.local_element (i);
}

template <int dim>
void VelocityMultigrid<dim>::rebuild ()
{
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic              = true;
  data.higher_order_elements = false;
  data.smoother_sweeps       = 2;
  data.aggregation_threshold = parameters.aggregation_threshold;
  DoFTools::extract_constant_modes (
      coarse_dofs, ComponentMask (2 * dim, true), data.constant_modes);
  coarse_amg.initialize (coarse_matrix, data);

  typename Smoother::AdditionalData smoothing;
  smoothing.degree              = parameters.smoother_sweeps;
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
  coarse_amg.vmult (coarse_solution_t, coarse_rhs_t);
  std::copy (
      coarse_solution_t.begin (), coarse_solution_t.end (), coarse_solution.begin ());
  transfer.prolongate_and_add (dst, coarse_solution);
  smoother.step (dst, src);
}

template class VelocityMultigrid<2>;
template class VelocityMultigrid<3>;
} // namespace wetbed
