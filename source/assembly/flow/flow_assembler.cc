#include <wetbed/assembly/flow/flow_assembler.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/affine_constraints.templates.h> // the (rhs, matrix) distribution for block vectors

namespace wetbed
{
using namespace dealii;

template <int dim>
FlowAssembler<dim>::FlowAssembler (const Mapping<dim>               &mapping,
                                   const DoFHandler<dim>            &flow_dof_handler,
                                   const DoFHandler<dim>            &alpha_dof_handler,
                                   const closures::ClosureEvaluator &closures,
                                   const FlowMaterial<dim>          &material)
    : mapping (mapping), flow_dof_handler (flow_dof_handler),
      alpha_dof_handler (alpha_dof_handler), evaluator (closures), material (material)
{
}

template <int dim>
void FlowAssembler<dim>::add_term (std::unique_ptr<FlowTerm<dim>> term)
{
  terms.push_back (std::move (term));
}

template <int dim>
std::vector<std::string> FlowAssembler<dim>::term_names () const
{
  std::vector<std::string> names;
  for (const auto &term : terms)
    names.push_back (term->name ());
  return names;
}

namespace
{
/** A cell's DoF values as the FEValuesViews *_from_local_dof_values functions take them
 * (deal.II instantiates those for ArrayView). */
dealii::ArrayView<double> local (dealii::Vector<double> &values)
{
  return dealii::make_array_view (values.begin (), values.end ());
}
} // namespace

template <int dim>
void FlowAssembler<dim>::prepare_cell (const CellIterator           &cell,
                                       const FlowAssemblyState<dim> &state,
                                       FlowCellScratch<dim>         &s) const
{
  const CellIterator alpha_cell (
      &cell->get_triangulation (), cell->level (), cell->index (), &alpha_dof_handler);
  s.velocity_values.reinit (
      static_cast<const typename Triangulation<dim>::cell_iterator &> (cell));
  s.pressure_values.reinit (
      static_cast<const typename Triangulation<dim>::cell_iterator &> (cell));
  s.alpha_values.reinit (alpha_cell);
  s.alpha_values.get_function_values (*state.alpha, s.alpha_s);
  s.alpha_values.get_function_gradients (*state.alpha, s.grad_alpha_s);
  s.alpha_values.get_function_values (*state.alpha_old, s.alpha_s_old);
  s.alpha_values.get_function_values (*state.alpha_old2, s.alpha_s_old2);
  s.alpha_values.get_function_values (*state.theta, s.theta);
  cell->get_dof_values (*state.flow, s.flow_local);
  cell->get_dof_values (*state.flow_old, s.flow_old_local);
  cell->get_dof_values (*state.flow_old2, s.flow_old2_local);
  const unsigned int n_q = s.JxW.size (), n_u = s.indices.n_velocity_basis;
  for (unsigned int q = 0; q < n_q; ++q)
  {
    s.JxW[q] = s.velocity_values.JxW (q);
    for (unsigned int a = 0; a < n_u; ++a)
    {
      s.phi[q][a]      = s.velocity_values.shape_value (a, q);
      s.grad_phi[q][a] = s.velocity_values.shape_grad (a, q);
    }
    for (unsigned int b = 0; b < s.indices.n_pressure_basis; ++b)
    {
      s.phi_p[q][b]      = s.pressure_values.shape_value (b, q);
      s.grad_phi_p[q][b] = s.pressure_values.shape_grad (b, q);
    }
    // both phases' velocities (current: with gradients; the two previous steps)
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int d = 0; d < dim; ++d)
      {
        const std::vector<unsigned int> &rows  = s.indices.velocity[k * dim + d];
        double                           value = 0, old = 0, old2 = 0;
        Tensor<1, dim>                   gradient;
        for (unsigned int a = 0; a < n_u; ++a)
        {
          const double phi = s.phi[q][a];
          value += s.flow_local[rows[a]] * phi;
          old += s.flow_old_local[rows[a]] * phi;
          old2 += s.flow_old2_local[rows[a]] * phi;
          gradient += s.flow_local[rows[a]] * s.grad_phi[q][a];
        }
        s.u[k][q][d]      = value;
        s.u_old[k][q][d]  = old;
        s.u_old2[k][q][d] = old2;
        for (unsigned int e = 0; e < dim; ++e)
          s.grad_u[k][q][d][e] = gradient[e];
      }
    s.slip[q] = (s.u[0][q] - s.u[1][q]).norm ();
  }
  // every closure, once per quadrature point (and P_s at the alpha_s nodes)
  alpha_cell->get_dof_values (*state.alpha, s.alpha_nodal);
  s.closures.template evaluate<dim> (
      evaluator, s.alpha_s, s.theta, s.slip, s.grad_u[1], s.alpha_nodal);

