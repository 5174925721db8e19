#include <wetbed/core/input_error.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace wetbed
{
double parse_number (const std::string &text, const std::string &where)
{
  std::size_t used  = 0;
  double      value = 0;
  try
  {
    value = std::stod (text, &used);
  }
  catch (const std::logic_error &)
  {
    used = 0;
  }
  require (used == text.size () && used > 0, where, "'" + text + "' is not a number");
  require (std::isfinite (value), where, "'" + text + "' is not a finite number");
  return value;
}

dealii::Tensor<1, 3> parse_vector (const std::string &text, const std::string &where)
{
  const std::vector<std::string> parts = dealii::Utilities::split_string_list (text, ',');
  require (parts.size () == 3,
           where,
           "needs three comma-separated numbers (got '" + text + "')");
  dealii::Tensor<1, 3> vector;
  for (unsigned int d = 0; d < 3; ++d)
    vector[d] = parse_number (parts[d], where);
  return vector;
}
} // namespace wetbed
