#include <wetbed/assembly/flow/inertia_term.h>
#include <wetbed/assembly/inertial_fraction.h>

namespace wetbed
{
template <int dim>
std::pair<double, double> InertiaTerm<dim>::mass_coefficient (
    const FlowCellScratch<dim> &s, const unsigned int q, const unsigned int k) const
{
  if (form == MomentumForm::advective)
    return {s.bdf_mass[k][q], s.bdf_mass[k][q]};
  const double density = k == 0 ? material.gas_density : material.particle_density;
  const double divergence =
      inertial_flux_divergence<dim> (k,
                                     s.alpha_s[q],
                                     s.grad_alpha_s[q],
                                     s.u[k][q],
                                     s.grad_u[k][q],
                                     material.residual_solids_fraction);
  if (form == MomentumForm::conservative)
    return {s.bdf_mass[k][q] + density * divergence,
            s.bdf_mass[k][q] + density * std::max (divergence, 0.0)};
  // skew-symmetric: the mean of the new and the old fraction, half the divergence; the
  // part below half the time coefficient is lagged (the diagonal stays positive)
  const double old =
      inertial_fraction (k, s.alpha_s_old[q], material.residual_solids_fraction) *
      density;
  const double rate      = s.inertia[k][q] > 0 ? s.bdf_mass[k][q] / s.inertia[k][q] : 0;
  const double time_part = 0.5 * (s.bdf_mass[k][q] + rate * old);
  const double full      = time_part + 0.5 * density * divergence;
  return {full, std::max (full, 0.5 * time_part)};
}

template <int dim>
double InertiaTerm<dim>::mass (const FlowCellScratch<dim> &s,
                               const unsigned int          q,
                               const unsigned int          k) const
{
  return mass_coefficient (s, q, k).second;
}

template <int dim>
void InertiaTerm<dim>::coefficients (const FlowCellScratch<dim> &s,
                                     const FlowAssemblyState<dim> &,
                                     const unsigned int          q,
                                     FlowPointCoefficients<dim> &c) const
{
  for (unsigned int k = 0; k < 2; ++k)
    c.mass[k] += mass (s, q, k);
}

template <int dim>
void InertiaTerm<dim>::cell (const FlowCellScratch<dim>   &s,
                             const FlowAssemblyState<dim> &state,
                             FlowCellCopy                 &copy) const
{
  const auto        &bdf = state.bdf;
  const double       dt = state.dt, residual = material.residual_solids_fraction;
  const double       density[2] = {material.gas_density, material.particle_density};
  const unsigned int n_u        = s.indices.n_velocity_basis;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const double w = s.JxW[q];
    for (unsigned int k = 0; k < 2; ++k)
    {
      // the weights of u^n and u^{n-1} in the history
      double                 history[2] = {s.inertia[k][q], s.inertia[k][q]};
      dealii::Tensor<1, dim> force;
      if (form != MomentumForm::advective)
      {
        history[0] = inertial_fraction (k, s.alpha_s_old[q], residual) * density[k];
        history[1] = inertial_fraction (k, s.alpha_s_old2[q], residual) * density[k];
      }
      if (form == MomentumForm::skew_symmetric)
        history[1] = 0.5 * (history[1] + history[0]);
      // the part of the mass coefficient not taken implicitly, with the lagged u*
      const auto [full, m] = mass_coefficient (s, q, k);
      force                = (m - full) * s.u[k][q];
      force -=
          (bdf.a1 * history[0] * s.u_old[k][q] + bdf.a2 * history[1] * s.u_old2[k][q]) /
          dt;
      for (unsigned int d = 0; d < dim; ++d)
      {
        const auto &rows = s.indices.velocity[k * dim + d];
        for (unsigned int a = 0; a < n_u; ++a)
        {
          const double phi_a = s.phi[q][a] * w;
          copy.rhs (rows[a]) += force[d] * phi_a;
          if (copy.with_matrix)
            for (unsigned int b = 0; b < n_u; ++b)
              copy.matrix (rows[a], rows[b]) += m * phi_a * s.phi[q][b];
        }
      }
    }
  }
}

template class InertiaTerm<2>;
template class InertiaTerm<3>;
} // namespace wetbed