  const double rho_g = material.gas_density, mu_g = material.gas_viscosity;
  double       volume = 0, alpha_integral = 0;
  for (unsigned int q = 0; q < n_q; ++q)
  {
    s.compaction_pressure[q] = 0;
    for (unsigned int j = 0; j < s.alpha_nodal.size (); ++j)
      s.compaction_pressure[q] +=
          s.closures.nodal_compaction_pressure[j] * s.alpha_values.shape_value (j, q);
    volume += s.JxW[q];
    alpha_integral += s.alpha_s[q] * s.JxW[q];
    const double alpha_g = 1.0 - s.alpha_s[q];
    s.fraction[0][q]     = alpha_g;
    s.fraction[1][q]     = s.alpha_s[q];
    s.inertia[0][q]      = alpha_g * rho_g;
    s.inertia[1][q]      = s.closures.inertial_fraction[q] * material.particle_density;
    s.viscosity[0][q]    = alpha_g * mu_g;
    s.viscosity[1][q]    = s.closures.shear_viscosity[q];
    s.bulk[0][q]         = -2.0 / 3.0 * alpha_g * mu_g;
    s.bulk[1][q] =
        s.closures.bulk_viscosity[q] - 2.0 / 3.0 * s.closures.shear_viscosity[q];
    for (unsigned int k = 0; k < 2; ++k)
      s.bdf_mass[k][q] = state.bdf.a0 * s.inertia[k][q] / state.dt;
  }
  s.alpha_mean = alpha_integral / volume;
  s.h          = cell->diameter () / std::sqrt (double (dim));
}

template <int dim>
void FlowAssembler<dim>::prepare_face (const CellIterator           &cell,
                                       const unsigned int            face,
                                       const FlowAssemblyState<dim> &state,
                                       FlowCellScratch<dim>         &s) const
{
  const CellIterator alpha_cell (
      &cell->get_triangulation (), cell->level (), cell->index (), &alpha_dof_handler);
  s.face_number = face;
  s.face_values.reinit (cell, face);
  s.alpha_face_values.reinit (alpha_cell, face);
  const FEValuesExtractors::Vector gas (0), solids (dim);
  // the cell's flow values, read in prepare_cell
  const auto flow = local (s.flow_local);
  s.face_values[gas].get_function_values_from_local_dof_values (flow, s.face_u[0]);
  s.face_values[solids].get_function_values_from_local_dof_values (flow, s.face_u[1]);
  s.face_values[solids].get_function_gradients_from_local_dof_values (flow,
                                                                      s.face_grad_u_s);
  s.alpha_face_values.get_function_values (*state.alpha, s.face_alpha_s);
  s.alpha_face_values.get_function_values (*state.theta, s.face_theta);
}

template <int dim>
FlowAssembler<dim>::CellCopy::CellCopy (const unsigned int n_dofs,
                                        const unsigned int n_pressure_dofs,
                                        const unsigned int n_sinks)
    : system (n_dofs, n_pressure_dofs), sink_data (n_sinks)
{
}

