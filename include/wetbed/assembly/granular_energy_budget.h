#pragma once

namespace wetbed
{
/** Where the granular energy goes (W per metre depth in 2D, W in 3D), integrated. */
struct GranularEnergyBudget
{
  double production    = 0; // viscous heating + compression
  double dissipation   = 0; // inelastic collisions
  double drag_exchange = 0; // -3 beta Theta, to the gas
  double wall_flux     = 0; // G_w - D_w through Johnson-Jackson walls (into the bed)
};
} // namespace wetbed
