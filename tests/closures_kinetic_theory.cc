// T1 (kinetic theory): radial distributions, Lun pressure, viscosities, conductivities,
// dissipation, Johnson-Jackson wall terms, Schaeffer viscosity and the algebraic
// granular temperature against reference values of the closed-form laws of
// doc/theory.md ("Kinetic-theory closures", "Granular energy", "Johnson-Jackson walls"),
// evaluated independently in Python (350 um glass, rho_s = 2500, e = 0.9, alpha_max =
// 0.61, g0 Ogawa, specularity 0.5, e_w = 0.8, u_slip = 0.1 m/s; rel. 1e-12), and every
// Sacado derivative against a central finite difference.
#include "test_utilities.h"

#include <wetbed/closures/frictional/schaeffer_viscosity.h>
#include <wetbed/closures/kinetic_theory/algebraic_granular_temperature.h>
#include <wetbed/closures/kinetic_theory/collisional_terms.h>
#include <wetbed/closures/kinetic_theory/granular_conductivity.h>
#include <wetbed/closures/kinetic_theory/kinetic_viscosity.h>
#include <wetbed/closures/kinetic_theory/radial_distribution.h>
#include <wetbed/closures/walls/johnson_jackson_wall.h>

#include <array>
#include <functional>
#include <vector>

using namespace wetbed;
using namespace wetbed::closures;
using testing::check_close;
using testing::check_derivative;

