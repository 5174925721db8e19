// T1 (wet closures): gap, rupture distances (Lian, Pitois, Mikami), approach velocity,
// St, St*, P_wet, mu_wet and the wet restitution laws (bridge-gated, literal,
// Gollwitzer) at points outside, inside and at both ends of the wet window, against
// values written from seed 000 s3 independently of the C++
// (tests/wet_closures_reference.py; rel. 1e-12), the smoothed window at its ends
// (exactly 1/2), the dry-scene guarantee (no WetParticles without liquid), and every
// Sacado derivative against a central difference.
//
// One point by hand (alpha_s = 0.45, Theta = 1e-3, seed-000 oil): 1/(3 pi 0.45) =
// 0.235785, + 5/6 = 1.069118, sqrt = 1.033982, h = 350e-6 x 0.033982 = 1.18936e-5 m;
// h_c = 0.5 x 1.0875 x 350e-6 x (0.001 x 2500/969)^(1/3) = 2.61019e-5 m, so h_a < h <=
// h_c (bridged); sqrt(pi 1e-3) = 0.0560499, P = 9/16 pi 0.4945 x 0.0560499 / 1.18936e-5
// x (6 x 0.45/pi)^(2/3) = 4118.07 x 0.903950 = 3722.6 Pa (doc/theory.md, "Wet closures":
// 3.72 kPa).
#include "test_utilities.h"

#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>
#include <wetbed/closures/wet/bridge_gated_restitution.h>
#include <wetbed/closures/wet/gollwitzer_restitution.h>
#include <wetbed/closures/wet/lian_rupture_distance.h>
#include <wetbed/closures/wet/literal_restitution.h>
#include <wetbed/closures/wet/mikami_rupture_distance.h>
#include <wetbed/closures/wet/pitois_rupture_distance.h>
#include <wetbed/closures/wet/wet_particles.h>
#include <wetbed/core/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>

using namespace wetbed;
using namespace wetbed::closures;
using testing::check;
using testing::check_close;
using testing::check_derivative;

namespace
{
/** Solids fraction at which the Woodcock gap equals h. */
double fraction_at_gap (const double h, const double d)
{
  const double s = h / d + 1.0;
  return 1.0 / (3.0 * M_PI * (s * s - 5.0 / 6.0));
}

struct Reference
{
  double alpha, theta, i2d;
  double gap, approach, stokes, critical_stokes, pressure, viscosity, e_gated, e_literal,
      e_gollwitzer, pitois;
};
} // namespace

