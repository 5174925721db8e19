#pragma once

#include <wetbed/closures/frictional/schaeffer_viscosity.h>
#include <wetbed/closures/number_traits.h>

#include <cmath>

namespace wetbed::closures
{
/**
 * Liquid and bridge data of a slightly wet bed (`subsection wet particles`; seed 000 s3,
 * doc/theory.md, "Wet closures").
 */
struct LiquidBridgeProperties
{
  double liquid_loading;             // delta = M_L / M_s (-)
  double liquid_viscosity;           // mu_L (Pa s)
  double liquid_density;             // rho_L (kg/m^3)
  double contact_angle;              // gamma_c (rad)
  double surface_tension;            // sigma (N/m), Pitois rupture distance
  double asperity;                   // h_a (m)
  double approach_factor;            // c_u in u_dot = c_u sqrt(pi Theta)
  double stability_angle;            // phi' (rad), wet viscosity
  double film_thickness;             // delta_f / d, Gollwitzer restitution
  double switch_width;               // relative width of the smoothed on/off switches
  double strain_rate_regularisation; // eps in |gamma_dot| = 2 sqrt(I_2D + eps^2) (1/s)
  double maximum_viscosity;          // cap of mu_wet (Pa s)
  bool   approach_only = false;      // lubrication stress only where div u_s < 0
};

/** Particle data the wet closures need. */
struct WetParticleMaterial
{
  double particle_density;  // rho_s
  double particle_diameter; // d
  double dry_restitution;   // e_dry
};

/** The state of a wet contact at one point: what the restitution laws depend on. */
template <typename Number>
struct WetContact
{
  Number gap;              // h, Woodcock
  Number rupture_distance; // h_c
  Number above_asperity;   // smoothed indicator of h > h_a
  Number bridged;          // smoothed indicator of h <= h_c
  Number stokes;           // St
  Number critical_stokes;  // St*
};

/** Woodcock inter-particle gap h = d [(1/(3 pi alpha_s) + 5/6)^(1/2) - 1] (seed 000 Eq.
 * 7); h = 0 at alpha_s = 0.6 (Woodcock's random close packing of this form). */
template <typename Number>
Number woodcock_gap (const Number &alpha_s, const double diameter)
{
  using std::sqrt;
  return diameter * (sqrt (1.0 / (3.0 * M_PI * alpha_s) + 5.0 / 6.0) - 1.0);
}

/** Approach velocity u_dot = c_u sqrt(pi Theta): c_u = 3/2 makes seed 000 Eq. 5 follow
 * from Eqs. 2-4 (its Eq. 3 prints 2/3; doc/theory.md, "Wet closures"). */
template <typename Number>
Number approach_velocity (const Number &theta, const double approach_factor)
{
  using std::sqrt;
  return approach_factor * sqrt (M_PI * theta);
}

/** St = 8 m u_dot / (3 pi mu_L d^2), m = rho_s pi d^3 / 6 (seed 000 Eq. 12). */
template <typename Number>
Number stokes_number (const Number              &approach_velocity,
                      const WetParticleMaterial &particle,
                      const double               liquid_viscosity)
{
  const double d = particle.particle_diameter;
  const double m = particle.particle_density * M_PI * d * d * d / 6.0;
  return 8.0 * m * approach_velocity / (3.0 * M_PI * liquid_viscosity * d * d);
}

/** St* = (1 + 1/e_dry) ln(h / h_a) (seed 000 Eq. 13). */
template <typename Number>
Number critical_stokes_number (const Number &gap,
                               const double  asperity,
                               const double  dry_restitution)
{
  using std::log;
  return (1.0 + 1.0 / dry_restitution) * log (gap / asperity);
}

/** Smoothed Heaviside of x: 1/2 (1 + tanh(x / width)); the sharp step (1 for x >= 0)
 * for width = 0. */
template <typename Number>
Number smooth_step (const Number &x, const double width)
{
  if (width > 0)
    return 0.5 * (1.0 + math::tanh (Number (x / width)));
  return select_greater_equal (x, 0.0, Number (1.0), Number (0.0));
}

/** The liquid-bridge normal stress of a bridged contact, before the gap window:
 * P = (3/8) pi mu_L d^2 u_dot / h * (6 alpha_s / (pi d^3))^(2/3) (seed 000 Eqs. 2-5). */
template <typename Number>
Number bridge_pressure (const Number &alpha_s,
                        const Number &gap,
                        const Number &approach_velocity,
                        const double  liquid_viscosity,
                        const double  diameter)
{
  using std::pow;
  const double d = diameter;
  return 3.0 / 8.0 * M_PI * liquid_viscosity * d * d * approach_velocity / gap *
         pow (6.0 * alpha_s / (M_PI * d * d * d), 2.0 / 3.0);
}

/** mu_wet = sqrt(2) P_wet sin(phi') / |gamma_dot| (seed 000 Eq. 6) with |gamma_dot| =
 * 2 sqrt(I_2D + eps^2) (the Schaeffer denominator: in simple shear the wet stress is
 * sqrt(2) P_wet sin(phi')), capped at mu_max. */
template <typename Number>
Number wet_viscosity (const Number &wet_pressure,
                      const Number &second_invariant,
                      const double  stability_angle,
                      const double  regularisation,
                      const double  maximum_viscosity)
{
  // sqrt(2) times the Schaeffer form with the wet pressure (same denominator and cap)
  return std::sqrt (2.0) * schaeffer_viscosity (wet_pressure,
                                                second_invariant,
                                                stability_angle,
                                                regularisation,
                                                maximum_viscosity / std::sqrt (2.0));
}

/** Weight of the lubrication stress (P_wet and mu_wet) on the solids' dilatation
 * div u_s (1/s) when it resists only approach: 1 where the solids converge (div u_s <=
 * 0), eps^2/(eps^2 + div u_s^2) where they separate, eps the strain rate
 * regularisation (smooth at 0; doc/theory.md, "Wet closures"). */
inline double approach_weight (const double velocity_divergence,
                               const double regularisation)
{
  if (velocity_divergence <= 0.0)
    return 1.0;
  const double e2 = regularisation * regularisation;
  return e2 / (e2 + velocity_divergence * velocity_divergence);
}

/**
 * The contact state at (alpha_s, Theta) (gap, h_c, window indicators, St, St*), with
 * the rupture distance h_c(u_dot) of a law as a callable, e.g.
 * [&](const Number &u) { return LianRuptureDistance::value (u, liquid, particle); }.
 * Floors: no solids -> an infinite gap; Theta -> 0 -> St -> 0; the gap above Woodcock's
 * packing (h <= 0) is floored at h_a/100 for h_c - h, St* and P (the window is then
 * closed: dry contact).
 */
template <typename Number, typename RuptureDistanceFunction>
WetContact<Number> wet_contact (const Number                  &alpha_s,
                                const Number                  &theta,
                                const LiquidBridgeProperties  &liquid,
                                const WetParticleMaterial     &particle,
                                const RuptureDistanceFunction &rupture_distance)
{
  const auto        &l         = liquid;
  const Number       a         = select_greater (alpha_s, 1e-12, alpha_s, Number (1e-12));
  const Number       t         = select_greater (theta, 1e-14, theta, Number (1e-14));
  const Number       gap       = woodcock_gap (a, particle.particle_diameter);
  const Number       gap_floor = 0.01 * l.asperity;
  const Number       h         = select_greater (gap, gap_floor, gap, gap_floor);
  const Number       u_dot     = approach_velocity (t, l.approach_factor);
  const Number       h_c       = rupture_distance (u_dot);
  WetContact<Number> c;
  c.gap              = gap;
  c.rupture_distance = h_c;
  c.above_asperity = smooth_step (Number ((h - l.asperity) / l.asperity), l.switch_width);
  c.bridged        = smooth_step (Number ((h_c - h) / h_c), l.switch_width);
  c.stokes         = stokes_number (u_dot, particle, l.liquid_viscosity);
  c.critical_stokes = critical_stokes_number (h, l.asperity, particle.dry_restitution);
  return c;
}
} // namespace wetbed::closures
