#pragma once

#include <wetbed/assembly/granular_energy_budget.h>
#include <wetbed/boundary_conditions/wall_conditions.h>
#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/core/parameters.h>
#include <wetbed/core/time_integration.h>
#include <wetbed/core/verification_hook.h>
#include <wetbed/mesh/boundaries.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

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
 * The assembly of the granular-energy equation (doc/theory.md, "Granular energy"; the
 * model is described at GranularEnergySolver::update): the PDE's lumped, upwinded
 * matrix and right-hand side with the Johnson-Jackson wall terms and a verification
 * run's imposed sources, or the local equilibrium of the algebraic model lumped-L2
 * projected onto the nodes; each with the granular energy budget of its terms (this
 * rank's part).
 */
template <int dim>
class GranularEnergyAssembler
{
public:
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  GranularEnergyAssembler (const Parameters &parameters, MPI_Comm communicator);

  /** Algebraic model: the local equilibrium at Theta* = `theta` lumped-L2 projected
   * into `solution` (0 at constrained nodes). */
  void project_algebraic (const GranularEnergyInputs<dim>       &inputs,
                          const AlphaVector                     &theta,
                          dealii::TrilinosWrappers::MPI::Vector &solution,
                          GranularEnergyBudget                  &budget) const;
  /** PDE model: `matrix` (its sparsity set) and `rhs` linearised at `theta`, assembled
   * and compressed. */
  void assemble (const GranularEnergyInputs<dim>        &inputs,
                 const AlphaVector                      &theta,
                 dealii::TrilinosWrappers::SparseMatrix &matrix,
                 dealii::TrilinosWrappers::MPI::Vector  &rhs,
                 GranularEnergyBudget                   &budget) const;

private:
  /** FEValues, Gauss-point fields and local system of the Theta assembly. */
  struct Scratch;
  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;

  /** PDE model, one cell's volume terms; returns the cell Peclet number. */
  double volume_terms (const GranularEnergyInputs<dim> &inputs,
                       const CellIterator              &cell,
                       Scratch                         &scratch,
                       GranularEnergyBudget            &budget) const;
  /** PDE model, one cell's imposed boundary flux and Johnson-Jackson wall terms. */
  void boundary_terms (const GranularEnergyInputs<dim> &inputs,
                       const AlphaVector               &theta,
                       const CellIterator              &cell,
                       const CellIterator              &flow_cell,
                       Scratch                         &scratch,
                       GranularEnergyBudget            &budget) const;

  const Parameters &parameters;
  MPI_Comm          communicator;
};
} // namespace wetbed
