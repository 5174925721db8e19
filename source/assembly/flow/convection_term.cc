#include <wetbed/assembly/flow/convection_term.h>

#include <cmath>

namespace wetbed
{
template <int dim>
double ConvectionTerm<dim>::supg (const FlowCellScratch<dim>   &s,
                                  const FlowAssemblyState<dim> &state,
                                  const unsigned int            q,
                                  const unsigned int            k) const
{
  if (!streamline_diffusion)
    return 0;
  const dealii::Tensor<1, dim> &u       = s.u[k][q];
  const double                  inertia = s.inertia[k][q];
  const double                  density = std::max (inertia, 1e-12);
  const double                  nu      = s.viscosity[k][q] / density;
  const double                  h_node  = 0.5 * s.h;
  const double                  tau =
      1.0 / std::sqrt (std::pow (2.0 * state.bdf.a0 / state.dt, 2) +
                       std::pow (2.0 * u.norm () / h_node, 2) +
                       std::pow (12.0 * nu / (h_node * h_node), 2) +
                       std::pow (s.closures.coupling_drag[q] / density, 2));
  return tau * inertia * inertia;
}

template <int dim>
void ConvectionTerm<dim>::coefficients (const FlowCellScratch<dim>   &s,
                                        const FlowAssemblyState<dim> &state,
                                        const unsigned int            q,
                                        FlowPointCoefficients<dim>   &c) const
{
  for (unsigned int k = 0; k < 2; ++k)
  {
    c.inertia[k] += s.inertia[k][q];
    c.supg[k] += supg (s, state, q, k);
    c.advection[k] = s.u[k][q];
  }
}

template <int dim>
void ConvectionTerm<dim>::cell (const FlowCellScratch<dim>   &s,
                                const FlowAssemblyState<dim> &state,
                                FlowCellCopy                 &copy) const
{
  if (!copy.with_matrix)
    return;
  const unsigned int  n_u = s.indices.n_velocity_basis;
  std::vector<double> advective (n_u);
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const double w = s.JxW[q];
    for (unsigned int k = 0; k < 2; ++k)
    {
      const dealii::Tensor<1, dim> &u       = s.u[k][q];
      const double                  inertia = s.inertia[k][q];
      for (unsigned int b = 0; b < n_u; ++b)
        advective[b] = u * s.grad_phi[q][b];
      const double weight = supg (s, state, q, k);
      for (unsigned int d = 0; d < dim; ++d)
      {
        const auto &rows = s.indices.velocity[k * dim + d];
        for (unsigned int a = 0; a < n_u; ++a)
        {
          const double test = (inertia * s.phi[q][a] + weight * advective[a]) * w;
          for (unsigned int b = 0; b < n_u; ++b)
            copy.matrix (rows[a], rows[b]) += test * advective[b];
        }
      }
    }
  }
}

template class ConvectionTerm<2>;
template class ConvectionTerm<3>;
} // namespace wetbed
