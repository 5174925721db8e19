#include <wetbed/assembly/flow/outlet_backflow_term.h>

namespace wetbed
{
template <int dim>
void OutletBackflowTerm<dim>::face (const typename FlowTerm<dim>::CellIterator &,
                                    unsigned int,
                                    const FlowCellScratch<dim> &s,
                                    const FlowAssemblyState<dim> &,
                                    FlowCellCopy &copy) const
{
  if (!copy.with_matrix)
    return;
  const auto        &fv    = s.face_values;
  const unsigned int n_u   = s.indices.n_velocity_basis;
  const auto        &first = s.indices.velocity[0];
  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
  {
    const double backflow =
        gas_density * std::max (-(s.face_u[0][q] * fv.normal_vector (q)), 0.0);
    if (!(backflow > 0))
      continue;
    const double w = backflow * fv.JxW (q);
    for (unsigned int d = 0; d < dim; ++d)
    {
      const auto &rows = s.indices.velocity[d];
      for (unsigned int a = 0; a < n_u; ++a)
        for (unsigned int b = 0; b < n_u; ++b)
          copy.matrix (rows[a], rows[b]) +=
              w * fv.shape_value (first[a], q) * fv.shape_value (first[b], q);
    }
  }
}

template <int dim>
void OutletBackflowTerm<dim>::face_coefficients (
    const typename FlowTerm<dim>::CellIterator &,
    unsigned int,
    const FlowCellScratch<dim> &s,
    const FlowAssemblyState<dim> &,
    const unsigned int              q,
    FlowFacePointCoefficients<dim> &c) const
{
  const auto &fv = s.face_values;
  c.backflow += gas_density * std::max (-(s.face_u[0][q] * fv.normal_vector (q)), 0.0);
}

template class OutletBackflowTerm<2>;
template class OutletBackflowTerm<3>;
} // namespace wetbed
