#pragma once

#include <deal.II/base/parameter_handler.h>

namespace wetbed
{
/** `subsection statistics`: time-averaged fields. */
struct StatisticsParameters
{
  bool   time_averages; // accumulate means and variances of the fields
  double start_time;    // from this time on (s): the start-up left out

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
