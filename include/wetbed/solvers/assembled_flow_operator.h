#pragma once

#include <wetbed/solvers/flow_operator.h>

#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>

namespace wetbed
{
/**
 * The flow operator as an assembled Trilinos matrix [[A, B^T], [B, 0]] over the blocks
 * (velocities, pressure), with the Schur preconditioner's mobility Laplacian L_c
 * assembled beside it (block (1, 1) of `schur`).
 */
class AssembledFlowOperator : public FlowOperator
{
public:
  std::string name () const override { return "assembled"; }
  void        vmult (BlockVector &dst, const BlockVector &src) const override
  {
    system.vmult (dst, src);
  }

  /** The sparsity of the system and of L_c on this mesh (after a mesh change). */
  void reinit (const std::vector<dealii::IndexSet>       &owned,
               const dealii::BlockDynamicSparsityPattern &system_pattern,
               const dealii::BlockDynamicSparsityPattern &schur_pattern,
               MPI_Comm                                   communicator)
  {
    system.reinit (owned, system_pattern, communicator);
    schur.reinit (owned, schur_pattern, communicator);
  }

  /** L_c alone (the system applied matrix-free and preconditioned without it). */
  void reinit_schur (const std::vector<dealii::IndexSet>       &owned,
                     const dealii::BlockDynamicSparsityPattern &schur_pattern,
                     MPI_Comm                                   communicator)
  {
    system.clear ();
    schur.reinit (owned, schur_pattern, communicator);
  }

  const dealii::TrilinosWrappers::SparseMatrix &velocity_block () const
  {
    return system.block (0, 0);
  }
  /** B^T: the pressure in the momentum equations. */
  const dealii::TrilinosWrappers::SparseMatrix &gradient_block () const
  {
    return system.block (0, 1);
  }
  const dealii::TrilinosWrappers::SparseMatrix &schur_block () const
  {
    return schur.block (1, 1);
  }

  // written by the assembly (FlowAssembler)
  dealii::TrilinosWrappers::BlockSparseMatrix system, schur;
};
} // namespace wetbed