int main ()
{
  const GranularMaterial glass{2500.0, 350e-6, 0.9, 0.61};
  // alpha, Theta | g0 Ogawa, Carnahan-Starling, Lun-Savage | P_s Lun | mu_col, mu_kin
  // Gidaspow, mu_kin Syamlal | lambda | kappa Gidaspow, Syamlal | gamma | C_JJ, G_w, D_w
  // | Theta_alg (simple shear 1/s with -3 beta Theta), Theta_alg MFIX variant (shear
  // 10/s, no drag) | beta Syamlal-O'Brien used in the first
  const std::vector<std::array<double, 19>> reference = {{0.1,
                                                          0.01,
                                                          2.208955745609145,
                                                          1.3031550068587103,
                                                          1.3139640401190922,
                                                          4.598507958328688,
                                                          0.0016575388635135606,
                                                          0.006867977068411494,
                                                          0.0015821576448078552,
                                                          0.0027625647725226013,
                                                          0.036779420881339654,
                                                          0.012477515596766506,
                                                          202.96394247104823,
                                                          41.05125539966588,
                                                          0.41051255399665887,
                                                          0.4433535583163914,
                                                          1.9723774185937902e-10,
                                                          2.1116739143254255e-05,
                                                          767.9820743286377},
                                                         {0.3,
                                                          0.001,
                                                          4.7469731818784915,
                                                          2.4781341107871726,
                                                          2.8073813811220645,
                                                          4.808662070506109,
                                                          0.010137619631026286,
                                                          0.00567262991896428,
                                                          0.003316200999770352,
                                                          0.01689603271837714,
                                                          0.0636549866299925,
                                                          0.045170524967790525,
                                                          124.13411793093407,
                                                          83.6907501393902,
                                                          0.8369075013939022,
                                                          0.0903860101505414,
                                                          1.6056368193371936e-09,
                                                          1.1637712016238867e-05,
                                                          3486.7326022667335},
                                                         {0.5,
                                                          0.0001,
                                                          15.592206883458674,
                                                          6.0,
                                                          13.630260419153414,
                                                          3.828149134821435,
                                                          0.02924989435466195,
                                                          0.009004550593640904,
                                                          0.006814448479139895,
                                                          0.04874982392443658,
                                                          0.14521009815228203,
                                                          0.11684643832388242,
                                                          35.81619716897382,
                                                          144.88286338230395,
                                                          1.4488286338230398,
                                                          0.01564734924528883,
                                                          1.6540161974499924e-08,
                                                          1.021533992605425e-05,
                                                          7811.892034674487},
                                                         {0.58,
                                                          1e-05,
                                                          59.98879367142228,
                                                          9.583198358708561,
                                                          98.8594260962936,
                                                          1.9316218681513129,
                                                          0.04788536702001655,
                                                          0.013014930777691674,
                                                          0.010374238309537832,
                                                          0.0798089450333609,
                                                          0.22817251096575725,
                                                          0.18746287404010298,
                                                          5.863514328981618,
                                                          204.47374435431894,
                                                          2.0447374435431898,
                                                          0.0022083164390266446,
                                                          5.785488060474821e-08,
                                                          9.968680070023421e-06,
                                                          10665.065577186839},
                                                         {0.45,
                                                          0.002,
                                                          10.370013071243127,
                                                          4.658151765589781,
                                                          7.69741718021125,
                                                          42.14862529160793,
                                                          0.07046866334000645,
                                                          0.02401720559460719,
                                                          0.01741170335454885,
                                                          0.11744777223334407,
                                                          0.36246774067048626,
                                                          0.286374549969415,
                                                          1725.7631838368918,
                                                          387.8343247492207,
                                                          3.8783432474922077,
                                                          0.8377221414583166,
                                                          8.420445446382325e-09,
                                                          1.042853216063432e-05,
                                                          6548.012246112105}};

  const auto               ogawa       = create_radial_distribution ("Ogawa");
  const auto               carnahan    = create_radial_distribution ("Carnahan-Starling");
  const auto               lun_savage  = create_radial_distribution ("Lun-Savage");
  const auto               mu_gidaspow = create_kinetic_viscosity ("Gidaspow");
  const auto               mu_syamlal  = create_kinetic_viscosity ("Syamlal");
  const auto               k_gidaspow  = create_granular_conductivity ("Gidaspow");
  const auto               k_syamlal   = create_granular_conductivity ("Syamlal");
  const JohnsonJacksonWall wall{0.5, 0.8, 0.61, 2500.0};
  const AlgebraicGranularTemperature equilibrium;
  const AlgebraicGranularTemperature mfix_variant{false, 0.5 * (3 * 0.9 + 1)};

  for (const auto &r : reference)
  {
    const double      a = r[0], theta = r[1], g0 = r[2];
    const std::string at = " at alpha=" + std::to_string (a);
    check_close (ogawa->value (a, 0.61), r[2], 1e-12, "g0 Ogawa" + at);
    check_close (carnahan->value (a, 0.61), r[3], 1e-12, "g0 Carnahan-Starling" + at);
    check_close (lun_savage->value (a, 0.61), r[4], 1e-12, "g0 Lun-Savage" + at);
    check_close (CollisionalTerms::solids_pressure (a, theta, g0, glass),
                 r[5],
                 1e-12,
                 "P_s Lun" + at);
    check_close (CollisionalTerms::shear_viscosity (a, theta, g0, glass),
                 r[6],
                 1e-12,
                 "mu_col" + at);
    check_close (
        mu_gidaspow->value (a, theta, g0, glass), r[7], 1e-12, "mu_kin Gidaspow" + at);
    check_close (
        mu_syamlal->value (a, theta, g0, glass), r[8], 1e-12, "mu_kin Syamlal" + at);
    check_close (CollisionalTerms::bulk_viscosity (a, theta, g0, glass),
                 r[9],
                 1e-12,
                 "lambda Lun" + at);
    check_close (
        k_gidaspow->value (a, theta, g0, glass), r[10], 1e-12, "kappa Gidaspow" + at);
    check_close (
        k_syamlal->value (a, theta, g0, glass), r[11], 1e-12, "kappa Syamlal" + at);
    check_close (CollisionalTerms::dissipation (a, theta, g0, glass, 0.9),
                 r[12],
                 1e-12,
                 "gamma" + at);
    check_close (wall.shear_coefficient (a, g0, theta), r[13], 1e-12, "C_JJ" + at);
    check_close (wall.energy_generation (a, g0, theta, 0.1), r[14], 1e-12, "G_w" + at);
    check_close (wall.energy_dissipation (a, g0, theta), r[15], 1e-12, "D_w" + at);
    check_close (equilibrium.value (a, g0, 0.0, 0.5, r[18], glass),
                 r[16],
                 1e-12,
                 "Theta_alg" + at);
    check_close (mfix_variant.value (a, g0, 0.0, 50.0, 0.0, glass),
                 r[17],
                 1e-12,
                 "Theta_alg MFIX" + at);

    // derivatives with respect to alpha_s (g0 follows alpha through Ogawa) and Theta
    const auto g0_of = [&] (const ADNumber &x) { return ogawa->value (x, 0.61); };
    check_derivative (g0_of, a, "dg0/dalpha Ogawa" + at);
    check_derivative ([&] (const ADNumber &x) { return carnahan->value (x, 0.61); },
                      a,
                      "dg0/dalpha CS" + at);
    check_derivative ([&] (const ADNumber &x) { return lun_savage->value (x, 0.61); },
                      a,
                      "dg0/dalpha LS" + at);
    const ADNumber th (theta);
    check_derivative (
        [&] (const ADNumber &x)
        { return CollisionalTerms::solids_pressure (x, th, g0_of (x), glass); },
        a,
        "dP_s/dalpha" + at);
    check_derivative (
        [&] (const ADNumber &x) {
          return CollisionalTerms::solids_pressure (
              ADNumber (a), x, ADNumber (g0), glass);
        },
        theta,
        "dP_s/dTheta" + at);
    check_derivative ([&] (const ADNumber &x)
                      { return mu_gidaspow->value (x, th, g0_of (x), glass); },
                      a,
                      "dmu_kin Gidaspow/dalpha" + at);
    check_derivative (
        [&] (const ADNumber &x)
        { return mu_syamlal->value (ADNumber (a), x, ADNumber (g0), glass); },
        theta,
        "dmu_kin Syamlal/dTheta" + at);
    check_derivative ([&] (const ADNumber &x)
                      { return k_gidaspow->value (x, th, g0_of (x), glass); },
                      a,
                      "dkappa Gidaspow/dalpha" + at);
    check_derivative (
        [&] (const ADNumber &x)
        { return k_syamlal->value (ADNumber (a), x, ADNumber (g0), glass); },
        theta,
        "dkappa Syamlal/dTheta" + at);
    check_derivative (
        [&] (const ADNumber &x) {
          return CollisionalTerms::dissipation (
              ADNumber (a), x, ADNumber (g0), glass, 0.9);
        },
        theta,
        "dgamma/dTheta" + at);
    check_derivative (
        [&] (const ADNumber &x)
        { return wall.energy_dissipation (ADNumber (a), ADNumber (g0), x); },
        theta,
        "dD_w/dTheta" + at);
    check_derivative (
        [&] (const ADNumber &x)
        {
          return equilibrium.value (
              ADNumber (a), ADNumber (g0), ADNumber (0.0), x, ADNumber (r[18]), glass);
        },
        0.5,
        "dTheta_alg/d(D:D)" + at);
  }
  // hand values: Schaeffer in simple shear 1/s (sqrt(I_2D) = 1/2) with P_fr = 1000 Pa and
  // phi = 30 deg gives mu = 1000 sin(30)/(2 * 0.5) = 500 Pa s; the cap applies above it
  check_close (schaeffer_viscosity (1000.0, 0.25, M_PI / 6, 0.0, 1e3),
               500.0,
               1e-12,
               "Schaeffer mu");
  check_close (schaeffer_viscosity (1000.0, 0.25, M_PI / 6, 0.0, 100.0),
               100.0,
               1e-12,
               "Schaeffer cap");
  check_close (AlgebraicGranularTemperature{}.value (0.3, 4.7, 0.0, 0.0, 0.0, glass) +
                   1.0,
               1.0,
               0.0,
               "no shear, no Theta");
  return testing::finish ("closures_kinetic_theory");
}
