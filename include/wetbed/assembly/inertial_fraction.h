#pragma once

#include <deal.II/base/tensor.h>

#include <algorithm>

namespace wetbed
{
/**
 * The volume fraction that weights the inertia of phase k (0 gas, 1 solids) in the
 * momentum equations: alpha_g = 1 - alpha_s, and alpha_s floored at the residual solids
 * fraction (a dilute solids phase keeps some inertia).
 */
inline double inertial_fraction (const unsigned int k,
                                 const double       alpha_s,
                                 const double       residual_fraction)
{
  return k == 0 ? 1 - alpha_s : std::max (alpha_s, residual_fraction);
}

/**
 * div(f_k u) = u . grad f_k + f_k div u for that fraction f_k, from alpha_s and its
 * gradient (grad f_k is -grad alpha_s for the gas, grad alpha_s above the residual
 * fraction for the solids, 0 below it); grad_u[i][j] = d_j u_i.
 */
template <int dim>
double inertial_flux_divergence (const unsigned int            k,
                                 const double                  alpha_s,
                                 const dealii::Tensor<1, dim> &grad_alpha_s,
                                 const dealii::Tensor<1, dim> &u,
                                 const dealii::Tensor<2, dim> &grad_u,
                                 const double                  residual_fraction)
{
  const double slope = k == 0 ? -1.0 : (alpha_s > residual_fraction ? 1.0 : 0.0);
  return slope * (u * grad_alpha_s) +
         inertial_fraction (k, alpha_s, residual_fraction) * dealii::trace (grad_u);
}
} // namespace wetbed
