#pragma once

namespace wetbed::closures
{
/**
 * The terminal velocity (m/s) of a single sphere of diameter d (m) and density rho_s
 * settling under gravity g (m/s^2) in a gas of density rho_g and viscosity mu, with the
 * Schiller-Naumann drag coefficient C_D = 24/Re (1 + 0.15 Re^0.687) below Re = 1000
 * and 0.44 above (doc/theory.md, "Divergence checks"); a speed scale of the case.
 */
double terminal_velocity (double particle_density,
                          double particle_diameter,
                          double gas_density,
                          double gas_viscosity,
                          double gravity);
} // namespace wetbed::closures
