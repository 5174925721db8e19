#include <wetbed/assembly/flow/pressure_coupling_term.h>

namespace wetbed
{
template <int dim>
void PressureCouplingTerm<dim>::cell (const FlowCellScratch<dim> &s,
                                      const FlowAssemblyState<dim> &,
                                      FlowCellCopy &copy) const
{
  if (!copy.with_matrix)
    return;
  const unsigned int n_u = s.indices.n_velocity_basis, n_p = s.indices.n_pressure_basis;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
    for (unsigned int k = 0; k < 2; ++k)
    {
      // grad alpha_g = -grad alpha_s
      const double sign = k == 0 ? -1.0 : 1.0, fraction = s.fraction[k][q];
      for (unsigned int d = 0; d < dim; ++d)
      {
        const auto  &rows          = s.indices.velocity[k * dim + d];
        const double grad_fraction = sign * s.grad_alpha_s[q][d];
        for (unsigned int a = 0; a < n_u; ++a)
        {
          // div(alpha_k v) for v = phi_a e_d
          const double divergence =
              (fraction * s.grad_phi[q][a][d] + s.phi[q][a] * grad_fraction) * s.JxW[q];
          for (unsigned int b = 0; b < n_p; ++b)
          {
            const double value = -s.phi_p[q][b] * divergence;
            copy.matrix (rows[a], s.indices.pressure[b]) += value;
            copy.matrix (s.indices.pressure[b], rows[a]) += value;
          }
        }
      }
    }
}

template <int dim>
void PressureCouplingTerm<dim>::coefficients (const FlowCellScratch<dim> &s,
                                              const FlowAssemblyState<dim> &,
                                              const unsigned int          q,
                                              FlowPointCoefficients<dim> &c) const
{
  c.pressure_coupling = true;
  c.alpha_s           = s.fraction[1][q];
  c.grad_alpha_s      = s.grad_alpha_s[q];
}

template class PressureCouplingTerm<2>;
template class PressureCouplingTerm<3>;
} // namespace wetbed
