// T1 (core part): drag laws and the Johnson-Jackson frictional pressure against
// reference values of the closed-form laws of doc/theory.md ("Closures"), evaluated
// independently in Python (rel. 1e-12), and the Sacado derivatives against central
// finite differences.
#include "test_utilities.h"

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/frictional/johnson_jackson_pressure.h>

#include <array>
#include <vector>

using namespace wetbed;
using namespace wetbed::closures;
using testing::check_close;

int main ()
{
  const GasParticleProperties air_glass{1.2, 1.8e-5, 350e-6};
  // alpha_s, slip, Syamlal-O'Brien, Gidaspow, Wen-Yu (Python reference values)
  const std::vector<std::array<double, 5>> drag_reference = {{0.050000000000000003,
                                                              0.29999999999999999,
                                                              277.0862201814827,
                                                              235.01775538476619,
                                                              235.01775538476619},
                                                             {0.20000000000000001,
                                                              0.5,
                                                              2083.9685190380496,
                                                              1702.0408163265306,
                                                              1620.4444607756548},
                                                             {0.34999999999999998,
                                                              1.2,
                                                              6258.5404001245561,
                                                              6673.8461538461524,
                                                              6090.7176306429647},
                                                             {0.45000000000000001,
                                                              0.80000000000000004,
                                                              8268.1905847061262,
                                                              10275.027829313543,
                                                              10114.357360655027},
                                                             {0.57999999999999996,
                                                              0.20000000000000001,
                                                              10085.04126031486,
                                                              18349.644314868801,
                                                              18923.589508766468},
                                                             {0.14999999999999999,
                                                              3,
                                                              2908.2198974158814,
                                                              2126.3834133790351,
                                                              2126.3834133790351},
                                                             {0.10000000000000001,
                                                              40,
                                                              9543.5714944021347,
                                                              5704.4041724682038,
                                                              5704.4041724682038}};
  const std::array<std::string, 3> names = {"Syamlal-O'Brien", "Gidaspow", "Wen-Yu"};
  for (unsigned int m = 0; m < 3; ++m)
  {
    const auto model = create_drag_model (names[m]);
    testing::check (model->name () == names[m], "registry name " + names[m]);
    for (const auto &row : drag_reference)
    {
      const double alpha = row[0], slip = row[1];
      check_close (model->coefficient (alpha, slip, air_glass),
                   row[2 + m],
                   1e-12,
                   names[m] + " beta at alpha=" + std::to_string (alpha));
      // Sacado derivatives vs central differences
      const ADNumber a (2, 0, alpha), s (2, 1, slip);
      const ADNumber beta = model->coefficient (a, s, air_glass);
      check_close (beta.val (), row[2 + m], 1e-12, names[m] + " AD value");
      const double ha = 1e-6 * alpha, hs = 1e-6 * slip;
      const double fd_alpha = (model->coefficient (alpha + ha, slip, air_glass) -
                               model->coefficient (alpha - ha, slip, air_glass)) /
                              (2 * ha);
      const double fd_slip = (model->coefficient (alpha, slip + hs, air_glass) -
                              model->coefficient (alpha, slip - hs, air_glass)) /
                             (2 * hs);
      // the laws switch branch at alpha_g = 0.85 (v_r) and 0.8 (Gidaspow): no
      // derivative there
      const bool at_switch =
          std::abs (alpha - 0.15) < 1e-9 || std::abs (alpha - 0.2) < 1e-9;
      if (!at_switch)
        check_close (beta.dx (0), fd_alpha, 1e-6, names[m] + " d beta/d alpha");
      check_close (beta.dx (1), fd_slip, 1e-6, names[m] + " d beta/d slip");
    }
    // finite and positive at zero slip (the Stokes limit)
    const double stokes = model->coefficient (0.3, 0.0, air_glass);
    testing::check (std::isfinite (stokes) && stokes > 0,
                    names[m] + " finite at zero slip");
  }
  // Wen-Yu Stokes limit by hand: 18 mu alpha alpha_g^-2.65 / d^2
  check_close (create_drag_model ("Wen-Yu")->coefficient (0.3, 0.0, air_glass),
               18 * 1.8e-5 * 0.3 * std::pow (0.7, -2.65) / (350e-6 * 350e-6),
               1e-13,
               "Wen-Yu Stokes limit");

  // Johnson-Jackson frictional pressure, seed-000 coefficients (Fr 0.05, n 2, p 3)
  const JohnsonJacksonPressureCoefficients jj{0.05, 2.0, 3.0, 0.58, 0.61, 0.001};
  const std::vector<std::array<double, 2>> friction_reference = {
      {0.55000000000000004, 0},
      {0.58499999999999996, 0.079999999999999946},
      {0.59999999999999998, 19.999999999999986},
      {0.60499999999999998, 249.99999999999977},
      // alpha > alpha_c = 0.609: tangent continuation, by hand
      // P(0.609) = 0.05 0.029^2 / 0.001^3 = 42050,
      // P'(0.609) = 0.05 (2 0.029 0.001 + 3 0.029^2) / 0.001^4 = 1.2905e8,
      // P(0.6095) = 42050 + 1.2905e8 * 0.0005 = 106575
      {0.60950000000000004, 106575.0}};
  for (const auto &row : friction_reference)
  {
    if (row[1] == 0)
      testing::check (johnson_jackson_pressure (row[0], jj) == 0, "P_fr = 0 below onset");
    else
      check_close (johnson_jackson_pressure (row[0], jj),
                   row[1],
                   1e-12,
                   "P_fr at " + std::to_string (row[0]));
    const double h  = 1e-7;
    const double fd = (johnson_jackson_pressure (row[0] + h, jj) -
                       johnson_jackson_pressure (row[0] - h, jj)) /
                      (2 * h);
    const double exact = johnson_jackson_pressure_derivative (row[0], jj);
    if (row[1] == 0)
      testing::check (exact == 0, "P_fr' = 0 below onset");
    else
      check_close (exact, fd, 1e-5, "P_fr' at " + std::to_string (row[0]));
    const ADNumber a (1, 0, row[0]);
    if (row[1] != 0)
      check_close (johnson_jackson_pressure (a, jj).dx (0), exact, 1e-12, "Sacado P_fr'");
  }
  // hand value: Fr (0.02)^2 / (0.01)^3 = 20 Pa at alpha = 0.60
  check_close (johnson_jackson_pressure (0.60, jj),
               0.05 * 0.02 * 0.02 / 1e-6,
               1e-12,
               "P_fr hand value");
  return testing::finish ("closures_drag_friction");
}