template <int dim>
void FlowAssembler<dim>::local_system (const CellIterator           &cell,
                                       const FlowAssemblyState<dim> &state,
                                       const Sinks                  &sinks,
                                       FlowCellScratch<dim>         &scratch,
                                       CellCopy                     &copy) const
{
  FlowCellCopy &system = copy.system;
  // (a cell without matrix leaves `matrix` as it is: no term writes it)
  if (system.with_matrix)
    system.matrix = 0;
  system.schur = 0;
  system.rhs   = 0;
  copy.cell    = cell;
  cell->get_dof_indices (system.dofs);
  for (unsigned int a = 0; a < system.pressure_dofs.size (); ++a)
    system.pressure_dofs[a] = system.dofs[scratch.indices.pressure[a]];
  prepare_cell (cell, state, scratch);
  for (const auto &term : terms)
    term->cell (scratch, state, system);
  CellCoefficients<dim> &coefficients      = copy.coefficients;
  const bool             with_coefficients = !sinks.empty ();
  if (with_coefficients)
  {
    point_coefficients (scratch, state, coefficients.values);
    for (unsigned int i = 0; i < sinks.size (); ++i)
      sinks[i]->local_cell (cell, scratch, coefficients.values, copy.sink_data[i]);
    coefficients.faces.resize (cell->n_faces ());
    for (auto &face : coefficients.faces)
    {
      face.values.clear ();
      face.points.clear ();
    }
  }
  for (const unsigned int f : cell->face_indices ())
  {
    if (!face_has_terms (cell, f))
      continue;
    const auto id = cell->face (f)->boundary_id ();
    prepare_face (cell, f, state, scratch);
    for (const auto &term : terms)
      if (term->acts_on_boundary (id))
        term->face (cell, f, scratch, state, system);
    if (!with_coefficients)
      continue;
    face_coefficients (cell, f, scratch, state, coefficients.faces[f]);
    for (unsigned int i = 0; i < sinks.size (); ++i)
      sinks[i]->local_face (cell, f, scratch, coefficients.faces[f], copy.sink_data[i]);
  }
  system.captured = cell->at_boundary ();
}

template <int dim>
void FlowAssembler<dim>::point_coefficients (
    const FlowCellScratch<dim>              &scratch,
    const FlowAssemblyState<dim>            &state,
    std::vector<FlowPointCoefficients<dim>> &values) const
{
  const unsigned int n_q = scratch.JxW.size ();
  values.assign (n_q, FlowPointCoefficients<dim> ());
  for (unsigned int q = 0; q < n_q; ++q)
    for (const auto &term : terms)
      term->coefficients (scratch, state, q, values[q]);
}

template <int dim>
void FlowAssembler<dim>::face_coefficients (const CellIterator           &cell,
                                            const unsigned int            f,
                                            const FlowCellScratch<dim>   &scratch,
                                            const FlowAssemblyState<dim> &state,
                                            FaceCoefficients<dim>        &face) const
{
  const auto         id   = cell->face (f)->boundary_id ();
  const unsigned int n_fq = scratch.face_values.n_quadrature_points;
  face.values.assign (n_fq, FlowFacePointCoefficients<dim> ());
  face.points = scratch.face_values.get_quadrature_points ();
  for (unsigned int q = 0; q < n_fq; ++q)
    for (const auto &term : terms)
      if (term->acts_on_boundary (id))
        term->face_coefficients (cell, f, scratch, state, q, face.values[q]);
}

template <int dim>
bool FlowAssembler<dim>::face_has_terms (const CellIterator &cell,
                                         const unsigned int  f) const
{
  if (!cell->face (f)->at_boundary ())
    return false;
  const auto id = cell->face (f)->boundary_id ();
  for (const auto &term : terms)
    if (term->acts_on_boundary (id))
      return true;
  return false;
}

