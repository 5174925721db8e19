#include <wetbed/assembly/flow/viscous_term.h>

namespace wetbed
{
template <int dim>
void ViscousTerm<dim>::cell (const FlowCellScratch<dim> &s,
                             const FlowAssemblyState<dim> &,
                             FlowCellCopy &copy) const
{
  if (!copy.with_matrix)
    return;
  const unsigned int n_u = s.indices.n_velocity_basis;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const auto &grad = s.grad_phi[q];
    for (unsigned int k = 0; k < 2; ++k)
    {
      const double mu = s.viscosity[k][q] * s.JxW[q], bulk = s.bulk[k][q] * s.JxW[q];
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int e = 0; e < dim; ++e)
        {
          const auto &rows = s.indices.velocity[k * dim + d];
          const auto &cols = s.indices.velocity[k * dim + e];
          for (unsigned int a = 0; a < n_u; ++a)
            for (unsigned int b = 0; b < n_u; ++b)
            {
              // 2 mu D(u):D(v) + b div u div v, row (d, a), column (e, b)
              double value =
                  mu * grad[b][d] * grad[a][e] + bulk * grad[b][e] * grad[a][d];
              if (d == e)
                value += mu * (grad[a] * grad[b]);
              copy.matrix (rows[a], cols[b]) += value;
            }
        }
    }
  }
}

template <int dim>
void ViscousTerm<dim>::coefficients (const FlowCellScratch<dim> &s,
                                     const FlowAssemblyState<dim> &,
                                     const unsigned int          q,
                                     FlowPointCoefficients<dim> &c) const
{
  for (unsigned int k = 0; k < 2; ++k)
  {
    c.viscosity[k] += s.viscosity[k][q];
    c.bulk[k] += s.bulk[k][q];
  }
}

template class ViscousTerm<2>;
template class ViscousTerm<3>;
} // namespace wetbed