int main ()
{
  LiquidBridgeProperties    liquid{0.1e-2,
                                0.4945,
                                969.0,
                                0.175,
                                0.021,
                                2.8e-6,
                                1.5,
                                30.0 * M_PI / 180.0,
                                0.1,
                                0.0,
                                1e-3,
                                1000.0};
  const WetParticleMaterial glass{2500.0, 350e-6, 0.9};
  const double              d = glass.particle_diameter;

  // tests/wet_closures_reference.py
  const double lian = 2.6101936262996381e-05, mikami = 2.5338892480395478e-05;
  const std::vector<Reference> reference = {
      // ruptured (h > h_c): no bridge, e_dry; the literal law stops the rebound
      {0.2,
       1e-3,
       1.0,
       5.8743931774557220e-05,
       8.4074868245968937e-02,
       6.6118871780899077e-02,
       6.4253111544144366e+00,
       0,
       0,
       0.9,
       0,
       0,
       6.2828417716183395e-05},
      // bridged, St << St*: e = 0; mu_wet at the cap
      {0.45,
       1e-3,
       1.0,
       1.1893642097718226e-05,
       8.4074868245968937e-02,
       6.6118871780899077e-02,
       3.0534785211638771e+00,
       3.7225570346055283e+03,
       1000,
       0,
       0,
       0,
       6.2828417716183395e-05},
      {0.45,
       1e-2,
       25.0,
       1.1893642097718226e-05,
       2.6586807763582743e-01,
       2.0908623114827460e-01,
       3.0534785211638771e+00,
       1.1771758949235709e+04,
       8.3238904130201888e+02,
       0,
       0,
       0,
       9.1411882034375235e-05},
      // contact (h <= h_a): dry
      {0.59,
       1e-3,
       1.0,
       2.2971115901376572e-06,
       8.4074868245968937e-02,
       6.6118871780899077e-02,
       -4.1793015143317636e-01,
       0,
       0,
       0.9,
       0.9,
       0,
       6.2828417716183395e-05},
      // bridged with St > St*: e_dry (1 - St*/St)
      {0.45,
       50.0,
       1.0,
       1.1893642097718226e-05,
       1.8799712059732503e+01,
       1.4784629189768291e+01,
       3.0534785211638771e+00,
       8.3238905794979970e+05,
       1000,
       7.1412244880992115e-01,
       7.1412244880992115e-01,
       4.4335181945993909e-02,
       5.7529092905866605e-04},
      // fast shear: mu_wet below the cap
      {0.45,
       1e-3,
       1e8,
       1.1893642097718226e-05,
       8.4074868245968937e-02,
       6.6118871780899077e-02,
       3.0534785211638771e+00,
       3.7225570346055283e+03,
       1.3161226612616206e-01,
       0,
       0,
       0,
       6.2828417716183395e-05}};

  check_close (LianRuptureDistance::value (0.0, liquid, glass), lian, 1e-12, "h_c Lian");
  check_close (
      MikamiRuptureDistance::value (0.0, liquid, glass), mikami, 1e-12, "h_c Mikami");

  for (const std::string restitution : {"bridge-gated", "literal", "Gollwitzer"})
  {
    const WetParticles wet (liquid, glass, "Lian", restitution);
    for (const auto &r : reference)
    {
      const std::string at = " at alpha_s " + std::to_string (r.alpha) + ", Theta " +
                             std::to_string (r.theta) + ", I_2D " +
                             std::to_string (r.i2d);
      const WetClosures w = wet.evaluate (r.alpha, r.theta, r.i2d, 10.0);
      check_close (w.gap, r.gap, 1e-12, "gap" + at);
      check_close (w.rupture_distance, lian, 1e-12, "h_c" + at);
      check_close (w.approach_velocity, r.approach, 1e-12, "u_dot" + at);
      check_close (w.stokes, r.stokes, 1e-12, "St" + at);
      check_close (w.critical_stokes, r.critical_stokes, 1e-12, "St*" + at);
      const auto near = [] (const double value, const double reference) {
        return std::abs (value - reference) <=
               1e-12 * std::max (1.0, std::abs (reference));
      };
      check (near (w.pressure, r.pressure),
             "P_wet" + at + ": " + std::to_string (w.pressure));
      check (near (w.viscosity, r.viscosity),
             "mu_wet" + at + ": " + std::to_string (w.viscosity));
      const double e = restitution == "bridge-gated" ? r.e_gated
                       : restitution == "literal"    ? r.e_literal
                                                     : r.e_gollwitzer;
      check (near (w.restitution, e),
             restitution + " e_wet" + at + ": " + std::to_string (w.restitution));
      check_close (PitoisRuptureDistance::value (r.approach, liquid, glass),
                   r.pitois,
                   1e-12,
                   "h_c Pitois" + at);
    }
  }
  {
    const WetParticles wet (liquid, glass, "Lian", "bridge-gated");
    check (wet.evaluate (0.2, 1e-3, 1, 0.0).regime (liquid.asperity) == "ruptured" &&
               wet.evaluate (0.45, 1e-3, 1, 0.0).regime (liquid.asperity) == "bridged" &&
               wet.evaluate (0.59, 1e-3, 1, 0.0).regime (liquid.asperity) == "contact",
           "regimes ruptured / bridged / contact");
  }

  // `lubrication stress = approach only`: P_wet and mu_wet unchanged where the solids
  // converge (div u_s <= 0), scaled by eps^2/(eps^2 + div^2) where they separate (one
  // half at div = eps), the literal model's values otherwise; e_wet unaffected
  {
    const WetParticles     literal (liquid, glass, "Lian", "bridge-gated");
    LiquidBridgeProperties approach = liquid;
    approach.approach_only          = true;
    const WetParticles resisting (approach, glass, "Lian", "bridge-gated");
    const double       eps = liquid.strain_rate_regularisation;
    for (const double divergence : {-5.0, 0.0, eps, 3 * eps, 100.0})
    {
      const WetClosures a = literal.evaluate (0.45, 1e-3, 1.0, divergence);
      const WetClosures b = resisting.evaluate (0.45, 1e-3, 1.0, divergence);
      const double      expected =
          divergence <= 0 ? 1.0 : eps * eps / (eps * eps + divergence * divergence);
      const std::string at = " at div u_s = " + std::to_string (divergence);
      check (a.pressure > 0 && a.approach_weight == 1.0, "literal weight" + at);
      check_close (b.approach_weight, expected, 1e-14, "approach weight" + at);
      check_close (b.pressure, expected * a.pressure, 1e-12, "approach-only P_wet" + at);
      check (std::abs (b.restitution - a.restitution) == 0.0, "approach-only e_wet" + at);
      if (divergence <= 0)
        check (b.viscosity == a.viscosity, "approach-only mu_wet" + at);
      else
        check (b.viscosity < a.viscosity, "approach-only mu_wet lower" + at);
    }
    check_close (approach_weight (eps, eps), 0.5, 1e-15, "approach weight 1/2 at eps");
  }

  // both ends of the window, smoothed (width 0.05): the weight is exactly 1/2 there and
  // P_wet half the bridged value; sharp: just inside (1 + 1e-6 from the end) the weight
  // is 1, just outside 0
  const double theta = 1e-3;
  for (const double width : {0.05, 0.0})
  {
    liquid.switch_width = width;
    const WetParticles wet (liquid, glass, "Lian", "bridge-gated");
    for (const double end : {lian, liquid.asperity})
      for (const double side :
           (width > 0 ? std::vector<double>{0.0} : std::vector<double>{-1e-6, 1e-6}))
      {
        const bool        upper  = end == lian;
        const double      h      = end * (1 + side);
        const double      alpha  = fraction_at_gap (h, d);
        const WetClosures w      = wet.evaluate (alpha, theta, 1.0, 0.0);
        const double      bridge = bridge_pressure (
            alpha, h, approach_velocity (theta, 1.5), liquid.liquid_viscosity, d);
        const bool        inside   = upper ? side < 0 : side > 0;
        const double      expected = width > 0 ? 0.5 : (inside ? 1.0 : 0.0);
        const std::string at =
            std::string (upper ? "h = h_c" : "h = h_a") +
            (width > 0 ? " (smoothed)"
                       : (inside ? " (sharp, inside)" : " (sharp, outside)"));
        check_close (w.gap, h, 1e-10, "gap at " + at);
        check (std::abs (w.window - expected) < 1e-9,
               "window weight at " + at + ": " + std::to_string (w.window));
        check (std::abs (w.pressure - expected * bridge) <= 1e-9 * bridge,
               "P_wet at " + at + ": " + std::to_string (w.pressure));
        // e = (1 - W) e_dry + W e_dry max(0, 1 - St*/St): at h_c St << St* (bridged
        // value 0), at h_a St* = 0 (bridged value e_dry; 0.89997 at h_a (1 + 1e-6))
        const double bridged = upper ? 0.0 : 0.9;
        check (std::abs (w.restitution - ((1 - expected) * 0.9 + expected * bridged)) <
                   1e-4,
               "e_wet at " + at + ": " + std::to_string (w.restitution));
      }
  }

  // a dry scene builds no wet closures
  {
    dealii::ParameterHandler prm;
    Parameters::declare_parameters (prm);
    prm.parse_input_from_string ("subsection solids stress\n set model = kinetic "
                                 "theory\nend\n");
    Parameters p;
    p.parse_parameters (prm);
    const auto stress =
        create_solids_stress_model (p.solids_stress, p.physical, p.kinetic_theory, p.wet);
    check (stress->kinetic_theory ()->wet () == nullptr,
           "dry scene (liquid loading 0): no wet closures");
    prm.enter_subsection ("wet particles");
    prm.set ("liquid loading", "0.001");
    prm.leave_subsection ();
    p.parse_parameters (prm);
    const auto wet_stress =
        create_solids_stress_model (p.solids_stress, p.physical, p.kinetic_theory, p.wet);
    check (wet_stress->kinetic_theory ()->wet () != nullptr,
           "wet scene (liquid loading 1e-3): wet closures built");
    // mu_wet enters mu_s, e_wet the dissipation only
    const auto dry_c = stress->kinetic_theory ()->evaluate (0.45, 1e-3);
    const auto wet_c = wet_stress->kinetic_theory ()->evaluate (0.45, 1e-3);
    check (wet_c.restitution < 1e-3 && dry_c.restitution == 0.9 &&
               wet_c.dissipation_factor > dry_c.dissipation_factor &&
               wet_c.shear_viscosity == dry_c.shear_viscosity &&
               wet_c.conductivity == dry_c.conductivity,
           "e_wet changes the dissipation only");
    const double mu_dry = stress->evaluate ({0.45, 1e-3, 2.0}).shear_viscosity;
    const double mu_wet = wet_stress->evaluate ({0.45, 1e-3, 2.0}).shear_viscosity;
    check (mu_wet - mu_dry > 500,
           "mu_wet enters mu_s: " + std::to_string (mu_wet - mu_dry));
  }

  // Sacado derivatives
  liquid.switch_width = 0.05;
  check_derivative ([&] (const ADNumber &a) { return woodcock_gap (a, d); }, 0.45, "gap");
  check_derivative (
      [&] (const ADNumber &t) { return approach_velocity (t, 1.5); }, 1e-3, "u_dot");
  check_derivative (
      [&] (const ADNumber &u) { return stokes_number (u, glass, 0.4945); }, 0.1, "St");
  check_derivative ([&] (const ADNumber &h)
                    { return critical_stokes_number (h, 2.8e-6, 0.9); },
                    1.2e-5,
                    "St*");
  check_derivative (
      [&] (const ADNumber &a)
      { return bridge_pressure (a, woodcock_gap (a, d), ADNumber (0.084), 0.4945, d); },
      0.45,
      "P_wet (alpha_s)");
  check_derivative ([&] (const ADNumber &i)
                    { return wet_viscosity (ADNumber (3700.0), i, 0.5236, 1e-3, 1e9); },
                    4.0,
                    "mu_wet (I_2D)");
  check_derivative ([&] (const ADNumber &u)
                    { return PitoisRuptureDistance::value (u, liquid, glass); },
                    0.1,
                    "h_c Pitois");
  const WetParticles gated (liquid, glass, "Lian", "bridge-gated"),
      literal (liquid, glass, "Lian", "literal"),
      gollwitzer (liquid, glass, "Lian", "Gollwitzer");
  for (const WetParticles *w : {&gated, &literal, &gollwitzer})
  {
    check_derivative (
        [&] (const ADNumber &t) {
          return w->restitution_law ().value (
              w->contact (ADNumber (0.45), t), liquid, glass);
        },
        50.0,
        w->restitution_law ().name () + " e_wet (Theta)");
    // across the smoothed upper end of the window
    check_derivative (
        [&] (const ADNumber &a) {
          return w->restitution_law ().value (
              w->contact (a, ADNumber (50.0)), liquid, glass);
        },
        fraction_at_gap (lian, d),
        w->restitution_law ().name () + " e_wet (alpha_s) at h = h_c");
  }
  return testing::finish ("closures_wet");
}
