#include <wetbed/core/input_error.h>
#include <wetbed/solvers/matrix_free_flow_operator.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/matrix_free/fe_evaluation.h>

#include <unordered_map>

namespace wetbed
{
using namespace dealii;

namespace
{
constexpr unsigned int velocity_degree = 2, n_q_1d = 3;
} // namespace

template <int dim>
MatrixFreeFlowOperator<dim>::MatrixFreeFlowOperator ()
    : velocity_fe (FE_Q<dim> (velocity_degree), 2 * dim), pressure_fe (1)
{
}

template <int dim>
void MatrixFreeFlowOperator<dim>::reinit (
    const Mapping<dim>              &mapping,
    const DoFHandler<dim>           &flow_dofs,
    const std::vector<IndexSet>     &owned,
    const AffineConstraints<double> &flow_constraints)
{
  flow_dof_handler = &flow_dofs;
  velocity_dof_handler.reinit (flow_dofs.get_triangulation ());
  velocity_dof_handler.distribute_dofs (velocity_fe);
  pressure_dof_handler.reinit (flow_dofs.get_triangulation ());
  pressure_dof_handler.distribute_dofs (pressure_fe);
  build_maps (flow_dofs, owned, flow_constraints);

  typename MatrixFree<dim, double, VA>::AdditionalData data;
  data.tasks_parallel_scheme = MatrixFree<dim, double, VA>::AdditionalData::none;
  data.mapping_update_flags =
      update_values | update_gradients | update_JxW_values | update_quadrature_points;
  data.mapping_update_flags_boundary_faces = update_values | update_gradients |
                                             update_JxW_values | update_normal_vectors |
                                             update_quadrature_points;
  // 0, 1: with the constraints (the operator); 2, 3: without any (the unconstrained
  // rows of the boundary reactions)
  const std::vector<const DoFHandler<dim> *> handlers = {&velocity_dof_handler,
                                                         &pressure_dof_handler,
                                                         &velocity_dof_handler,
                                                         &pressure_dof_handler};
  unconstrained.clear ();
  unconstrained.close ();
  const std::vector<const AffineConstraints<double> *> constraints = {
      &velocity_constraints, &pressure_constraints, &unconstrained, &unconstrained};
  matrix_free.reinit (mapping, handlers, constraints, QGauss<1> (n_q_1d), data);
  matrix_free.initialize_dof_vector (src_u, 0);
  matrix_free.initialize_dof_vector (dst_u, 0);
  matrix_free.initialize_dof_vector (src_p, 1);
  matrix_free.initialize_dof_vector (dst_p, 1);
  matrix_free.initialize_dof_vector (plain_u, 2);
  matrix_free.initialize_dof_vector (plain_p, 3);
  matrix_free.initialize_dof_vector (plain_result, 2);

  // the MatrixFree vectors' local positions of the flow blocks' owned elements
  const LocalVector *layout[2] = {&src_u, &src_p};
  for (unsigned int b = 0; b < 2; ++b)
    for (auto &index : local_of_block[b])
      index = layout[b]->get_partitioner ()->global_to_local (index);
  velocity_constrained_local.clear ();
  const IndexSet velocity_owned = velocity_dof_handler.locally_owned_dofs ();
  for (const auto index : velocity_owned)
    if (velocity_constraints.is_constrained (index))
      velocity_constrained_local.push_back (
          src_u.get_partitioner ()->global_to_local (index));
  cell_data.clear ();
  face_data.clear ();
  find_batch_places ();
}

template <int dim>
void MatrixFreeFlowOperator<dim>::find_batch_places ()
{
  const unsigned int lanes = VA::size ();
  cell_place.assign (velocity_dof_handler.get_triangulation ().n_active_cells (),
                     numbers::invalid_unsigned_int);
  for (unsigned int batch = 0; batch < matrix_free.n_cell_batches (); ++batch)
    for (unsigned int lane = 0;
         lane < matrix_free.n_active_entries_per_cell_batch (batch);
         ++lane)
      cell_place[matrix_free.get_cell_iterator (batch, lane, 0)->active_cell_index ()] =
          batch * lanes + lane;

  const unsigned int n_fq       = Utilities::pow (n_q_1d, dim - 1);
  const unsigned int first      = matrix_free.n_inner_face_batches (),
                     n_boundary = matrix_free.n_boundary_face_batches ();
  boundary_face_place.clear ();
  boundary_face_points.assign (n_boundary * lanes * n_fq, Point<dim> ());
  FEFaceEvaluation<dim, velocity_degree, n_q_1d, 2 * dim, double> phi (
      matrix_free, true, 0);
  for (unsigned int face = first; face < first + n_boundary; ++face)
  {
    phi.reinit (face);
    for (unsigned int lane = 0; lane < matrix_free.n_active_entries_per_face_batch (face);
         ++lane)
    {
      const auto [cell, face_number]   = matrix_free.get_face_iterator (face, lane, true);
      const unsigned int place         = (face - first) * lanes + lane;
      boundary_face_place[cell->active_cell_index () * GeometryInfo<dim>::faces_per_cell +
                          face_number] = place;
      for (unsigned int q = 0; q < n_fq; ++q)
        for (unsigned int e = 0; e < dim; ++e)
          boundary_face_points[place * n_fq + q][e] = phi.quadrature_point (q)[e][lane];
    }
  }
}

template <int dim>
void MatrixFreeFlowOperator<dim>::build_maps (
    const DoFHandler<dim>           &flow_dofs,
    const std::vector<IndexSet>     &owned,
    const AffineConstraints<double> &flow_constraints)
{
  // flow DoF -> (block, DoF of the velocity or pressure handler), on every cell this
  // rank sees (the constraints of the locally relevant DoFs need their masters)
  std::unordered_map<types::global_dof_index, types::global_dof_index> target;
  const FiniteElement<dim>            &flow_fe = flow_dofs.get_fe ();
  std::vector<types::global_dof_index> flow_indices (flow_fe.n_dofs_per_cell ()),
      velocity_indices (velocity_fe.n_dofs_per_cell ()),
      pressure_indices (pressure_fe.n_dofs_per_cell ());
  const unsigned int n_velocity_components = 2 * dim;
  for (const auto &cell : flow_dofs.active_cell_iterators ())
  {
    if (!cell->is_locally_owned () && !cell->is_ghost ())
      continue;
    cell->get_dof_indices (flow_indices);
    typename DoFHandler<dim>::active_cell_iterator (&cell->get_triangulation (),
                                                    cell->level (),
                                                    cell->index (),
                                                    &velocity_dof_handler)
        ->get_dof_indices (velocity_indices);
    typename DoFHandler<dim>::active_cell_iterator (&cell->get_triangulation (),
                                                    cell->level (),
                                                    cell->index (),
                                                    &pressure_dof_handler)
        ->get_dof_indices (pressure_indices);
    for (unsigned int i = 0; i < flow_indices.size (); ++i)
    {
      const auto [component, a] = flow_fe.system_to_component_index (i);
      target[flow_indices[i]] =
          component < n_velocity_components
              ? velocity_indices[velocity_fe.component_to_system_index (component, a)]
              : pressure_indices[a];
    }
  }

  const types::global_dof_index n_velocity = owned[0].size ();
  n_velocity_flow_dofs                     = n_velocity;
  const IndexSet own[2]                    = {velocity_dof_handler.locally_owned_dofs (),
                                              pressure_dof_handler.locally_owned_dofs ()};
  for (unsigned int b = 0; b < 2; ++b)
  {
    local_of_block[b].clear ();
    constrained[b].clear ();
    constrained_global[b].clear ();
    unsigned int i = 0;
    for (const auto index : owned[b])
    {
      const types::global_dof_index global = index + (b == 1 ? n_velocity : 0);
      const types::global_dof_index mapped = target.at (global);
      AssertThrow (own[b].is_element (mapped),
                   ExcMessage ("matrix-free flow operator: a flow DoF and its velocity/"
                               "pressure DoF are owned by different ranks"));
      local_of_block[b].push_back (mapped); // made local in reinit()
      if (flow_constraints.is_constrained (global))
      {
        constrained[b].push_back (i);
        constrained_global[b].push_back (index);
      }
      ++i;
    }
    constrained_diagonal[b].assign (constrained[b].size (), 1.0);
  }

  // the homogeneous part of the flow constraints, in the new numberings
  AffineConstraints<double> *translated[2] = {&velocity_constraints,
                                              &pressure_constraints};
  const IndexSet             relevant[2]   = {
                    DoFTools::extract_locally_relevant_dofs (velocity_dof_handler),
                    DoFTools::extract_locally_relevant_dofs (pressure_dof_handler)};
  for (unsigned int b = 0; b < 2; ++b)
  {
    translated[b]->clear ();
    translated[b]->reinit (relevant[b]);
  }
  for (const auto &line : flow_constraints.get_lines ())
  {
    const auto found = target.find (line.index);
    if (found == target.end ())
      continue;
    const unsigned int b = line.index < n_velocity ? 0 : 1;
    translated[b]->add_line (found->second);
    for (const auto &entry : line.entries)
      translated[b]->add_entry (found->second, target.at (entry.first), entry.second);
  }
  for (unsigned int b = 0; b < 2; ++b)
    translated[b]->close ();
}

template <int dim>
void MatrixFreeFlowOperator<dim>::begin_update (const FlowAssembler<dim> &assembler)
{
  const std::string missing = assembler.term_without_coefficients ();
  require (missing.empty (),
           "linear solver/operator",
           "matrix-free cannot apply the flow term '" + missing +
               "' (it has no matrix-free coefficients); use 'assembled'");
  const unsigned int n_q  = Utilities::pow (n_q_1d, dim);
  const unsigned int n_fq = Utilities::pow (n_q_1d, dim - 1);
  cell_data.assign (matrix_free.n_cell_batches () * n_q, CellData ());
  face_data.assign (matrix_free.n_boundary_face_batches () * n_fq, FaceData ());
  face_batch_active.clear ();
  pressure_coupling = false;
}

template <int dim>
void MatrixFreeFlowOperator<dim>::distribute (
    const FlowCell              &cell,
    const CellCoefficients<dim> &coefficients,
    const typename FlowCoefficientSink<dim>::LocalData &)
{
  const unsigned int lanes = VA::size (), n_q = Utilities::pow (n_q_1d, dim),
                     n_fq  = Utilities::pow (n_q_1d, dim - 1);
  const unsigned int place = cell_place[cell->active_cell_index ()];
  const unsigned int batch = place / lanes, lane = place % lanes;
  for (unsigned int q = 0; q < n_q; ++q)
  {
    const FlowPointCoefficients<dim> &c = coefficients.values[q];
    CellData                         &d = cell_data[batch * n_q + q];
    for (unsigned int k = 0; k < 2; ++k)
    {
      d.mass[k][lane]      = c.mass[k];
      d.viscosity[k][lane] = c.viscosity[k];
      d.bulk[k][lane]      = c.bulk[k];
      d.inertia[k][lane]   = c.inertia[k];
      d.supg[k][lane]      = c.supg[k];
      for (unsigned int e = 0; e < dim; ++e)
        d.advection[k][e][lane] = c.advection[k][e];
    }
    d.drag[lane]    = c.drag;
    d.alpha_s[lane] = c.alpha_s;
    for (unsigned int e = 0; e < dim; ++e)
      d.grad_alpha_s[e][lane] = c.grad_alpha_s[e];
    pressure_coupling = pressure_coupling || c.pressure_coupling;
  }

  // the boundary faces' coefficients, matched to MatrixFree's face points
  for (unsigned int f = 0; f < coefficients.faces.size (); ++f)
  {
    const FaceCoefficients<dim> &face = coefficients.faces[f];
    // (a face MatrixFree does not hold as a boundary face, e.g. periodic: none to apply)
    const auto found = boundary_face_place.find (
        cell->active_cell_index () * GeometryInfo<dim>::faces_per_cell + f);
    if (face.values.empty () || found == boundary_face_place.end ())
      continue;
    const unsigned int face_place = found->second;
    const unsigned int face_batch = face_place / lanes, face_lane = face_place % lanes;
    const double       tolerance = 1e-6 * cell->diameter ();
    for (unsigned int q = 0; q < n_fq; ++q)
    {
      const Point<dim> &x       = boundary_face_points[face_place * n_fq + q];
      unsigned int      nearest = 0;
      for (unsigned int r = 1; r < face.points.size (); ++r)
        if (x.distance (face.points[r]) < x.distance (face.points[nearest]))
          nearest = r;
      AssertThrow (x.distance (face.points[nearest]) < tolerance,
                   ExcMessage ("matrix-free flow operator: face points do not match"));
      const FlowFacePointCoefficients<dim> &c = face.values[nearest];
      FaceData                             &d = face_data[face_batch * n_fq + q];
      d.backflow[face_lane]                   = c.backflow;
      for (unsigned int k = 0; k < 2; ++k)
      {
        d.friction[k][face_lane]  = c.friction[k];
        d.slips[k][face_lane]     = c.slips[k] ? 1.0 : 0.0;
        d.viscosity[k][face_lane] = c.viscosity[k];
        d.bulk[k][face_lane]      = c.bulk[k];
        d.penalty[k][face_lane]   = c.penalty[k];
        d.fraction[k][face_lane]  = c.fraction[k];
      }
      for (unsigned int e = 0; e < dim; ++e)
        d.wall_normal[e][face_lane] = c.wall_normal[e];
    }
  }
}

template <int dim>
void MatrixFreeFlowOperator<dim>::set_constrained_diagonal (
    const AssembledFlowOperator &assembled)
{
  for (unsigned int b = 0; b < 2; ++b)
    for (unsigned int i = 0; i < constrained[b].size (); ++i)
      constrained_diagonal[b][i] =
          assembled.system.block (b, b).diag_element (constrained_global[b][i]);
}

template <int dim>
void MatrixFreeFlowOperator<dim>::apply_cells (LocalVector       *dst_velocity,
                                               LocalVector       *dst_pressure,
                                               const LocalVector *src_velocity,
                                               const LocalVector *src_pressure,
                                               const Layout       layout) const
{
  // one kernel per combination of blocks in and out, chosen here once per apply: the
  // smoother's velocity-only apply carries no pressure or continuity work and no
  // branch at the quadrature points
  static const auto  kernels = kernel_table (std::make_index_sequence<16> ());
  const unsigned int flags =
      (src_velocity != nullptr ? velocity_in : 0u) |
      (pressure_coupling && src_pressure != nullptr ? pressure_in : 0u) |
      (dst_velocity != nullptr ? velocity_out : 0u) |
      (pressure_coupling && dst_pressure != nullptr ? pressure_out : 0u);
  (this->*kernels[flags]) (
      dst_velocity, dst_pressure, src_velocity, src_pressure, layout);
}

template <int dim>
template <std::size_t... flags>
auto MatrixFreeFlowOperator<dim>::kernel_table (std::index_sequence<flags...>)
    -> std::array<Kernel, sizeof...(flags)>
{
  return {{&MatrixFreeFlowOperator<dim>::template apply_cells_kernel<flags>...}};
}

namespace
{
/** The bilinear form at one quadrature point of a cell batch (doc/theory.md,
 * "Matrix-free flow operator"): from the velocities' values and gradients and the
 * pressure read (`u_in`, `p_in`), the values and gradients submitted to the momentum
 * rows and the continuity row (`u_out`, `p_out`), with the point's coefficients `c`. */
template <int  dim,
          bool u_in,
          bool p_in,
          bool u_out,
          bool p_out,
          typename Data,
          typename VA>
DEAL_II_ALWAYS_INLINE inline void
cell_point_kernel (const Data                                   &c,
                   const Tensor<1, 2 * dim, VA>                 &value,
                   const Tensor<1, 2 * dim, Tensor<1, dim, VA>> &grad,
                   const VA                                      pressure,
                   Tensor<1, 2 * dim, VA>                       &value_out,
                   Tensor<1, 2 * dim, Tensor<1, dim, VA>>       &grad_out,
                   VA                                           &continuity)
{
  for (unsigned int k = 0; k < 2; ++k)
  {
    const unsigned int o = k * dim, other = (1 - k) * dim;
    const VA           fraction = k == 0 ? VA (1.0) - c.alpha_s : c.alpha_s;
    const double       sign     = k == 0 ? -1.0 : 1.0; // grad f_k = sign grad alpha_s
    if constexpr (u_in)
    {
      VA                 divergence = 0.0;
      Tensor<1, dim, VA> convective;
      for (unsigned int d = 0; d < dim; ++d)
      {
        divergence += grad[o + d][d];
        for (unsigned int e = 0; e < dim; ++e)
          convective[d] += grad[o + d][e] * c.advection[k][e];
      }
      if constexpr (u_out)
        for (unsigned int d = 0; d < dim; ++d)
        {
          value_out[o + d] = c.mass[k] * value[o + d] + c.inertia[k] * convective[d] +
                             c.drag * (value[o + d] - value[other + d]);
          const VA supg = c.supg[k] * convective[d];
          for (unsigned int e = 0; e < dim; ++e)
            grad_out[o + d][e] = c.viscosity[k] * (grad[o + d][e] + grad[o + e][d]) +
                                 supg * c.advection[k][e];
          grad_out[o + d][d] += c.bulk[k] * divergence;
        }
      if constexpr (p_out)
      {
        VA grad_fraction_u = 0.0;
        for (unsigned int d = 0; d < dim; ++d)
          grad_fraction_u += c.grad_alpha_s[d] * value[o + d];
        continuity -= fraction * divergence + sign * grad_fraction_u;
      }
    }
    if constexpr (p_in && u_out)
      for (unsigned int d = 0; d < dim; ++d)
      {
        value_out[o + d] -= sign * pressure * c.grad_alpha_s[d];
        grad_out[o + d][d] -= pressure * fraction;
      }
  }
}
} // namespace

template <int dim>
template <unsigned int flags>
void MatrixFreeFlowOperator<dim>::apply_cells_kernel (LocalVector       *dst_velocity,
                                                      LocalVector       *dst_pressure,
                                                      const LocalVector *src_velocity,
                                                      const LocalVector *src_pressure,
                                                      const Layout       layout) const
{
  constexpr bool u_in = flags & velocity_in, p_in = flags & pressure_in,
                 u_out = flags & velocity_out, p_out = flags & pressure_out;
  if constexpr (!u_out && !p_out)
    return;
  else
  {
    const unsigned int n_q   = Utilities::pow (n_q_1d, dim);
    const auto [read, write] = dof_indices (layout);
    using VelocityEvaluation =
        FEEvaluation<dim, velocity_degree, n_q_1d, 2 * dim, double>;
    using PressureEvaluation = FEEvaluation<dim, 1, n_q_1d, 1, double>;
    VelocityEvaluation u (matrix_free, write), u_read (matrix_free, read);
    PressureEvaluation p (matrix_free, write + 1), p_read (matrix_free, read + 1);
    // the lifting reads through another DoF index than it writes
    VelocityEvaluation &u_source = read == write ? u : u_read;
    PressureEvaluation &p_source = read == write ? p : p_read;
    const auto          both     = EvaluationFlags::values | EvaluationFlags::gradients;
    for (unsigned int cell = 0; cell < matrix_free.n_cell_batches (); ++cell)
    {
      u.reinit (cell);
      p.reinit (cell);
      if constexpr (u_in)
      {
        if (read != write)
          u_source.reinit (cell);
        u_source.gather_evaluate (*src_velocity, both);
      }
      if constexpr (p_in)
      {
        if (read != write)
          p_source.reinit (cell);
        p_source.gather_evaluate (*src_pressure, EvaluationFlags::values);
      }
      const CellData *data = &cell_data[cell * n_q];
      for (unsigned int q = 0; q < n_q; ++q)
      {
        const CellData                        &c = data[q];
        Tensor<1, 2 * dim, VA>                 value;
        Tensor<1, 2 * dim, Tensor<1, dim, VA>> grad;
        if constexpr (u_in)
        {
          value = u_source.get_value (q);
          grad  = u_source.get_gradient (q);
        }
        VA pressure = 0.0;
        if constexpr (p_in)
          pressure = p_source.get_value (q);
        Tensor<1, 2 * dim, VA>                 value_out;
        Tensor<1, 2 * dim, Tensor<1, dim, VA>> grad_out;
        VA                                     continuity = 0.0;
        cell_point_kernel<dim, u_in, p_in, u_out, p_out> (
            c, value, grad, pressure, value_out, grad_out, continuity);
        if constexpr (u_out)
        {
          u.submit_value (value_out, q);
          u.submit_gradient (grad_out, q);
        }
        if constexpr (p_out)
          p.submit_value (continuity, q);
      }
      if constexpr (u_out)
        u.integrate_scatter (both, *dst_velocity);
      if constexpr (p_out)
        p.integrate_scatter (EvaluationFlags::values, *dst_pressure);
    }
  }
}

template <int dim>
void MatrixFreeFlowOperator<dim>::mark_active_face_batches () const
{
  const unsigned int n_fq      = Utilities::pow (n_q_1d, dim - 1);
  const unsigned int n_batches = matrix_free.n_boundary_face_batches ();
  face_batch_active.assign (n_batches, false);
  for (unsigned int batch = 0; batch < n_batches; ++batch)
    for (unsigned int q = 0; q < n_fq; ++q)
    {
      const FaceData &c = face_data[batch * n_fq + q];
      for (unsigned int lane = 0; lane < VA::size (); ++lane)
        face_batch_active[batch] = face_batch_active[batch] || c.backflow[lane] != 0.0 ||
                                   c.friction[0][lane] != 0.0 ||
                                   c.friction[1][lane] != 0.0 ||
                                   c.slips[0][lane] != 0.0 || c.slips[1][lane] != 0.0;
    }
}

template <int dim>
void MatrixFreeFlowOperator<dim>::apply_boundary_faces (LocalVector       *dst_velocity,
                                                        LocalVector       *dst_pressure,
                                                        const LocalVector *src_velocity,
                                                        const LocalVector *src_pressure,
                                                        const Layout       layout) const
{
  const unsigned int n_fq      = Utilities::pow (n_q_1d, dim - 1);
  const unsigned int first     = matrix_free.n_inner_face_batches ();
  const unsigned int n_batches = matrix_free.n_boundary_face_batches ();
  if (face_batch_active.size () != n_batches)
    mark_active_face_batches ();
  const auto [read, write] = dof_indices (layout);
  using VelocityEvaluation =
      FEFaceEvaluation<dim, velocity_degree, n_q_1d, 2 * dim, double>;
  using PressureEvaluation = FEFaceEvaluation<dim, 1, n_q_1d, 1, double>;
  VelocityEvaluation u (matrix_free, true, write), u_read (matrix_free, true, read);
  PressureEvaluation p (matrix_free, true, write + 1),
      p_read (matrix_free, true, read + 1);
  VelocityEvaluation &u_source = read == write ? u : u_read;
  PressureEvaluation &p_source = read == write ? p : p_read;
  const auto          both     = EvaluationFlags::values | EvaluationFlags::gradients;
  for (unsigned int face = first; face < first + n_batches; ++face)
  {
    if (!face_batch_active[face - first])
      continue;
    const FaceData *data = &face_data[(face - first) * n_fq];
    u.reinit (face);
    p.reinit (face);
    if (read != write)
    {
      u_source.reinit (face);
      p_source.reinit (face);
    }
    if (src_velocity != nullptr)
      u_source.gather_evaluate (*src_velocity, both);
    if (src_pressure != nullptr)
      p_source.gather_evaluate (*src_pressure, EvaluationFlags::values);
    for (unsigned int q = 0; q < n_fq; ++q)
    {
      const FaceData                        &c = data[q];
      Tensor<1, 2 * dim, VA>                 value;
      Tensor<1, 2 * dim, Tensor<1, dim, VA>> grad;
      if (src_velocity != nullptr)
      {
        value = u_source.get_value (q);
        grad  = u_source.get_gradient (q);
      }
      const VA    pressure = src_pressure != nullptr ? p_source.get_value (q) : VA (0.0);
      const auto  n_h      = u.get_normal_vector (q);
      const auto &n        = c.wall_normal;
      Tensor<1, 2 * dim, VA>                 value_out;
      Tensor<1, 2 * dim, Tensor<1, dim, VA>> grad_out;
      VA                                     continuity = 0.0;
      for (unsigned int k = 0; k < 2; ++k)
      {
        const unsigned int o  = k * dim;
        VA mapped_normal_part = 0.0, normal_part = 0.0, divergence = 0.0, stretch = 0.0;
        for (unsigned int d = 0; d < dim; ++d)
        {
          mapped_normal_part += value[o + d] * n_h[d];
          normal_part += value[o + d] * n[d];
          divergence += grad[o + d][d];
          for (unsigned int e = 0; e < dim; ++e)
            stretch += n[d] * grad[o + d][e] * n[e];
        }
        // n.tau_k(u_k) n, and the Nitsche terms masked to the slipping phases
        const VA normal_stress = 2.0 * c.viscosity[k] * stretch + c.bulk[k] * divergence;
        const VA weak_value = c.slips[k] * (c.penalty[k] * normal_part - normal_stress +
                                            c.fraction[k] * pressure);
        const VA weak_gradient = c.slips[k] * normal_part;
        for (unsigned int d = 0; d < dim; ++d)
        {
          value_out[o + d] =
              c.friction[k] * (value[o + d] - mapped_normal_part * n_h[d]) +
              weak_value * n[d];
          if (k == 0)
            value_out[o + d] += c.backflow * value[o + d];
          for (unsigned int e = 0; e < dim; ++e)
            grad_out[o + d][e] = -weak_gradient * 2.0 * c.viscosity[k] * n[d] * n[e];
          grad_out[o + d][d] -= weak_gradient * c.bulk[k];
        }
        continuity += c.slips[k] * c.fraction[k] * normal_part;
      }
      if (dst_velocity != nullptr)
      {
        u.submit_value (value_out, q);
        u.submit_gradient (grad_out, q);
      }
      if (dst_pressure != nullptr)
        p.submit_value (continuity, q);
    }
    if (dst_velocity != nullptr)
      u.integrate_scatter (both, *dst_velocity);
    if (dst_pressure != nullptr)
      p.integrate_scatter (EvaluationFlags::values, *dst_pressure);
  }
}

template <int dim>
void MatrixFreeFlowOperator<dim>::vmult (BlockVector &dst, const BlockVector &src) const
{
  to_velocity (src_u, src.block (0));
  {
    const double *values = src.block (1).begin ();
    for (unsigned int i = 0; i < local_of_block[1].size (); ++i)
      src_p.local_element (local_of_block[1][i]) = values[i];
  }
  src_u.update_ghost_values ();
  src_p.update_ghost_values ();
  dst_u = 0.0;
  dst_p = 0.0;
  apply_cells (&dst_u, &dst_p, &src_u, &src_p);
  if (!face_data.empty ())
    apply_boundary_faces (&dst_u, &dst_p, &src_u, &src_p);
  LocalVector *in[2] = {&src_u, &src_p}, *out[2] = {&dst_u, &dst_p};
  for (unsigned int b = 0; b < 2; ++b)
  {
    out[b]->compress (VectorOperation::add);
    in[b]->zero_out_ghost_values ();
    double       *result = dst.block (b).begin ();
    const double *values = src.block (b).begin ();
    for (unsigned int i = 0; i < local_of_block[b].size (); ++i)
      result[i] = out[b]->local_element (local_of_block[b][i]);
    for (unsigned int i = 0; i < constrained[b].size (); ++i)
      result[constrained[b][i]] = constrained_diagonal[b][i] * values[constrained[b][i]];
  }
}

template <int dim>
void MatrixFreeFlowOperator<dim>::vmult_velocity (LocalVector       &dst,
                                                  const LocalVector &src) const
{
  src.update_ghost_values ();
  dst = 0.0;
  apply_cells (&dst, nullptr, &src, nullptr);
  if (!face_data.empty ())
    apply_boundary_faces (&dst, nullptr, &src, nullptr);
  dst.compress (VectorOperation::add);
  src.zero_out_ghost_values ();
  for (const unsigned int i : velocity_constrained_local)
    dst.local_element (i) = src.local_element (i);
}

template <int dim>
void MatrixFreeFlowOperator<dim>::vmult_gradient (
    LocalVector &dst, const TrilinosWrappers::MPI::Vector &p) const
{
  const double *values = p.begin ();
  for (unsigned int i = 0; i < local_of_block[1].size (); ++i)
    src_p.local_element (local_of_block[1][i]) = values[i];
  src_p.update_ghost_values ();
  dst = 0.0;
  apply_cells (&dst, nullptr, nullptr, &src_p);
  if (!face_data.empty ())
    apply_boundary_faces (&dst, nullptr, nullptr, &src_p);
  dst.compress (VectorOperation::add);
  src_p.zero_out_ghost_values ();
  for (const unsigned int i : velocity_constrained_local)
    dst.local_element (i) = 0;
}

template <int dim>
void MatrixFreeFlowOperator<dim>::to_velocity (
    LocalVector &dst, const TrilinosWrappers::MPI::Vector &src) const
{
  const double *values = src.begin ();
  for (unsigned int i = 0; i < local_of_block[0].size (); ++i)
    dst.local_element (local_of_block[0][i]) = values[i];
}

template <int dim>
void MatrixFreeFlowOperator<dim>::from_velocity (TrilinosWrappers::MPI::Vector &dst,
                                                 const LocalVector             &src) const
{
  double *values = dst.begin ();
  for (unsigned int i = 0; i < local_of_block[0].size (); ++i)
    values[i] = src.local_element (local_of_block[0][i]);
}

template <int dim>
std::array<double, 3> MatrixFreeFlowOperator<dim>::weighted_row_sums (
    const BlockVector                                                 &solution,
    const std::array<std::vector<std::pair<unsigned int, double>>, 3> &weights) const
{
  std::array<double, 3> sums = {{0, 0, 0}};
  if (cell_data.empty ()) // nothing assembled yet (the initial monitors row)
    return sums;
  // the owned positions of the MatrixFree vectors are those of the constrained layout
  const double *velocity = solution.block (0).begin (),
               *pressure = solution.block (1).begin ();
  for (unsigned int i = 0; i < local_of_block[0].size (); ++i)
    plain_u.local_element (local_of_block[0][i]) = velocity[i];
  for (unsigned int i = 0; i < local_of_block[1].size (); ++i)
    plain_p.local_element (local_of_block[1][i]) = pressure[i];
  plain_u.update_ghost_values ();
  plain_p.update_ghost_values ();
  plain_result = 0.0;
  apply_cells (&plain_result, nullptr, &plain_u, &plain_p, Layout::plain);
  if (!face_data.empty ())
    apply_boundary_faces (&plain_result, nullptr, &plain_u, &plain_p, Layout::plain);
  plain_result.compress (VectorOperation::add);
  plain_u.zero_out_ghost_values ();
  plain_p.zero_out_ghost_values ();
  for (unsigned int b = 0; b < 3; ++b)
    for (const auto &[position, weight] : weights[b])
      sums[b] += weight * plain_result.local_element (local_of_block[0][position]);
  return sums;
}

template <int dim>
void MatrixFreeFlowOperator<dim>::subtract_lifting (
    BlockVector &rhs, const AffineConstraints<double> &flow_constraints) const
{
  LocalVector *source[2] = {&plain_u, &plain_p}, *result[2] = {&dst_u, &dst_p};
  bool         any = false;
  for (unsigned int b = 0; b < 2; ++b)
  {
    *source[b] = 0.0;
    for (unsigned int i = 0; i < constrained[b].size (); ++i)
    {
      const double value = flow_constraints.get_inhomogeneity (
          constrained_global[b][i] + (b == 1 ? n_velocity_flow_dofs : 0));
      source[b]->local_element (local_of_block[b][constrained[b][i]]) = value;
      any = any || value != 0.0;
    }
  }
  if (Utilities::MPI::max (any ? 1 : 0, plain_u.get_mpi_communicator ()) == 0)
    return;
  for (unsigned int b = 0; b < 2; ++b)
  {
    source[b]->update_ghost_values ();
    *result[b] = 0.0;
  }
  apply_cells (&dst_u, &dst_p, &plain_u, &plain_p, Layout::lifting);
  if (!face_data.empty ())
    apply_boundary_faces (&dst_u, &dst_p, &plain_u, &plain_p, Layout::lifting);
  for (unsigned int b = 0; b < 2; ++b)
  {
    result[b]->compress (VectorOperation::add);
    source[b]->zero_out_ghost_values ();
    // (the constrained rows receive nothing: the write resolves the constraints)
    double *values = rhs.block (b).begin ();
    for (unsigned int i = 0; i < local_of_block[b].size (); ++i)
      values[i] -= result[b]->local_element (local_of_block[b][i]);
  }
}

template <int dim>
std::size_t MatrixFreeFlowOperator<dim>::memory_consumption () const
{
  std::size_t bytes =
      matrix_free.memory_consumption () + cell_data.size () * sizeof (CellData) +
      face_data.size () * sizeof (FaceData) + velocity_dof_handler.memory_consumption () +
      pressure_dof_handler.memory_consumption () +
      velocity_constraints.memory_consumption () +
      pressure_constraints.memory_consumption ();
  for (unsigned int b = 0; b < 2; ++b)
    bytes += local_of_block[b].size () * sizeof (unsigned int);
  for (const LocalVector *v : {&src_u, &src_p, &dst_u, &dst_p})
    bytes += v->memory_consumption ();
  return bytes;
}

template class MatrixFreeFlowOperator<2>;
template class MatrixFreeFlowOperator<3>;
} // namespace wetbed

