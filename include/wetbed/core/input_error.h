#pragma once

#include <deal.II/base/tensor.h>

#include <stdexcept>
#include <string>

namespace wetbed
{
/**
 * An error in the user's input: names the parameter (as `subsection/name`) or the
 * file, and the reason. main() prints it as one line and exits with status 2.
 */
class InputError : public std::runtime_error
{
public:
  InputError (const std::string &where, const std::string &reason)
      : std::runtime_error (where + ": " + reason)
  {
  }
};

/** Throws an InputError naming `where` unless `condition` holds. */
inline void
require (const bool condition, const std::string &where, const std::string &reason)
{
  if (!condition)
    throw InputError (where, reason);
}

/** Throws an InputError naming `where` unless value > 0. */
inline void require_positive (const double value, const std::string &where)
{
  require (value > 0.0, where, "must be > 0 (got " + std::to_string (value) + ")");
}

/** A finite number, the whole of `text`; an InputError naming `where` otherwise. */
double parse_number (const std::string &text, const std::string &where);

/** Three comma-separated numbers; an InputError naming `where` otherwise. */
dealii::Tensor<1, 3> parse_vector (const std::string &text, const std::string &where);
} // namespace wetbed
