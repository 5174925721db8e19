#pragma once

#include <deal.II/base/numbers.h>

#include <map>
#include <string>

namespace wetbed
{
/** The constants the expressions of a case file may use (muparser knows none by these
 * names): pi. */
inline std::map<std::string, double> expression_constants ()
{
  return {{"pi", dealii::numbers::PI}};
}
} // namespace wetbed
