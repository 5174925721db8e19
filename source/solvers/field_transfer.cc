#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/dofs/dof_tools.h>

/*
 * The fields that move with the mesh (adaptation) or are saved with it (checkpoint),
 * always in the same order: u_g, u_s, p' at t_{n+1}, t_n, t_{n-1}; alpha_s and Theta at
 * the same three levels. Attach, refine or save, then interpolate or deserialize in
 * this order.
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
std::vector<typename TwoFluidSolver<dim>::BlockVector *>
TwoFluidSolver<dim>::flow_fields ()
{
  return {&flow_solution, &flow_old, &flow_old2};
}

template <int dim>
std::vector<typename TwoFluidSolver<dim>::AlphaVector *>
TwoFluidSolver<dim>::scalar_fields ()
{
  return {&alpha, &alpha_old, &alpha_old2, &theta, &theta_old, &theta_old2};
}

template <int dim>
typename TwoFluidSolver<dim>::FieldTransfers
TwoFluidSolver<dim>::attach_fields (const bool for_serialization)
{
  FieldTransfers transfers{std::make_unique<FlowTransfer> (flow_dof_handler),
                           std::make_unique<ScalarTransfer> (alpha_dof_handler)};
  std::vector<const BlockVector *> flow;
  for (BlockVector *v : flow_fields ())
    flow.push_back (v);
  std::vector<const AlphaVector *> scalars;
  for (AlphaVector *v : scalar_fields ())
  {
    v->update_ghost_values ();
    scalars.push_back (v);
  }
  if (for_serialization)
  {
    transfers.flow->prepare_for_serialization (flow);
    transfers.scalars->prepare_for_serialization (scalars);
  }
  else
  {
    transfers.flow->prepare_for_coarsening_and_refinement (flow);
    transfers.scalars->prepare_for_coarsening_and_refinement (scalars);
  }
  return transfers;
}

template <int dim>
void TwoFluidSolver<dim>::receive_fields (FieldTransfers &transfers,
                                          const bool      from_checkpoint)
{
  std::vector<BlockVector>   owned (3, BlockVector (flow_owned, communicator));
  std::vector<BlockVector *> flow{&owned[0], &owned[1], &owned[2]};
  if (from_checkpoint)
    transfers.flow->deserialize (flow);
  else
    transfers.flow->interpolate (flow);
  // hanging nodes of the new mesh take their constrained values
  AffineConstraints<double> hanging (
      DoFTools::extract_locally_relevant_dofs (flow_dof_handler));
  DoFTools::make_hanging_node_constraints (flow_dof_handler, hanging);
  hanging.close ();
  const auto targets = flow_fields ();
  for (unsigned int k = 0; k < 3; ++k)
  {
    hanging.distribute (owned[k]);
    *targets[k] = owned[k];
  }
  // ghosted targets: the cells' values are written into ghost entries too
  auto scalars = scalar_fields ();
  if (from_checkpoint)
    transfers.scalars->deserialize (scalars);
  else
    transfers.scalars->interpolate (scalars);
  for (AlphaVector *v : scalars)
  {
    v->zero_out_ghost_values ();
    alpha_constraints.distribute (*v);
    v->update_ghost_values ();
  }
}

template std::vector<TwoFluidSolver<2>::BlockVector *> TwoFluidSolver<2>::flow_fields ();
template std::vector<TwoFluidSolver<3>::BlockVector *> TwoFluidSolver<3>::flow_fields ();
template std::vector<TwoFluidSolver<2>::AlphaVector *>
TwoFluidSolver<2>::scalar_fields ();
template std::vector<TwoFluidSolver<3>::AlphaVector *>
                                           TwoFluidSolver<3>::scalar_fields ();
template TwoFluidSolver<2>::FieldTransfers TwoFluidSolver<2>::attach_fields (bool);
template TwoFluidSolver<3>::FieldTransfers TwoFluidSolver<3>::attach_fields (bool);
template void TwoFluidSolver<2>::receive_fields (FieldTransfers &, bool);
template void TwoFluidSolver<3>::receive_fields (FieldTransfers &, bool);
} // namespace wetbed
