#include <wetbed/assembly/flow/imposed_source_term.h>

namespace wetbed
{
template <int dim>
void ImposedSourceTerm<dim>::cell (const FlowCellScratch<dim> &s,
                                   const FlowAssemblyState<dim> &,
                                   FlowCellCopy &copy) const
{
  const unsigned int n_u = s.indices.n_velocity_basis, n_p = s.indices.n_pressure_basis;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const dealii::Point<dim>    &x        = s.velocity_values.quadrature_point (q);
    const dealii::Tensor<1, dim> force[2] = {hook->momentum_source (x, 0),
                                             hook->momentum_source (x, 1)};
    const double volume_source            = hook->mixture_volume_source (x) * s.JxW[q];
    for (unsigned int c = 0; c < 2 * dim; ++c)
      for (unsigned int a = 0; a < n_u; ++a)
        copy.rhs (s.indices.velocity[c][a]) +=
            force[c / dim][c % dim] * s.phi[q][a] * s.JxW[q];
    for (unsigned int b = 0; b < n_p; ++b)
      copy.rhs (s.indices.pressure[b]) -= volume_source * s.phi_p[q][b];
  }
}

template <int dim>
void ImposedSourceTerm<dim>::face (const typename FlowTerm<dim>::CellIterator &cell,
                                   const unsigned int          face_number,
                                   const FlowCellScratch<dim> &s,
                                   const FlowAssemblyState<dim> &,
                                   FlowCellCopy &copy) const
{
  const auto        &fv  = s.face_values;
  const unsigned int n_u = s.indices.n_velocity_basis;
  const bool on_out      = outlets.count (cell->face (face_number)->boundary_id ()) > 0;
  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
  {
    const dealii::Point<dim>    &x = fv.quadrature_point (q);
    const dealii::Tensor<1, dim> n = fv.normal_vector (q);
    dealii::Tensor<1, dim>       traction[2];
    for (unsigned int k = 0; k < 2; ++k)
      traction[k] =
          on_out ? hook->outlet_traction (x, n, k) : hook->wall_traction_source (x, n, k);
    for (unsigned int c = 0; c < 2 * dim; ++c)
      for (unsigned int a = 0; a < n_u; ++a)
        copy.rhs (s.indices.velocity[c][a]) +=
            traction[c / dim][c % dim] * fv.shape_value (s.indices.velocity[c][a], q) *
            fv.JxW (q);
  }
}

template class ImposedSourceTerm<2>;
template class ImposedSourceTerm<3>;
} // namespace wetbed
