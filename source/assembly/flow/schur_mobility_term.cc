#include <wetbed/assembly/flow/schur_mobility_term.h>

namespace wetbed
{
template <int dim>
void SchurMobilityTerm<dim>::cell (const FlowCellScratch<dim> &s,
                                   const FlowAssemblyState<dim> &,
                                   FlowCellCopy &copy) const
{
  const unsigned int n_p = s.indices.n_pressure_basis;
  const double       h2  = s.h * s.h;
  for (unsigned int q = 0; q < s.JxW.size (); ++q)
  {
    const double alpha_g = s.fraction[0][q], alpha_s = s.fraction[1][q];
    const double beta     = s.closures.coupling_drag[q];
    const double a_g      = s.bdf_mass[0][q] + alpha_g * material.gas_viscosity / h2;
    const double a_s      = s.bdf_mass[1][q] + s.closures.shear_viscosity[q] / h2;
    const double mobility = (alpha_g * alpha_g * a_s + alpha_s * alpha_s * a_g + beta) /
                            (a_g * a_s + beta * (a_g + a_s));
    for (unsigned int a = 0; a < n_p; ++a)
      for (unsigned int b = 0; b < n_p; ++b)
        copy.schur (a, b) +=
            mobility * (s.grad_phi_p[q][a] * s.grad_phi_p[q][b]) * s.JxW[q];
  }
}

template class SchurMobilityTerm<2>;
template class SchurMobilityTerm<3>;
} // namespace wetbed
