#pragma once

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace wetbed
{
/**
 * Weak no-penetration u_k.n = 0 on a slip wall by symmetric Nitsche (doc/theory.md,
 * "No penetration by symmetric Nitsche"; Urquiza-Garon-Farinas 2014), for each phase k
 * that slips there:
 *   - int (n.sigma_k(u_k, p) n)(v_k.n) - int (n.tau_k(v_k) n)(u_k.n)
 *   + int gamma mu*_k / h (u_k.n)(v_k.n)
 * with sigma_k = tau_k - alpha_k p I - P_k I, tau_k = 2 mu_k D + b_k (div u) I, and the
 * symmetric counterpart + int alpha_k q (u_k.n) of the pressure term in the mixture
 * continuity row (the continuity row is -(q, div(alpha_k u_k)), the transpose of the
 * momentum's -(p, div(alpha_k v_k))). P_k, the solids pressure applied explicitly in the
 * volume as (P, div v), gives the consistency term -int P (v.n) on the right-hand side.
 * The tangential traction stays natural (zero, or the Robin -C u_slip added elsewhere).
 * The penalty scale mu*_k = mu_k + alpha_k rho_k |u_k| h + alpha_k rho_k h^2/dt + beta
 * h^2 keeps the term active where inertia or drag dominate the viscosity (Massing,
 * Schott, Wall); gamma = gamma_0 (degree + 1)^2.
 * cell_matrix may be null (the right-hand side alone).
 * n is the wall normal given by the caller: on a curved wall the manifold's normal at the
 * quadrature point, not the normal of the mapped (Q2) face. The mapped normal is off by
 * O(h^2) between the nodes, so u.n_h = 0 imposed weakly there perturbs the boundary data
 * by O(h^2) at the scale h, which costs the velocity gradient half an order (measured in
 * T11: 1.5 instead of 2).
 */
struct NitschePhase
{
  bool         slips = false;   // weak no-penetration for this phase on this face
  unsigned int first_component; // 0: gas, dim: solids
  double       fraction;        // alpha_k at the face point
  double       viscosity;       // mu_k as in the volume terms (alpha_g mu_g for the gas)
  double       bulk;            // b_k: tau_k = 2 mu_k D + b_k (div u) I
  double       penalty_scale;   // mu*_k
  double       normal_pressure; // P_k applied explicitly (solids pressure), else 0
};

template <int dim>
void add_nitsche_no_penetration (const dealii::FEFaceValues<dim>   &face_values,
                                 unsigned int                       q,
                                 const dealii::Tensor<1, dim>      &n,
                                 const std::vector<unsigned int>   &component,
                                 const std::array<NitschePhase, 2> &phases,
                                 double                             gamma,
                                 double                             h,
                                 dealii::FullMatrix<double>        *cell_matrix,
                                 dealii::Vector<double>            &cell_rhs);
} // namespace wetbed
