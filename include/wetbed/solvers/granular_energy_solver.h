#pragma once

#include <wetbed/assembly/granular_energy.h>
#include <wetbed/assembly/granular_energy_budget.h>
#include <wetbed/core/parameters.h>
#include <wetbed/solvers/solve_history.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>

namespace wetbed
{
/**
 * The granular temperature Theta as a component: the PDE (its matrix, assembled and
 * solved each outer iteration) or the local equilibrium projected onto the nodes, and
 * the granular energy budget of its last update, which monitors.csv reports. It reads
 * GranularEnergyInputs and writes only itself and Theta; the assembly is
 * GranularEnergyAssembler's.
 */
template <int dim>
class GranularEnergySolver
{
public:
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  GranularEnergySolver (const Parameters    &parameters,
                        MPI_Comm             communicator,
                        dealii::TimerOutput &timer);

  /** For a new mesh (after the alpha_s DoFs and constraints): the matrix's sparsity
   * (PDE model only). */
  void reinit (const dealii::DoFHandler<dim>           &alpha_dof_handler,
               const dealii::AffineConstraints<double> &alpha_constraints);

  /** Theta (ghosted; the linearisation point Theta* on entry) updated from `inputs`,
   * clamped to [minimum, maximum]; false, with `rejection_reason`, if the solve failed
   * or Theta is not finite (then Theta is unusable and the step is rejected). The
   * solve goes into `history`. */
  bool update (const GranularEnergyInputs<dim> &inputs,
               AlphaVector                     &theta,
               SolveHistory                    &history,
               std::string                     &rejection_reason);

  /** The production, dissipation, drag exchange and wall flux of the last update,
   * summed over the ranks. */
  const GranularEnergyBudget &budget () const { return last_budget; }

private:
  /** PDE model: GMRES from the current Theta; false (rejection_reason) if it failed. */
  bool solve_granular_energy_system (const AlphaVector                           &theta,
                                     const dealii::TrilinosWrappers::MPI::Vector &rhs,
                                     dealii::TrilinosWrappers::MPI::Vector &solution,
                                     SolveHistory                          &history,
                                     std::string &rejection_reason) const;
  /** Theta = the clamped nodal `solution`; false (rejection_reason) if not finite. */
  bool
  set_granular_temperature (const dealii::TrilinosWrappers::MPI::Vector &solution,
                            const dealii::AffineConstraints<double> &alpha_constraints,
                            AlphaVector                             &theta,
                            std::string &rejection_reason) const;

  const Parameters                      &parameters;
  MPI_Comm                               communicator;
  dealii::TimerOutput                   &timer;
  GranularEnergyAssembler<dim>           assembler;
  dealii::TrilinosWrappers::SparseMatrix matrix; // PDE model only
  GranularEnergyBudget                   last_budget;
};
} // namespace wetbed
