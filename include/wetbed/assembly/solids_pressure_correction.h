#pragma once

#include <wetbed/assembly/volume_fraction_transport.h>
#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/core/parameters.h>
#include <wetbed/core/time_integration.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <string>
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

/** Where a linear solve reports how it went (the solver name, its control with history
 * data, whether it converged): SolveHistory::record. */
using SolveRecord =
    std::function<void (const std::string &, const dealii::SolverControl &, bool)>;

/**
 * The implicit solids-pressure correction of one outer iteration (doc/theory.md, "One
 * time step", steps 3-4): after the alpha_s transport, the response of the compaction
 * force the momentum solve saw is made implicit in the change of alpha_s since then,
 * first for alpha_s (edge fluxes through the transport's limiter), then with the same
 * compaction response for u_s. It owns the correction matrices, the alpha_s the momentum
 * solve saw (alpha_m) and the vertical mixture momentum its velocity correction added
 * (which the momentum budget of monitors.csv reads).
 */
template <int dim>
class SolidsPressureCorrection
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  SolidsPressureCorrection (const Parameters    &parameters,
                            MPI_Comm             communicator,
                            dealii::TimerOutput &timer);

  /** For a new mesh (after the alpha_s DoFs and constraints): the matrices' sparsity;
   * `layout` gives the parallel layout of the alpha_s vectors. */
  void reinit (const dealii::DoFHandler<dim>           &alpha_dof_handler,
               const dealii::AffineConstraints<double> &alpha_constraints,
               const AlphaVector                       &layout);
  /** Before the transport: alpha_m = `alpha` (ghosted), the alpha_s the momentum solve
   * saw; no momentum added yet. */
  void begin (const AlphaVector &alpha);
  /** The implicit correction of `alpha` (ghosted) through the limiter of `transport`;
   * false where no compacted region exists (nothing was done). Its CG solve is
   * reported to `record`. */
  bool correct_solids_fraction (const SolidsTransportInputs<dim> &inputs,
                                const BlockVector                &flow_solution,
                                AlphaVector                      &alpha,
                                VolumeFractionTransport<dim>     &transport,
                                const SolveRecord                &record);
  /** u_s += -P_s'(alpha) / (a0 alpha_s rho_s / dt + beta) grad (alpha - alpha_m). */
  void correct_solids_velocity (const SolidsTransportInputs<dim> &inputs,
                                const AlphaVector                &alpha,
                                BlockVector                      &flow_solution);
  /** The vertical mixture momentum the velocity correction added since begin() (N s,
   * per metre depth in 2D; 0 where nothing was compacted). */
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
  /** alpha corrected by the edge fluxes of the nodal pressure increment w = S z
   * (`increment`: z), limited by `transport`. */
  void apply_pressure_increment (const closures::ClosureEvaluator            &closures,
                                 const dealii::TrilinosWrappers::MPI::Vector &increment,
                                 AlphaVector                                 &alpha,
                                 VolumeFractionTransport<dim> &transport) const;
  /** z of the correction by CG: point Jacobi, AMG where Jacobi is slow. */
  void solve_correction (const dealii::TrilinosWrappers::MPI::Vector &rhs,
                         dealii::TrilinosWrappers::MPI::Vector       &increment,
                         const SolveRecord                           &record) const;

  const Parameters    &parameters;
  MPI_Comm             communicator;
  dealii::TimerOutput &timer;
  // M_L + dt K diag(P'_j) (solved) and dt K (the edge fluxes)
  dealii::TrilinosWrappers::SparseMatrix correction_matrix, compaction_flux_matrix;
  // alpha_m: the alpha_s the momentum solve saw (ghosted)
  AlphaVector alpha_momentum;
  double      last_correction_momentum = 0;
};
} // namespace wetbed
