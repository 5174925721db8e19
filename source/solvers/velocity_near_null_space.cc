#include <wetbed/solvers/velocity_near_null_space.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <limits>

namespace wetbed
{
using namespace dealii;

template <int dim>
VelocityNearNullSpace velocity_near_null_space (const Mapping<dim>    &mapping,
                                                const DoFHandler<dim> &flow_dof_handler,
                                                const IndexSet        &owned,
                                                const bool             rotations,
                                                MPI_Comm               communicator)
{
  const auto           &fe          = flow_dof_handler.get_fe ();
  const unsigned int    n_rotations = rotations ? (dim == 2 ? 1 : 3) : 0;
  const unsigned int    per_phase   = dim + n_rotations;
  VelocityNearNullSpace space{
      std::vector<std::vector<double>> (2 * per_phase,
                                        std::vector<double> (owned.n_elements (), 0.0)),
      1};
  auto      &modes = space.modes;
  Point<dim> lower, upper;
  for (unsigned int d = 0; d < dim; ++d)
  {
    lower[d] = std::numeric_limits<double>::max ();
    upper[d] = -lower[d];
  }
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
      for (const auto v : cell->vertex_indices ())
        for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min (lower[d], cell->vertex (v)[d]);
          upper[d] = std::max (upper[d], cell->vertex (v)[d]);
        }
  Point<dim> centre;
  for (unsigned int d = 0; d < dim; ++d)
    centre[d] = 0.5 * (Utilities::MPI::min (lower[d], communicator) +
                       Utilities::MPI::max (upper[d], communicator));
  const Quadrature<dim> nodes (fe.get_unit_support_points ());
  FEValues<dim>         node_values (mapping, fe, nodes, update_quadrature_points);
  std::vector<types::global_dof_index> dofs (fe.n_dofs_per_cell ());
  // node blocks: ML aggregates nodes and smooths node blocks when the 2 dim velocity
  // DoFs of every support point are consecutive rows (the numbering keeps them so;
  // checked here, and the blocks are dropped where it would not hold)
  bool nodes_contiguous = true;
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      node_values.reinit (cell);
      for (unsigned int i = 0; i < dofs.size (); ++i)
      {
        const auto [c, node] = fe.system_to_component_index (i);
        if (c >= 2 * dim || !owned.is_element (dofs[i]))
          continue;
        if (dofs[i] != dofs[fe.component_to_system_index (0, node)] + c)
          nodes_contiguous = false;
        const auto         row   = owned.index_within_set (dofs[i]);
        const unsigned int phase = c / dim, d = c % dim;
        modes[phase * per_phase + d][row] = 1.0;
        const Tensor<1, dim> x            = node_values.quadrature_point (i) - centre;
        if (n_rotations == 1) // (-y, x)
          modes[phase * per_phase + dim][row] = d == 0 ? -x[1] : x[0];
        else if (n_rotations == 3) // e_a x x
          for (unsigned int a = 0; a < 3; ++a)
          {
            const unsigned int b = (a + 1) % 3, e = (a + 2) % 3;
            modes[phase * per_phase + dim + a][row] = d == b   ? -x[e]
                                                      : d == e ? x[b]
                                                               : 0.0;
          }
      }
    }
  nodes_contiguous    = Utilities::MPI::min (nodes_contiguous ? 1 : 0, communicator) == 1;
  space.dofs_per_node = nodes_contiguous ? 2 * dim : 1;
  return space;
}

template VelocityNearNullSpace velocity_near_null_space (
    const Mapping<2> &, const DoFHandler<2> &, const IndexSet &, bool, MPI_Comm);
template VelocityNearNullSpace velocity_near_null_space (
    const Mapping<3> &, const DoFHandler<3> &, const IndexSet &, bool, MPI_Comm);
} // namespace wetbed