template <int dim>
std::string FlowAssembler<dim>::term_without_coefficients () const
{
  for (const auto &term : terms)
    if (term->has_matrix () && !term->has_coefficients ())
      return term->name ();
  return "";
}

template <int dim>
void FlowAssembler<dim>::capture_boundary_rows (
    const FlowCellCopy              &copy,
    const std::vector<unsigned int> &component,
    const BoundaryRowCapture        &capture,
    const bool                       rows)
{
  const unsigned int n_dofs = copy.dofs.size ();
  BoundaryCellSystem system{copy.dofs, {}, {{0, 0, 0}}};
  bool               any = false;
  for (unsigned int i = 0; i < n_dofs; ++i)
    for (unsigned int b = 0; b < 3 && component[i] < 2 * dim; ++b)
      if ((*capture.velocity_dofs)[b].is_element (copy.dofs[i]))
      {
        const double weight = capture.up[component[i] % dim];
        if (weight != 0)
        {
          if (rows)
          {
            system.row[b].resize (n_dofs, 0.0);
            for (unsigned int j = 0; j < n_dofs; ++j)
              system.row[b][j] += weight * copy.matrix (i, j);
          }
          system.rhs[b] += weight * copy.rhs (i);
          any = true;
        }
        break;
      }
  if (any)
    capture.systems->push_back (std::move (system));
}

template <int dim>
void FlowAssembler<dim>::assemble (const FlowAssemblyState<dim>    &state,
                                   const AffineConstraints<double> &flow_constraints,
                                   const AffineConstraints<double> &schur_constraints,
                                   const Target                    &target,
                                   BlockVector                     &rhs,
                                   const BoundaryRowCapture        &capture) const
{
  const bool   matrix = target.system != nullptr;
  const Sinks &sinks  = target.sinks;
  if (matrix)
    *target.system = 0;
  *target.schur = 0;
  rhs           = 0;
  capture.systems->clear ();
  const auto &fe = dynamic_cast<const FESystem<dim> &> (flow_dof_handler.get_fe ());
  const FlowCellScratch<dim> scratch (
      mapping, fe, alpha_dof_handler.get_fe (), QGauss<dim> (3), QGauss<dim - 1> (3));
  const CellCopy copy (
      fe.n_dofs_per_cell (), scratch.indices.n_pressure_basis, sinks.size ());
  const std::vector<unsigned int> &component = scratch.indices.component;

  using Filtered = FilteredIterator<CellIterator>;
  WorkStream::run (
      Filtered (IteratorFilters::LocallyOwnedCell (), flow_dof_handler.begin_active ()),
      Filtered (IteratorFilters::LocallyOwnedCell (), flow_dof_handler.end ()),
      [&] (const Filtered &cell, FlowCellScratch<dim> &s, CellCopy &c)
      {
        c.system.with_matrix = matrix;
        local_system (cell, state, sinks, s, c);
      },
      [&] (const CellCopy &copy_data)
      {
        const FlowCellCopy &c = copy_data.system;
        if (c.captured)
          capture_boundary_rows (c, component, capture, matrix);
        if (matrix)
          flow_constraints.distribute_local_to_global (
              c.matrix, c.rhs, c.dofs, *target.system, rhs);
        else
          flow_constraints.distribute_local_to_global (c.rhs, c.dofs, rhs);
        schur_constraints.distribute_local_to_global (
            c.schur, c.pressure_dofs, *target.schur);
        for (unsigned int i = 0; i < sinks.size (); ++i)
          sinks[i]->distribute (
              copy_data.cell, copy_data.coefficients, copy_data.sink_data[i]);
      },
      scratch,
      copy);
  if (matrix)
    target.system->compress (VectorOperation::add);
  target.schur->compress (VectorOperation::add);
  rhs.compress (VectorOperation::add);
}

template class FlowAssembler<2>;
template class FlowAssembler<3>;
} // namespace wetbed
