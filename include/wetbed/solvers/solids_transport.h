#pragma once

#include <wetbed/assembly/solids_pressure_correction.h>
#include <wetbed/assembly/volume_fraction_transport.h>
#include <wetbed/core/parameters.h>
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
 * The solids continuity of one outer iteration as a component (doc/theory.md, "One time
 * step", steps 2-4): the explicit bounded alpha_s transport from t_n with the midpoint
 * of u_s^n and u_s* (VolumeFractionTransport, FCT), then the implicit solids-pressure
 * correction of alpha_s and, with the same compaction response, of u_s
 * (SolidsPressureCorrection). It owns the transport operator and the correction; it
 * reads SolidsTransportInputs and writes only itself, alpha_s and the flow iterate it is
 * handed.
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

  /** The solids feed's source (InletConditions::solids_inflow_rates; size 0: none),
   * for this mesh. */
  void set_inflow (const AlphaVector &rates) { transport.set_inflow (rates); }

  /** The solids volume the feed added in the last advance() (m^3; m^2 in 2D). */
  double inflow_volume () const { return transport.inflow_volume; }

  /** The vertical mixture momentum the velocity correction of the last advance added
   * (N s, per metre depth in 2D; 0 where nothing was compacted). */
  double correction_momentum () const { return correction.correction_momentum (); }

private:
  const Parameters             &parameters;
  dealii::TimerOutput          &timer;
  VolumeFractionTransport<dim>  transport;
  SolidsPressureCorrection<dim> correction;
};
} // namespace wetbed
