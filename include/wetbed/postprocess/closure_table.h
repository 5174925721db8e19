#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace wetbed
{
struct Parameters;

/** A local state at which `wetbed closures` evaluates every closure. */
struct ClosurePoint
{
  double alpha_s;
  double theta;      // m^2/s^2
  double shear_rate; // sqrt(2 D_dev:D_dev) (1/s)
};

/**
 * `wetbed closures CASE.prm [--alpha-s A,...] [--theta T,...] [--shear-rate G,...]
 * [--points FILE]`: the points (the product of the lists, or the rows "alpha_s theta
 * shear_rate" of FILE; default alpha_s = 0.01, 0.02, ..., maximum packing at Theta =
 * 1e-3 and 1/s). Throws InputError naming the option on bad input.
 */
std::vector<ClosurePoint> closure_points (const std::vector<std::string> &options,
                                          const Parameters               &parameters);

/** Every dry closure of the case at the points, and with a positive liquid loading
 * every wet one (h, h_c, regime, u_dot, P_wet, mu_wet, St, St*, e_wet), as CSV. */
void write_closure_table (const Parameters                &parameters,
                          const std::vector<ClosurePoint> &points,
                          std::ostream                    &out);
} // namespace wetbed