// deal.II's MatrixFree for the SIMD width wetbed is compiled with
// (doc/developer_guide.md, "SIMD width"): the library holds these classes only for the
// width it was configured with (one lane in Debian's build); FEEvaluation and
// FEFaceEvaluation, templates on the degree, are compiled inline in the operator. Nothing
// is instantiated here when the two widths agree.
#include <deal.II/base/config.h>

#if defined(WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS) &&                               \
    DEAL_II_VECTORIZATION_WIDTH_IN_BITS != WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS
// the mapping's evaluation inside MatrixFree (MappingQ of degree 2) needs the
// runtime-degree evaluators: compiled for degrees 1 and 2 here, higher ones take
// deal.II's generic path
#define FE_EVAL_FACTORY_DEGREE_MAX 2
#include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>
// (deal.II 9.4's two factory files share one include guard)
#undef dealii_matrix_free_evaluation_template_factory_templates_h
#include <deal.II/matrix_free/evaluation_template_factory.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>

namespace dealii
{
using WetbedVectorizedArray = VectorizedArray<double>;

#define WETBED_INSTANTIATE_MATRIX_FREE(dim)                                              \
  template class MatrixFree<dim, double, WetbedVectorizedArray>;                         \
  template void                                                                          \
  MatrixFree<dim, double, WetbedVectorizedArray>::internal_reinit<double, dim> (         \
      const std::shared_ptr<hp::MappingCollection<dim>> &,                               \
      const std::vector<const DoFHandler<dim, dim> *> &,                                 \
      const std::vector<const AffineConstraints<double> *> &,                            \
      const std::vector<IndexSet> &,                                                     \
      const std::vector<hp::QCollection<dim>> &,                                         \
      const MatrixFree<dim, double, WetbedVectorizedArray>::AdditionalData &);           \
  template struct internal::MatrixFreeFunctions::                                        \
      MappingInfo<dim, double, WetbedVectorizedArray>;                                   \
  template void internal::FEEvaluationFactory<dim, WetbedVectorizedArray>::evaluate (    \
      const unsigned int,                                                                \
      const EvaluationFlags::EvaluationFlags,                                            \
      const WetbedVectorizedArray *,                                                     \
      FEEvaluationData<dim, WetbedVectorizedArray, false> &);                            \
  template void                                                                          \
  internal::FEFaceEvaluationFactory<dim, WetbedVectorizedArray>::evaluate (              \
      const unsigned int,                                                                \
      const EvaluationFlags::EvaluationFlags,                                            \
      const WetbedVectorizedArray *,                                                     \
      FEEvaluationData<dim, WetbedVectorizedArray, true> &);                             \
  template struct internal::                                                             \
      FEEvaluationHangingNodesFactory<dim, double, WetbedVectorizedArray>;               \
  template void internal::MatrixFreeFunctions::ShapeInfo<                                \
      WetbedVectorizedArray>::reinit<dim, dim, dim> (const Quadrature<dim> &,            \
                                                     const FiniteElement<dim, dim> &,    \
                                                     unsigned int);

template struct internal::MatrixFreeFunctions::ShapeInfo<WetbedVectorizedArray>;
WETBED_INSTANTIATE_MATRIX_FREE (2)
WETBED_INSTANTIATE_MATRIX_FREE (3)
#undef WETBED_INSTANTIATE_MATRIX_FREE
} // namespace dealii
#endif
