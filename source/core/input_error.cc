#include <wetbed/core/input_error.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace wetbed
{
dealii::Tensor<1, 3> parse_vector (const std::string &text, const std::string &where)
{
  const std::vector<std::string> parts = dealii::Utilities::split_string_list (text, ',');
  require (parts.size () == 3,
           where,
           "needs three comma-separated numbers (got '" + text + "')");
  dealii::Tensor<1, 3> vector;
  for (unsigned int d = 0; d < 3; ++d)
  {
    std::size_t used = 0;
    try
    {
      vector[d] = std::stod (parts[d], &used);
    }
    catch (const std::logic_error &)
    {
      used = 0;
    }
    require (used == parts[d].size () && used > 0,
             where,
             "'" + parts[d] + "' is not a number");
    require (
        std::isfinite (vector[d]), where, "'" + parts[d] + "' is not a finite number");
  }
  return vector;
}
} // namespace wetbed
