#pragma once

#include <deal.II/base/parameter_handler.h>

namespace wetbed
{
/** `subsection spectrum`: the spectra of the monitors written at the end of a run. */
struct SpectrumParameters
{
  bool         enabled;
  double       start_time; // skip the start-up before it (s)
  unsigned int segments;   // Welch segments (50% overlap)

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};
} // namespace wetbed
