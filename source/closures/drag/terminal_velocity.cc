#include <wetbed/closures/drag/terminal_velocity.h>

#include <algorithm>
#include <cmath>

namespace wetbed::closures
{
double terminal_velocity (const double particle_density,
                          const double particle_diameter,
                          const double gas_density,
                          const double gas_viscosity,
                          const double gravity)
{
  const double buoyant = (particle_density - gas_density) * gravity;
  if (!(buoyant > 0) || !(particle_diameter > 0) || !(gas_viscosity > 0))
    return 0;
  // drag minus buoyant weight per particle volume, increasing in u: bisection
  const auto excess = [&] (const double u)
  {
    const double re = gas_density * u * particle_diameter / gas_viscosity;
    const double cd =
        re < 1000 ? 24 / std::max (re, 1e-300) * (1 + 0.15 * std::pow (re, 0.687)) : 0.44;
    return 0.75 * cd * gas_density * u * u / particle_diameter - buoyant;
  };
  double lo = 0, hi = 1;
  while (excess (hi) < 0 && hi < 1e6)
    hi *= 2;
  for (unsigned int k = 0; k < 100; ++k)
  {
    const double mid             = 0.5 * (lo + hi);
    (excess (mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
} // namespace wetbed::closures
