// Issue 29 (item 1): every closure law is one template for double, ADNumber and
// dealii::VectorizedArray<double>. Each law is evaluated on VectorizedArray inputs whose
// states straddle every branch of the law (alpha_g on both sides of 0.8 and 0.85,
// Re on both sides of 1000, alpha_s below and above the frictional onset and the
// continuation point, zero and nonzero slip, Theta zero and positive, the wet gap below
// and above h_a and h_c, ...) and compared lane by lane with the double evaluation
// (rel. 1e-14, absolute near 0); the ADNumber value is compared too.
//
// The registries are iterated through their law lists (drag/drag_laws.h,
// kinetic_theory/kinetic_theory_laws.h, wet/wet_laws.h), which the registries are built
// from: a newly registered law is instantiated here for VectorizedArray (a scalar `if`
// on the state does not compile for it) and checked lane by lane, and a registered
// name missing from its list is reported.
//
// VectorizedArray<double> has as many lanes as the build's SIMD width (8 with AVX-512
// and WETBED_SIMD, 1 without: doc/developer_guide.md, "SIMD width"); the states are
// packed VectorizedArray::size() at a time, ordered so that neighbouring lanes sit on
// different branches.
#include "test_utilities.h"

#include <wetbed/closures/drag/drag_laws.h>
#include <wetbed/closures/frictional/johnson_jackson_pressure.h>
#include <wetbed/closures/frictional/schaeffer_viscosity.h>
#include <wetbed/closures/kinetic_theory/algebraic_granular_temperature.h>
#include <wetbed/closures/kinetic_theory/collisional_terms.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory_laws.h>
#include <wetbed/closures/number_traits.h>
#include <wetbed/closures/walls/johnson_jackson_wall.h>
#include <wetbed/closures/wet/liquid_bridge.h>
#include <wetbed/closures/wet/wet_laws.h>

#include <deal.II/base/vectorization.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

using namespace wetbed;
using namespace wetbed::closures;

namespace
{
using Vector                   = dealii::VectorizedArray<double>;
constexpr std::size_t n_lanes  = Vector::size ();
unsigned int          n_vector = 0, n_ad = 0, n_registry = 0;

static_assert (NumberTraits<Vector>::is_vectorized &&
                   NumberTraits<Vector>::n_lanes == n_lanes,
               "number traits of VectorizedArray");
static_assert (!is_vectorized_v<double> && !is_vectorized_v<ADNumber>,
               "number traits of the scalars");

/** value vs reference: rel. 1e-14, or both (nearly) zero, or the same infinity. */
void compare (const double value, const double reference, const std::string &what)
{
  if (std::isinf (reference))
    testing::check (value == reference,
                    what + ": " + std::to_string (value) + " vs " +
                        std::to_string (reference));
  else if (std::abs (reference) < 1e-300)
    testing::check (std::abs (value) < 1e-300,
                    what + ": " + std::to_string (value) + " vs 0");
  else
    testing::check_close (value, reference, 1e-14, what);
}

template <std::size_t k>
std::string to_string (const std::array<double, k> &state)
{
  std::ostringstream out;
  out << std::setprecision (17) << "(";
  for (std::size_t i = 0; i < k; ++i)
    out << (i > 0 ? ", " : "") << state[i];
  out << ")";
  return out.str ();
}

/** The cartesian product of the values of each argument, in an order that puts
 * neighbouring states (neighbouring lanes) on different values of every argument. */
template <std::size_t k>
std::vector<std::array<double, k>>
product (const std::array<std::vector<double>, k> &values)
{
  std::vector<std::array<double, k>> states (1);
  for (std::size_t i = 0; i < k; ++i)
  {
    std::vector<std::array<double, k>> next;
    for (const auto &state : states)
      for (const double v : values[i])
      {
        auto s = state;
        s[i]   = v;
        next.push_back (s);
      }
    states = next;
  }
  // a stride coprime to the size mixes the states across the packs
  const std::size_t n      = states.size ();
  std::size_t       stride = 7;
  while (std::gcd (stride, n) != 1)
    ++stride;
  std::vector<std::array<double, k>> mixed (n);
  for (std::size_t i = 0; i < n; ++i)
    mixed[i] = states[(i * stride) % n];
  return mixed;
}

/**
 * Evaluates f (a generic callable of k numbers of one type, returning that type) on
 * the states packed into VectorizedArrays and compares every lane with f on doubles;
 * f on ADNumbers (value only) too.
 */
template <std::size_t k, class Function>
void check_lanes (const std::string                        &what,
                  const std::vector<std::array<double, k>> &states,
                  const Function                           &f)
{
  for (std::size_t start = 0; start < states.size (); start += n_lanes)
  {
    std::array<Vector, k> packed;
    for (std::size_t lane = 0; lane < n_lanes; ++lane)
    {
      // a last, partial pack repeats the last state
      const auto &s = states[std::min (start + lane, states.size () - 1)];
      for (std::size_t i = 0; i < k; ++i)
        packed[i][lane] = s[i];
    }
    static_assert (std::is_same_v<decltype (std::apply (f, packed)), Vector>,
                   "a law returns its number type");
    const Vector vector = std::apply (f, packed);
    for (std::size_t lane = 0; lane < n_lanes && start + lane < states.size (); ++lane)
    {
      const auto  &s      = states[start + lane];
      const double scalar = std::apply (f, s);
      compare (vector[lane],
               scalar,
               what + " lane " + std::to_string (lane) + " at " + to_string (s));
      ++n_vector;
      std::array<ADNumber, k> ad;
      for (std::size_t i = 0; i < k; ++i)
        ad[i] = ADNumber (s[i]);
      const ADNumber ad_value = std::apply (f, ad);
      compare (ad_value.val (), scalar, what + " ADNumber at " + to_string (s));
      ++n_ad;
    }
  }
}

/** The names of a law list against the names a registry reports. */
template <class List>
void check_registry (const List, const std::string &registered, const std::string &what)
{
  std::set<std::string> listed;
  for_each_law (List{}, [&] (auto tag) { listed.insert (decltype (tag)::type::name); });
  std::set<std::string> names;
  std::stringstream     in (registered);
  for (std::string name; std::getline (in, name, '|');)
    names.insert (name);
  std::string joined;
  for (const auto &name : listed)
    joined += (joined.empty () ? "" : "|") + name;
  testing::check (listed == names && List::size == names.size (),
                  what + ": registered '" + registered + "' but the law list has '" +
                      joined + "' (register laws through the list)");
  ++n_registry;
}

/** Solids fraction at which the Woodcock gap equals h. */
double fraction_at_gap (const double h, const double d)
{
  const double s = h / d + 1.0;
  return 1.0 / (3.0 * M_PI * (s * s - 5.0 / 6.0));
}
} // namespace

