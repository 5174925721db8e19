#include <wetbed/assembly/flow/body_force_term.h>

namespace wetbed
{
template <int dim>
void BodyForceTerm<dim>::cell (const FlowCellScratch<dim> &s,
                               const FlowAssemblyState<dim> &,
                               FlowCellCopy &copy) const
{
  const unsigned int           n_u = s.indices.n_velocity_basis;
  const dealii::Tensor<1, dim> weight =
      s.alpha_mean * (material.particle_density - material.gas_density) *
      material.gravity;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const double pressure =
        (s.compaction_pressure[q] + s.closures.kinetic_pressure[q]) * s.JxW[q];
    for (unsigned int d = 0; d < dim; ++d)
    {
      const auto &rows = s.indices.velocity[dim + d];
      for (unsigned int a = 0; a < n_u; ++a)
        copy.rhs (rows[a]) +=
            weight[d] * s.phi[q][a] * s.JxW[q] + pressure * s.grad_phi[q][a][d];
    }
  }
}

template class BodyForceTerm<2>;
template class BodyForceTerm<3>;
} // namespace wetbed
