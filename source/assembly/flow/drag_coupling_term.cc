#include <wetbed/assembly/flow/drag_coupling_term.h>

namespace wetbed
{
template <int dim>
void DragCouplingTerm<dim>::cell (const FlowCellScratch<dim> &s,
                                  const FlowAssemblyState<dim> &,
                                  FlowCellCopy &copy) const
{
  if (!copy.with_matrix)
    return;
  const unsigned int n_u = s.indices.n_velocity_basis;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const double beta = s.closures.coupling_drag[q] * s.JxW[q];
    for (unsigned int d = 0; d < dim; ++d)
    {
      const auto &gas = s.indices.velocity[d], &solids = s.indices.velocity[dim + d];
      for (unsigned int a = 0; a < n_u; ++a)
        for (unsigned int b = 0; b < n_u; ++b)
        {
          const double value = beta * s.phi[q][a] * s.phi[q][b];
          copy.matrix (gas[a], gas[b]) += value;
          copy.matrix (solids[a], solids[b]) += value;
          copy.matrix (gas[a], solids[b]) -= value;
          copy.matrix (solids[a], gas[b]) -= value;
        }
    }
  }
}

template <int dim>
void DragCouplingTerm<dim>::coefficients (const FlowCellScratch<dim> &s,
                                          const FlowAssemblyState<dim> &,
                                          const unsigned int          q,
                                          FlowPointCoefficients<dim> &c) const
{
  c.drag += s.closures.coupling_drag[q];
}

template class DragCouplingTerm<2>;
template class DragCouplingTerm<3>;
} // namespace wetbed
