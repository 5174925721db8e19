#pragma once

#include <cmath>
#include <iostream>
#include <string>

namespace wetbed::testing
{
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
} // namespace wetbed::testing