int main ()
{
  // the helpers of number_traits.h, at a == b too
  const auto pairs = product<2> ({{{-1.0, 0.0, 0.5, 2.0}, {-1.0, 0.0, 0.5, 2.0}}});
  check_lanes ("select_less",
               pairs,
               [] (const auto &a, const auto &b)
               { return select_less (a, b, a, b - 1.0); });
  check_lanes ("select_less_equal",
               pairs,
               [] (const auto &a, const auto &b)
               { return select_less_equal (a, b, a, b - 1.0); });
  check_lanes ("select_greater",
               pairs,
               [] (const auto &a, const auto &b)
               { return select_greater (a, b, a, b - 1.0); });
  check_lanes ("select_greater_equal",
               pairs,
               [] (const auto &a, const auto &b)
               { return select_greater_equal (a, b, a, b - 1.0); });
  check_lanes (
      "math::max", pairs, [] (const auto &a, const auto &b) { return math::max (a, b); });
  check_lanes (
      "math::min", pairs, [] (const auto &a, const auto &b) { return math::min (a, b); });
  const auto positive = product<1> ({{{0.0, 1e-3, 0.5, 2.0, 1e3}}});
  check_lanes ("math::pow", positive, [] (const auto &x) { return math::pow (x, 1.7); });
  check_lanes ("math::sqrt", positive, [] (const auto &x) { return math::sqrt (x); });
  check_lanes ("math::cbrt", positive, [] (const auto &x) { return math::cbrt (x); });
  check_lanes ("math::log",
               product<1> ({{{1e-3, 0.5, 2.0, 1e3}}}),
               [] (const auto &x) { return math::log (x); });
  const auto reals = product<1> ({{{-3.0, -1e-3, 0.0, 0.5, 2.0}}});
  check_lanes ("math::exp", reals, [] (const auto &x) { return math::exp (x); });
  check_lanes ("math::tanh", reals, [] (const auto &x) { return math::tanh (x); });
  check_lanes ("math::abs", reals, [] (const auto &x) { return math::abs (x); });

  // drag: alpha_g on both sides of 0.85 (Syamlal-O'Brien) and 0.8 (Gidaspow), the
  // Wen-Yu Reynolds number (alpha_g rho d |du| / mu = 23.3 alpha_g |du|) on both sides
  // of 1000, zero and nonzero slip
  const GasParticleProperties air_glass{1.2, 1.8e-5, 350e-6};
  const auto                  drag_states = product<2> (
      {{{1e-4, 0.05, 0.1, 0.149, 0.15, 0.151, 0.19, 0.2, 0.21, 0.3, 0.45, 0.58, 0.63},
                         {0.0, 0.3, 3.0, 40.0, 45.0, 50.0, 60.0, 200.0}}});
  check_registry (DragLaws{}, drag_model_names (), "drag");
  for_each_law (DragLaws{},
                [&] (auto tag)
                {
                  using Law = typename decltype (tag)::type;
                  check_lanes (std::string ("drag ") + Law::name,
                               drag_states,
                               [&] (const auto &alpha_s, const auto &slip)
                               { return Law::beta (alpha_s, slip, air_glass); });
                  // the registered model is the listed law
                  compare (
                      create_drag_model (Law::name)->coefficient (0.3, 1.0, air_glass),
                      Law::beta (0.3, 1.0, air_glass),
                      std::string ("registered drag ") + Law::name);
                });
  check_lanes ("Gidaspow Ergun part",
               drag_states,
               [&] (const auto &alpha_s, const auto &slip)
               { return Gidaspow::ergun (alpha_s, slip, air_glass); });
  check_lanes (
      "Syamlal-O'Brien v_r",
      product<2> ({{{0.3, 0.8, 0.849, 0.85, 0.851, 0.95, 1.0}, {0.0, 1.0, 100.0, 1e4}}}),
      [] (const auto &alpha_g, const auto &reynolds)
      { return SyamlalOBrien::terminal_velocity_ratio (alpha_g, reynolds); });

  // kinetic theory: alpha_s from 0 to near packing, Theta zero and positive
  const GranularMaterial glass{2500.0, 350e-6, 0.9, 0.63};
  const double           alpha_max = glass.maximum_packing;
  check_registry (
      RadialDistributionLaws{}, radial_distribution_names (), "radial distribution");
  const auto fractions = product<1> ({{{0.0, 1e-3, 0.1, 0.3, 0.5, 0.55, 0.6}}});
  for_each_law (RadialDistributionLaws{},
                [&] (auto tag)
                {
                  using Law = typename decltype (tag)::type;
                  check_lanes (std::string ("g0 ") + Law::name,
                               fractions,
                               [&] (const auto &alpha)
                               { return Law::value (alpha, alpha_max); });
                  compare (create_radial_distribution (Law::name)->value (0.3, alpha_max),
                           Law::value (0.3, alpha_max),
                           std::string ("registered g0 ") + Law::name);
                });
  // (alpha, Theta, g0) with g0 = Carnahan-Starling(alpha)
  std::vector<std::array<double, 3>> kinetic_states;
  for (const auto &s : product<2> ({{{0.0, 0.05, 0.3, 0.55}, {0.0, 1e-6, 1e-3, 0.5}}}))
    kinetic_states.push_back (
        {{s[0], s[1], CarnahanStarlingRadialDistribution::value (s[0], alpha_max)}});
  const auto check_coefficients = [&] (const auto list, const std::string &kind)
  {
    for_each_law (list,
                  [&] (auto tag)
                  {
                    using Law = typename decltype (tag)::type;
                    check_lanes (
                        kind + " " + Law::name,
                        kinetic_states,
                        [&] (const auto &alpha, const auto &theta, const auto &g0)
                        { return Law::value (alpha, theta, g0, glass); });
                  });
  };
  check_registry (
      KineticViscosityLaws{}, kinetic_viscosity_names (), "kinetic viscosity");
  check_coefficients (KineticViscosityLaws{}, "mu_kin");
  check_registry (GranularConductivityLaws{},
                  granular_conductivity_names (),
                  "granular conductivity");
  check_coefficients (GranularConductivityLaws{}, "kappa");
  for_each_law (KineticViscosityLaws{},
                [&] (auto tag)
                {
                  using Law = typename decltype (tag)::type;
                  compare (
                      create_kinetic_viscosity (Law::name)->value (0.3, 0.01, 2.0, glass),
                      Law::value (0.3, 0.01, 2.0, glass),
                      std::string ("registered mu_kin ") + Law::name);
                });
  for_each_law (
      GranularConductivityLaws{},
      [&] (auto tag)
      {
        using Law = typename decltype (tag)::type;
        compare (create_granular_conductivity (Law::name)->value (0.3, 0.01, 2.0, glass),
                 Law::value (0.3, 0.01, 2.0, glass),
                 std::string ("registered kappa ") + Law::name);
      });
  check_lanes ("P_s (Lun)",
               kinetic_states,
               [&] (const auto &alpha, const auto &theta, const auto &g0)
               { return CollisionalTerms::solids_pressure (alpha, theta, g0, glass); });
  check_lanes ("mu_col",
               kinetic_states,
               [&] (const auto &alpha, const auto &theta, const auto &g0)
               { return CollisionalTerms::shear_viscosity (alpha, theta, g0, glass); });
  check_lanes ("lambda_s",
               kinetic_states,
               [&] (const auto &alpha, const auto &theta, const auto &g0)
               { return CollisionalTerms::bulk_viscosity (alpha, theta, g0, glass); });
  for (const double e : {0.9, 0.3})
    check_lanes ("gamma, e = " + std::to_string (e),
                 kinetic_states,
                 [&] (const auto &alpha, const auto &theta, const auto &g0)
                 { return CollisionalTerms::dissipation (alpha, theta, g0, glass, e); });

  // algebraic Theta: a = 0 (no solids) and a > 0, c = 0 (no shear), c < 0 and c > 0,
  // b < 0 (compression, tr D < 0) and b >= 0
  std::vector<std::array<double, 5>> equilibrium_states;
  for (const auto &s :
       product<4> ({{{0.0, 0.3, 0.55}, {-50.0, 0.0, 0.5}, {0.0, 0.5, 10.0}, {0.0, 1e3}}}))
    equilibrium_states.push_back (
        {{s[0],
          CarnahanStarlingRadialDistribution::value (s[0], alpha_max),
          s[1],
          s[2],
          s[3]}});
  for (const AlgebraicGranularTemperature &law :
       {AlgebraicGranularTemperature{}, AlgebraicGranularTemperature{false, 1.85}})
    check_lanes (std::string ("Theta_alg ") +
                     (law.kinetic_pressure ? "OpenFOAM" : "MFIX"),
                 equilibrium_states,
                 [&] (const auto &alpha,
                      const auto &g0,
                      const auto &trace_d,
                      const auto &d_ddot_d,
                      const auto &beta)
                 { return law.value (alpha, g0, trace_d, d_ddot_d, beta, glass); });

  // Johnson-Jackson pressure and derivative: below/at/above the onset, below/above the
  // continuation point alpha_c and alpha_max; also without a continuation (alpha_c below
  // the onset) and with a non-integer n (the power law is NaN below the onset, where
  // it is not chosen)
  const auto packing = product<1> ({{{0.2,
                                      0.5,
                                      0.55,
                                      0.58,
                                      0.585,
                                      0.6,
                                      0.608,
                                      0.609,
                                      0.6095,
                                      0.61,
                                      0.62,
                                      0.625,
                                      0.629,
                                      0.63,
                                      0.64}}});
  for (const JohnsonJacksonPressureCoefficients &jj :
       {JohnsonJacksonPressureCoefficients{0.05, 2.0, 3.0, 0.58, 0.61, 0.001},
        JohnsonJacksonPressureCoefficients{0.05, 2.5, 3.5, 0.5, 0.61, 0.2},
        JohnsonJacksonPressureCoefficients{0.1, 2.5, 5.0, 0.5, 0.63, 0.002}})
  {
    const std::string with = " (onset " + std::to_string (jj.onset) + ", delta_min " +
                             std::to_string (jj.minimum_distance) + ")";
    check_lanes ("P_fr" + with,
                 packing,
                 [&] (const auto &alpha)
                 { return johnson_jackson_pressure (alpha, jj); });
    check_lanes ("P_fr'" + with,
                 packing,
                 [&] (const auto &alpha)
                 { return johnson_jackson_pressure_derivative (alpha, jj); });
  }

  // Schaeffer: below and above the cap (100 Pa s), no strain rate
  check_lanes ("mu_fr Schaeffer",
               product<2> ({{{0.0, 10.0, 1e3, 1e5, 1e7}, {0.0, 1e-4, 0.25, 100.0}}}),
               [] (const auto &pressure, const auto &i2d)
               { return schaeffer_viscosity (pressure, i2d, M_PI / 6, 1e-3, 100.0); });

  // Johnson-Jackson wall: Theta and slip zero and positive
  const JohnsonJacksonWall           wall{0.5, 0.9, alpha_max, glass.particle_density};
  std::vector<std::array<double, 4>> wall_states;
  for (const auto &s :
       product<3> ({{{0.0, 0.3, 0.6}, {0.0, 1e-3, 0.5}, {0.0, 0.2, 1.5}}}))
    wall_states.push_back ({{s[0],
                             CarnahanStarlingRadialDistribution::value (s[0], alpha_max),
                             s[1],
                             s[2]}});
  check_lanes ("C_JJ",
               wall_states,
               [&] (const auto &alpha, const auto &g0, const auto &theta, const auto &)
               { return wall.shear_coefficient (alpha, g0, theta); });
  check_lanes (
      "G_w",
      wall_states,
      [&] (const auto &alpha, const auto &g0, const auto &theta, const auto &slip)
      { return wall.energy_generation (alpha, g0, theta, slip); });
  check_lanes ("D_w",
               wall_states,
               [&] (const auto &alpha, const auto &g0, const auto &theta, const auto &)
               { return wall.energy_dissipation (alpha, g0, theta); });

  // wet closures (seed-000 oil, tests/closures_wet.cc)
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
  const WetParticleMaterial oil_glass{2500.0, 350e-6, 0.9};
  const double              d        = oil_glass.particle_diameter;
  const double              asperity = liquid.asperity;
  const double              lian =
      LianRuptureDistance::value (0.0, liquid, oil_glass); // h_c ~ 2.6e-5 m
  check_registry (RuptureDistanceLaws{}, rupture_distance_names (), "rupture distance");
  const auto approach = product<1> ({{{0.0, 1e-4, 0.08, 2.0}}});
  for_each_law (
      RuptureDistanceLaws{},
      [&] (auto tag)
      {
        using Law = typename decltype (tag)::type;
        check_lanes (std::string ("h_c ") + Law::name,
                     approach,
                     [&] (const auto &u_dot)
                     { return Law::value (u_dot, liquid, oil_glass); });
        compare (create_rupture_distance (Law::name)->value (0.08, liquid, oil_glass),
                 Law::value (0.08, liquid, oil_glass),
                 std::string ("registered h_c ") + Law::name);
      });
  check_registry (WetRestitutionLaws{}, wet_restitution_names (), "wet restitution");
  // alpha_s: none (floored), the gap above/below h_c (both laws' h_c are close to
  // Lian's) and above/below h_a, Woodcock's packing (gap 0) and above (floored);
  // Theta: zero (floored), St below and above St* (St ~ 0.8 u_dot, St* ~ 5 near h_c)
  const auto wet_states = product<2> ({{{0.0,
                                         1e-13,
                                         0.05,
                                         0.2,
                                         fraction_at_gap (1.2 * lian, d),
                                         fraction_at_gap (0.8 * lian, d),
                                         0.45,
                                         fraction_at_gap (1.1 * asperity, d),
                                         fraction_at_gap (0.9 * asperity, d),
                                         0.58,
                                         0.6,
                                         0.62},
                                        {0.0, 1e-15, 1e-6, 1e-3, 50.0, 1e4}}});
  for (const double width : {0.05, 0.0})
    for (const double film : {0.1, -0.5}) // -0.5: Gollwitzer's clip at e_dry
    {
      liquid.switch_width    = width;
      liquid.film_thickness  = film;
      const std::string with = " (switch width " + std::to_string (width) + ", film " +
                               std::to_string (film) + ")";
      for_each_law (
          RuptureDistanceLaws{},
          [&] (auto rupture_tag)
          {
            using Rupture      = typename decltype (rupture_tag)::type;
            const auto contact = [&] (const auto &alpha_s, const auto &theta)
            {
              using Number = std::decay_t<decltype (alpha_s)>;
              return wet_contact (alpha_s,
                                  theta,
                                  liquid,
                                  oil_glass,
                                  [&] (const Number &u_dot)
                                  { return Rupture::value (u_dot, liquid, oil_glass); });
            };
            const std::string at = std::string (" with h_c ") + Rupture::name + with;
            if (film > 0)
            {
              check_lanes ("contact gap" + at,
                           wet_states,
                           [&] (const auto &a, const auto &t)
                           { return contact (a, t).gap; });
              check_lanes ("contact h_c" + at,
                           wet_states,
                           [&] (const auto &a, const auto &t)
                           { return contact (a, t).rupture_distance; });
              check_lanes ("contact h > h_a" + at,
                           wet_states,
                           [&] (const auto &a, const auto &t)
                           { return contact (a, t).above_asperity; });
              check_lanes ("contact h <= h_c" + at,
                           wet_states,
                           [&] (const auto &a, const auto &t)
                           { return contact (a, t).bridged; });
              check_lanes ("contact St" + at,
                           wet_states,
                           [&] (const auto &a, const auto &t)
                           { return contact (a, t).stokes; });
              check_lanes ("contact St*" + at,
                           wet_states,
                           [&] (const auto &a, const auto &t)
                           { return contact (a, t).critical_stokes; });
            }
            for_each_law (
                WetRestitutionLaws{},
                [&] (auto restitution_tag)
                {
                  using Restitution = typename decltype (restitution_tag)::type;
                  check_lanes (
                      std::string ("e_wet ") + Restitution::name + at,
                      wet_states,
                      [&] (const auto &a, const auto &t)
                      { return Restitution::value (contact (a, t), liquid, oil_glass); });
                  compare (create_wet_restitution (Restitution::name)
                               ->value (contact (0.45, 50.0), liquid, oil_glass),
                           Restitution::value (contact (0.45, 50.0), liquid, oil_glass),
                           std::string ("registered e_wet ") + Restitution::name + at);
                });
          });
    }
  liquid.switch_width   = 0.0;
  liquid.film_thickness = 0.1;

  // the single-form liquid-bridge laws
  check_lanes ("Woodcock gap",
               fractions,
               [&] (const auto &alpha_s) { return woodcock_gap (alpha_s, d); });
  check_lanes ("u_dot",
               product<1> ({{{0.0, 1e-6, 1e-3, 50.0}}}),
               [] (const auto &theta) { return approach_velocity (theta, 1.5); });
  check_lanes ("St",
               approach,
               [&] (const auto &u_dot)
               { return stokes_number (u_dot, oil_glass, liquid.liquid_viscosity); });
  check_lanes (
      "St*",
      product<1> ({{{0.01 * asperity, 0.9 * asperity, asperity, 10 * asperity}}}),
      [&] (const auto &h)
      { return critical_stokes_number (h, asperity, oil_glass.dry_restitution); });
  for (const double width : {0.05, 0.0})
    check_lanes ("smooth step, width " + std::to_string (width),
                 product<1> ({{{-1.0, -1e-3, -1e-300, 0.0, 1e-300, 1e-3, 1.0}}}),
                 [&] (const auto &x) { return smooth_step (x, width); });
  check_lanes ("P_wet (bridge)",
               product<3> ({{{1e-3, 0.2, 0.45}, {0.9 * asperity, lian}, {0.0, 0.08}}}),
               [&] (const auto &alpha_s, const auto &h, const auto &u_dot) {
                 return bridge_pressure (alpha_s, h, u_dot, liquid.liquid_viscosity, d);
               });
  check_lanes ("mu_wet",
               product<2> ({{{0.0, 10.0, 3700.0, 1e6}, {0.0, 0.25, 4.0, 1e4}}}),
               [&] (const auto &pressure, const auto &i2d)
               {
                 return wet_viscosity (pressure,
                                       i2d,
                                       liquid.stability_angle,
                                       liquid.strain_rate_regularisation,
                                       liquid.maximum_viscosity);
               });
  // bridged restitution: 1 - St*/St below 0, in (0, 1) and above 1 (St* < 0)
  check_lanes ("bridged restitution",
               product<2> ({{{1e-3, 1.0, 5.0, 50.0}, {-2.0, 0.0, 0.5, 4.0, 60.0}}}),
               [&] (const auto &stokes, const auto &critical_stokes)
               {
                 using Number = std::decay_t<decltype (stokes)>;
                 WetContact<Number> c;
                 c.gap = c.rupture_distance = c.above_asperity = c.bridged = Number (1.0);
                 c.stokes                                                  = stokes;
                 c.critical_stokes = critical_stokes;
                 return bridged_restitution (c, oil_glass.dry_restitution);
               });

  std::cout << "closures_vectorized: VectorizedArray<double> of " << n_lanes
            << " lane(s): " << n_vector << " lanes and " << n_ad
            << " ADNumber values compared with double, " << n_registry
            << " registries checked against their law lists" << std::endl;
  return testing::finish ("closures_vectorized");
}
