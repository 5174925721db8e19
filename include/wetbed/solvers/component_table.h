#pragma once

#include <deal.II/fe/fe.h>

#include <vector>

namespace wetbed
{
/**
 * The system index of every DoF of a primitive element by component and index within
 * the component: table[c][a] = fe.component_to_system_index (c, a), built once per use
 * (deal.II's function searches the element's table linearly at every call, which made it
 * a few per cent of a 3D step where cell loops called it per node).
 */
template <int dim>
std::vector<std::vector<unsigned int>>
component_to_system_table (const dealii::FiniteElement<dim> &fe)
{
  std::vector<std::vector<unsigned int>> table (fe.n_components ());
  for (unsigned int i = 0; i < fe.n_dofs_per_cell (); ++i)
  {
    const auto [component, index] = fe.system_to_component_index (i);
    if (table[component].size () <= index)
      table[component].resize (index + 1);
    table[component][index] = i;
  }
  return table;
}
} // namespace wetbed
