#include <wetbed/assembly/flow/manufactured_source_term.h>

namespace wetbed
{
template <int dim>
void ManufacturedSourceTerm<dim>::cell (const FlowCellScratch<dim> &s,
                                        const FlowAssemblyState<dim> &,
                                        FlowCellCopy &copy) const
{
  const unsigned int n_u = s.indices.n_velocity_basis, n_p = s.indices.n_pressure_basis;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const dealii::Point<dim>    &x        = s.velocity_values.quadrature_point (q);
    const dealii::Tensor<1, dim> force[2] = {solution->gas_momentum_source (x),
                                             solution->solids_momentum_source (x)};
    const double volume_source = solution->mixture_volume_source (x) * s.JxW[q];
    for (unsigned int c = 0; c < 2 * dim; ++c)
      for (unsigned int a = 0; a < n_u; ++a)
        copy.rhs (s.indices.velocity[c][a]) +=
            force[c / dim][c % dim] * s.phi[q][a] * s.JxW[q];
    for (unsigned int b = 0; b < n_p; ++b)
      copy.rhs (s.indices.pressure[b]) -= volume_source * s.phi_p[q][b];
  }
}

template <int dim>
void ManufacturedSourceTerm<dim>::face (const typename FlowTerm<dim>::CellIterator &cell,
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
      traction[k] = on_out ? (k == 0 ? solution->gas_traction (x, n)
                                     : solution->solids_traction (x, n))
                           : solution->wall_traction_source (x, n, k);
    for (unsigned int c = 0; c < 2 * dim; ++c)
      for (unsigned int a = 0; a < n_u; ++a)
        copy.rhs (s.indices.velocity[c][a]) +=
            traction[c / dim][c % dim] * fv.shape_value (s.indices.velocity[c][a], q) *
            fv.JxW (q);
  }
}

template class ManufacturedSourceTerm<2>;
template class ManufacturedSourceTerm<3>;
} // namespace wetbed
