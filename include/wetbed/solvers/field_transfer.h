#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <array>
#include <memory>
#include <vector>

namespace wetbed
{
/**
 * The fields that move with the mesh (adaptation) or are saved with it (checkpoint),
 * always in the same order: u_g, u_s, p' at t_{n+1}, t_n, t_{n-1} (then the time
 * averages' flow accumulators); alpha_s at the same three levels, Theta at the same
 * three levels (then the time averages' scalar accumulators). Pointers to the solver's
 * vectors: what a transfer writes.
 */
template <int dim>
struct TransferredFields
{
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  std::vector<BlockVector *> flow;
  std::vector<AlphaVector *> scalars;
};

/**
 * Moves TransferredFields across a mesh change or through a checkpoint with deal.II's
 * parallel SolutionTransfer (source/solvers/field_transfer.cc): attach them before the
 * refinement or save(), then, once the mesh has changed (or been loaded) and the DoFs
 * are set up anew, receive them on the new mesh, hanging nodes at their constrained
 * values. It writes only the fields it is handed (their ghost values on attach, every
 * value on receive).
 */
template <int dim>
class FieldTransfer
{
public:
  using BlockVector = typename TransferredFields<dim>::BlockVector;
  using AlphaVector = typename TransferredFields<dim>::AlphaVector;

  /** Before the mesh change or load(): the DoF handlers the fields live on. */
  FieldTransfer (const dealii::DoFHandler<dim> &flow_dof_handler,
                 const dealii::DoFHandler<dim> &alpha_dof_handler);

  /** Attaches every field (ghost values updated) to the triangulation, for a mesh
   * change or, `for_serialization`, for save(). */
  void attach (const TransferredFields<dim> &fields, bool for_serialization);

  /** After the mesh change (or load(), `from_checkpoint`) and the new DoFs: every field
   * on the new mesh (`flow_owned` its flow blocks, `alpha_constraints` the hanging
   * nodes of the alpha_s space). */
  void receive (const TransferredFields<dim>            &fields,
                const std::vector<dealii::IndexSet>     &flow_owned,
                const dealii::AffineConstraints<double> &alpha_constraints,
                bool                                     from_checkpoint);

private:
  using FlowTransfer = dealii::parallel::distributed::SolutionTransfer<dim, BlockVector>;
  using ScalarTransfer =
      dealii::parallel::distributed::SolutionTransfer<dim, AlphaVector>;
  const dealii::DoFHandler<dim> &flow_dof_handler;
  FlowTransfer                   flow;
  ScalarTransfer                 scalars;
};
} // namespace wetbed
