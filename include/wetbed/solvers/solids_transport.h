#pragma once

#include <wetbed/assembly/volume_fraction_transport.h>
#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/core/parameters.h>
#include <wetbed/core/time_integration.h>
#include <wetbed/solvers/solve_history.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace wetbed
{
/**
 * What the alpha_s transport and the compaction correction read, as a const view
 * (references into the solver's state): the discretisation and constraints, the fields
 * at t_n, the closures and the time step. alpha_s and the flow iterate, which the
 * component changes, are the arguments of SolidsTransport::advance.
 */
template <int dim>
struct SolidsTransportInputs
{
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  // the discretisation
  const dealii::Mapping<dim>              &mapping;
  const dealii::FiniteElement<dim>        &flow_fe;
  const dealii::DoFHandler<dim>           &flow_dof_handler;
  const std::vector<dealii::IndexSet>     &flow_owned;
  const dealii::AffineConstraints<double> &flow_constraints;
  const dealii::FiniteElement<dim>        &alpha_fe;
  const dealii::DoFHandler<dim>           &alpha_dof_handler;
  const dealii::AffineConstraints<double> &alpha_constraints;

  // the fields at t_n (ghosted): (u_g, u_s, p') and alpha_s
  const BlockVector &flow_old;
  const AlphaVector &alpha_old;

  // the closures (P_s, its slope, the drag) and the time step
  const closures::ClosureEvaluator &closures;
  BDFCoefficients                   bdf;
  double                            dt;
};

/**
 * The solids continuity of one outer iteration as a component (doc/theory.md, "One time
 * step", steps 2-4): the explicit bounded alpha_s transport from t_n with the midpoint
 * of u_s^n and u_s* (VolumeFractionTransport, FCT), then the implicit solids-pressure
 * correction of alpha_s and, with the same compaction response, of u_s. It owns the
 * transport operator, the correction matrices and the vertical mixture momentum its
 * velocity correction added (which the momentum budget of monitors.csv reads); it reads
 * SolidsTransportInputs and writes only itself, alpha_s and the flow iterate it is
 * handed (source/solvers/solids_transport.cc; the correction in
 * source/assembly/solids_pressure_correction.cc).
 */
template <int dim>
class SolidsTransport
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  SolidsTransport (const Parameters    &parameters,
                   MPI_Comm             communicator,
                   dealii::TimerOutput &timer);

  /** For a new mesh (after the alpha_s DoFs and constraints): the transport operator's
   * graph and lumped mass, the correction matrices' sparsity; `layout` gives the
   * parallel layout of the alpha_s vectors. */
  void reinit (const dealii::Mapping<dim>              &mapping,
               const dealii::DoFHandler<dim>           &alpha_dof_handler,
               const dealii::AffineConstraints<double> &alpha_constraints,
               const AlphaVector                       &layout);

  /** One outer iteration's solids continuity: `alpha` (ghosted; on entry the alpha_s
   * the momentum solve saw, on exit alpha_s transported from t_n and corrected) and
   * the solids velocity of `flow_solution` (ghosted; corrected where the bed is
   * compacted, the gas giving way). The correction CG solve goes into `history`.
   * Returns false, with `alpha` and `flow_solution` as they came and the reason in
   * `reason`, when the transport would need more than
   * VolumeFractionTransport::max_sub_steps sub-steps: the step is to be rejected. */
  bool advance (const SolidsTransportInputs<dim> &inputs,
                AlphaVector                      &alpha,
                BlockVector                      &flow_solution,
                SolveHistory                     &history,
                std::string                      &reason);

  /** The lumped mass of the alpha_s space (m^3 per node, m^2 in 2D). */
  const AlphaVector &lumped_mass () const { return transport.lumped_mass (); }

  /** The vertical mixture momentum the velocity correction of the last advance added
   * (N s, per metre depth in 2D; 0 where nothing was compacted). */
  double correction_momentum () const { return last_correction_momentum; }

private:
  /** dP_s/dalpha at the larger of alpha_s and alpha_m. */
  double compaction_stiffness (const closures::ClosureEvaluator &closures,
                               double                            alpha_s,
                               double                            alpha_m) const;
  /** alpha_s/R: the solids volume flux a unit compaction force gradient drives. */
  double compaction_mobility (const closures::ClosureEvaluator &closures,
                              double                            alpha_s,
                              const dealii::Tensor<1, dim>     &slip,
                              double                            rate) const;
  /** dP_s/dalpha at the alpha_s nodes of a cell (compaction_stiffness node by node,
   * alpha_m from alpha_momentum). */
  void
  nodal_compaction_stiffness (const closures::ClosureEvaluator &closures,
                              const std::vector<dealii::types::global_dof_index> &dofs,
                              const AlphaVector                                  &alpha,
                              std::vector<double> &slopes) const;
  /** The implicit correction of `alpha`; false where no compacted region exists
   * (nothing was done). */
  bool correct_solids_pressure (const SolidsTransportInputs<dim> &inputs,
                                const BlockVector                &flow_solution,
                                AlphaVector                      &alpha,
                                SolveHistory                     &history);
  /** z of the correction by CG: point Jacobi, AMG where Jacobi is slow. */
  void solve_correction (const dealii::TrilinosWrappers::MPI::Vector &rhs,
                         dealii::TrilinosWrappers::MPI::Vector       &increment,
                         SolveHistory                                &history) const;
  /** u_s += -P_s'(alpha) / (a0 alpha_s rho_s / dt + beta) grad (alpha - alpha_m). */
  void correct_solids_velocity (const SolidsTransportInputs<dim> &inputs,
                                const AlphaVector                &alpha,
                                BlockVector                      &flow_solution);

  const Parameters            &parameters;
  MPI_Comm                     communicator;
  dealii::TimerOutput         &timer;
  VolumeFractionTransport<dim> transport;
  // M_L + dt K diag(P'_j) (solved) and dt K (the edge fluxes)
  dealii::TrilinosWrappers::SparseMatrix correction_matrix, compaction_flux_matrix;
  // alpha_m: the alpha_s the momentum solve saw (ghosted)
  AlphaVector alpha_momentum;
  double      last_correction_momentum = 0;
};
} // namespace wetbed
