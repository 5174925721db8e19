#pragma once

#include <wetbed/closures/drag/drag_model.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace wetbed::testing
{
/** The text of a file; a missing or unreadable file ends the test (exit 1). */
inline std::string file_text (const std::string &path)
{
  std::ifstream in (path);
  if (!in)
  {
    std::cerr << "cannot read " << path << std::endl;
    std::exit (1);
  }
  std::ostringstream text;
  text << in.rdbuf ();
  return text.str ();
}

/** The settings file argv[index] (appended to every case of a test), or "" when the
 * argument is absent or "-". */
inline std::string extra_settings (const int argc, char **argv, const int index)
{
  if (argc <= index || std::string (argv[index]) == "-")
    return "";
  return file_text (argv[index]);
}

/** Counts failed checks; a test's main returns failures() != 0. */
inline unsigned int &failure_count ()
{
  static unsigned int count = 0;
  return count;
}

inline void check (const bool condition, const std::string &what)
{
  if (!condition)
  {
    ++failure_count ();
    std::cout << "FAILED: " << what << std::endl;
  }
}

inline void check_close (const double       value,
                         const double       reference,
                         const double       tolerance,
                         const std::string &what)
{
  const double scale = std::max (std::abs (reference), 1e-300);
  const double error = std::abs (value - reference) / scale;
  if (!(error <= tolerance))
  {
    ++failure_count ();
    std::cout << "FAILED: " << what << ": " << value << " vs " << reference
              << " (rel. error " << error << " > " << tolerance << ")" << std::endl;
  }
}

inline int finish (const std::string &name)
{
  std::cout << name << ": "
            << (failure_count () == 0 ? "all checks passed" : "checks failed")
            << std::endl;
  return failure_count () == 0 ? 0 : 1;
}

/** d f / d x by Sacado at x vs a central difference with step 1e-6 x (rel. 1e-6). */
inline void
check_derivative (const std::function<closures::ADNumber (const closures::ADNumber &)> &f,
                  const double                                                          x,
                  const std::string &what)
{
  using closures::ADNumber;
  const ADNumber ad = f (ADNumber (1, 0, x));
  const double   h  = 1e-6 * x;
  const double fd = (f (ADNumber (x + h)).val () - f (ADNumber (x - h)).val ()) / (2 * h);
  check_close (ad.dx (0), fd, 1e-6, what + " (Sacado vs finite difference)");
}

/** Prints the errors of each quantity over the meshes (sizes h) with the observed rate
 * of the last two, and checks rate > expected - 0.2. */
template <std::size_t n>
void report_rates (const std::vector<std::array<double, n>> &errors,
                   const std::vector<double>                &sizes,
                   const std::array<std::string, n>         &names,
                   const std::array<double, n>              &expected)
{
  const std::size_t last = errors.size () - 1;
  for (std::size_t k = 0; k < n; ++k)
  {
    std::cout << std::setw (16) << names[k];
    for (const auto &e : errors)
      std::cout << "  " << std::scientific << std::setprecision (3) << e[k];
    const double rate = std::log (errors[last - 1][k] / errors[last][k]) /
                        std::log (sizes[last - 1] / sizes[last]);
    std::cout << "  rate " << std::fixed << std::setprecision (2) << rate << "\n";
    check (rate > expected[k] - 0.2,
           names[k] + " rate " + std::to_string (rate) + " < " +
               std::to_string (expected[k] - 0.2));
  }
}
} // namespace wetbed::testing
