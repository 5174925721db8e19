#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

namespace wetbed
{
/**
 * The sparsity of a matrix on a scalar space (alpha_s, Theta), its rows distributed as
 * the space's locally owned DoFs and condensed with `constraints` (dropped entries
 * removed): what the alpha_s transport, the compaction correction and the granular energy
 * matrices are made from.
 */
template <int dim>
dealii::DynamicSparsityPattern
distributed_scalar_sparsity (const dealii::DoFHandler<dim>           &dof_handler,
                             const dealii::AffineConstraints<double> &constraints)
{
  const dealii::IndexSet &owned = dof_handler.locally_owned_dofs ();
  const dealii::IndexSet  relevant =
      dealii::DoFTools::extract_locally_relevant_dofs (dof_handler);
  dealii::DynamicSparsityPattern dsp (relevant);
  dealii::DoFTools::make_sparsity_pattern (dof_handler, dsp, constraints, false);
  dealii::SparsityTools::distribute_sparsity_pattern (
      dsp, owned, dof_handler.get_triangulation ().get_communicator (), relevant);
  return dsp;
}
} // namespace wetbed
