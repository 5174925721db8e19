#pragma once

#include <wetbed/assembly/granular_energy_budget.h>
#include <wetbed/boundary_conditions/wall_conditions.h>
#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/core/parameters.h>
#include <wetbed/core/time_integration.h>
#include <wetbed/core/verification_hook.h>
#include <wetbed/mesh/boundaries.h>
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
 * What the Theta update reads, as a const view (references into the solver's state):
 * the discretisation, the fields of the current outer iteration and the Theta history,
 * the models, and the time step. Theta itself, the linearisation point on entry and the
 * result on exit, is the argument GranularEnergySolver::update writes.
 */
template <int dim>
struct GranularEnergyInputs
{
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  // the discretisation: Theta lives on the alpha_s space (its DoFs and constraints)
  const dealii::Mapping<dim>              &mapping;
  const dealii::FiniteElement<dim>        &alpha_fe;
  const dealii::DoFHandler<dim>           &alpha_dof_handler;
  const dealii::FiniteElement<dim>        &flow_fe;
  const dealii::DoFHandler<dim>           &flow_dof_handler;
  const dealii::AffineConstraints<double> &alpha_constraints;
  const Boundaries                        &boundaries;
  const WallConditions                    &wall_conditions;
  dealii::Tensor<1, dim>                   moving_wall_velocity; // zero without one

  // the fields (ghosted): alpha_s and (u_g, u_s, p') of the current outer iteration,
  // Theta at t_n and t_{n-1}
  const AlphaVector &alpha;
  const BlockVector &flow_solution;
  const AlphaVector &theta_old, &theta_old2;

  // the models; what a verification run imposes (nothing in a production run)
  const closures::ClosureEvaluator &closures;
  const closures::KineticTheory    &kinetic_theory;
  const VerificationHook<dim>      &verification;

  // the time step
  BDFCoefficients bdf;
  double          dt;
};

/**
 * The granular temperature Theta as a component: the PDE (its matrix, assembled and
 * solved each outer iteration) or the local equilibrium projected onto the nodes, and
 * the granular energy budget of its last update, which monitors.csv reports. It reads
 * GranularEnergyInputs and writes only itself and Theta (source/solvers/
 * granular_energy_solver.cc; the assembly in source/assembly/granular_energy.cc).
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
  /** FEValues, Gauss-point fields and local system of the Theta assembly. */
  struct Scratch;
  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;

  /** Algebraic model: the local equilibrium lumped-L2 projected into `solution`. */
  void
  project_algebraic_granular_temperature (const GranularEnergyInputs<dim>       &inputs,
                                          const AlphaVector                     &theta,
                                          dealii::TrilinosWrappers::MPI::Vector &solution,
                                          GranularEnergyBudget &budget) const;
  /** PDE model: the matrix and `rhs` assembled and compressed. */
  void assemble_granular_energy_system (const GranularEnergyInputs<dim>       &inputs,
                                        const AlphaVector                     &theta,
                                        dealii::TrilinosWrappers::MPI::Vector &rhs,
                                        GranularEnergyBudget                  &budget);
  /** PDE model, one cell's volume terms; returns the cell Peclet number. */
  double assemble_granular_energy_volume_terms (const GranularEnergyInputs<dim> &inputs,
                                                const CellIterator              &cell,
                                                Scratch                         &scratch,
                                                GranularEnergyBudget &budget) const;
  /** PDE model, one cell's imposed boundary flux and Johnson-Jackson wall terms. */
  void assemble_granular_energy_boundary_terms (const GranularEnergyInputs<dim> &inputs,
                                                const AlphaVector               &theta,
                                                const CellIterator              &cell,
                                                const CellIterator   &flow_cell,
                                                Scratch              &scratch,
                                                GranularEnergyBudget &budget) const;
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
  dealii::TrilinosWrappers::SparseMatrix matrix; // PDE model only
  GranularEnergyBudget                   last_budget;
};
} // namespace wetbed
