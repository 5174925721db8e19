#include <wetbed/solvers/field_transfer.h>

#include <deal.II/dofs/dof_tools.h>

/*
 * The fields that move with the mesh (adaptation) or are saved with it (checkpoint),
 * always in the order of TransferredFields: attach, refine or save, then interpolate or
 * deserialize in this order (doc/theory.md, "Adaptive meshes" and "Checkpoints").
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
FieldTransfer<dim>::FieldTransfer (const DoFHandler<dim> &flow_dof_handler,
                                   const DoFHandler<dim> &alpha_dof_handler)
    : flow_dof_handler (flow_dof_handler), flow (flow_dof_handler),
      scalars (alpha_dof_handler)
{
}

template <int dim>
void FieldTransfer<dim>::attach (const TransferredFields<dim> &fields,
                                 const bool                    for_serialization)
{
  const std::vector<const BlockVector *> flow_fields (fields.flow.begin (),
                                                      fields.flow.end ());
  std::vector<const AlphaVector *>       scalar_fields;
  for (AlphaVector *v : fields.scalars)
  {
    v->update_ghost_values ();
    scalar_fields.push_back (v);
  }
  if (for_serialization)
  {
    flow.prepare_for_serialization (flow_fields);
    scalars.prepare_for_serialization (scalar_fields);
  }
  else
  {
    flow.prepare_for_coarsening_and_refinement (flow_fields);
    scalars.prepare_for_coarsening_and_refinement (scalar_fields);
  }
}

template <int dim>
void FieldTransfer<dim>::receive (const TransferredFields<dim>    &fields,
                                  const std::vector<IndexSet>     &flow_owned,
                                  const AffineConstraints<double> &alpha_constraints,
                                  const bool                       from_checkpoint)
{
  const MPI_Comm communicator = flow_dof_handler.get_triangulation ().get_communicator ();
  std::vector<BlockVector>   owned (fields.flow.size (),
                                  BlockVector (flow_owned, communicator));
  std::vector<BlockVector *> received;
  for (BlockVector &v : owned)
    received.push_back (&v);
  if (from_checkpoint)
    flow.deserialize (received);
  else
    flow.interpolate (received);
  // hanging nodes of the new mesh take their constrained values
  AffineConstraints<double> hanging (
      DoFTools::extract_locally_relevant_dofs (flow_dof_handler));
  DoFTools::make_hanging_node_constraints (flow_dof_handler, hanging);
  hanging.close ();
  for (unsigned int k = 0; k < owned.size (); ++k)
  {
    hanging.distribute (owned[k]);
    *fields.flow[k] = owned[k];
  }
  // ghosted targets: the cells' values are written into ghost entries too
  std::vector<AlphaVector *> scalar_fields (fields.scalars.begin (),
                                            fields.scalars.end ());
  if (from_checkpoint)
    scalars.deserialize (scalar_fields);
  else
    scalars.interpolate (scalar_fields);
  for (AlphaVector *v : scalar_fields)
  {
    v->zero_out_ghost_values ();
    alpha_constraints.distribute (*v);
    v->update_ghost_values ();
  }
}

template class FieldTransfer<2>;
template class FieldTransfer<3>;
} // namespace wetbed
