#pragma once

namespace wetbed
{
/**
 * Variable-step BDF weights: du/dt at t_{n+1} ~ (a0 u^{n+1} + a1 u^n + a2 u^{n-1}) / dt
 * with dt = t_{n+1} - t_n and omega = dt / (t_n - t_{n-1}).
 */
struct BDFCoefficients
{
  double a0, a1, a2;
};

inline BDFCoefficients
bdf_coefficients (const unsigned int order, const double dt, const double previous_dt)
{
  if (order == 1 || previous_dt <= 0.0)
    return {1.0, -1.0, 0.0};
  const double omega = dt / previous_dt;
  return {
      (1.0 + 2.0 * omega) / (1.0 + omega), -(1.0 + omega), omega * omega / (1.0 + omega)};
}
} // namespace wetbed
