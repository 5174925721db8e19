#pragma once

#include <deal.II/base/tensor.h>

#include <array>

namespace wetbed
{
/**
 * The coefficients of the flow system's bilinear form at one quadrature point of a
 * cell, as the volume terms define them (doc/theory.md, "Matrix-free flow operator"):
 * with phase k (0 gas, 1 solids), velocity u_k and test function v_k,
 *   a(u, v) = sum_k [ mass_k (u_k, v_k) + (tau_k(u_k), grad v_k)
 *                     + ((inertia_k v_k + supg_k w_k.grad v_k), w_k.grad u_k) ]
 *             + (beta (u_g - u_s), v_g - v_s)
 *             - sum_k (p, div(f_k v_k)) - sum_k (q, div(f_k u_k)),
 * tau_k(u) = mu_k (grad u + grad u^T) + bulk_k (div u) I, w_k the advecting velocity
 * (the linearisation point), f_g = 1 - alpha_s, f_s = alpha_s. The assembled operator
 * and the matrix-free one read the same numbers: each term writes its own part.
 */
template <int dim>
struct FlowPointCoefficients
{
  std::array<double, 2>                 mass{{0, 0}}, viscosity{{0, 0}}, bulk{{0, 0}};
  std::array<double, 2>                 inertia{{0, 0}}, supg{{0, 0}};
  std::array<dealii::Tensor<1, dim>, 2> advection;
  double                                drag = 0;
  // the pressure couplings: alpha_s and its gradient (0 without them)
  bool                   pressure_coupling = false;
  double                 alpha_s           = 0;
  dealii::Tensor<1, dim> grad_alpha_s;
};

/**
 * The coefficients of the boundary terms at one quadrature point of a boundary face:
 *   sum_k friction_k (P_t u_k, P_t v_k) + backflow (u_g, v_g)
 *   + sum_{k slipping} [ -(n.tau_k(u_k) n)(v_k.n) - (n.tau_k(v_k) n)(u_k.n)
 *                        + penalty_k (u_k.n)(v_k.n) + f_k p (v_k.n) + f_k q (u_k.n) ],
 * P_t = I - n_h n_h with the mapped normal n_h, n the wall's own normal (Nitsche).
 */
template <int dim>
struct FlowFacePointCoefficients
{
  std::array<double, 2>  friction{{0, 0}};
  double                 backflow = 0;
  std::array<bool, 2>    slips{{false, false}};
  std::array<double, 2>  viscosity{{0, 0}}, bulk{{0, 0}}, penalty{{0, 0}};
  std::array<double, 2>  fraction{{0, 0}};
  dealii::Tensor<1, dim> wall_normal;
};
} // namespace wetbed
