#pragma once

#include <wetbed/boundary_conditions/wall_conditions.h>
#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/core/parameters.h>
#include <wetbed/mesh/boundaries.h>
#include <wetbed/postprocess/monitors.h>
#include <wetbed/solvers/time_step_controller.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

namespace wetbed
{
template <int dim>
class FlowSystem;

template <int dim>
class TimeAverages;

/**
 * A read-only view of the simulation after a step, what the postprocessors and the
 * time-step controller read (as ASPECT's SimulatorAccess): the discretisation, the
 * fields now and at the start of the last accepted step, the models, the flow system and
 * the time-stepping counters. TwoFluidSolver::state() makes it; it holds references, so
 * it is valid while the solver's state does not change.
 */
template <int dim>
struct SolverState
{
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  const Parameters &parameters;
  MPI_Comm          communicator;

  // the discretisation
  const dealii::parallel::distributed::Triangulation<dim> &triangulation;
  const Boundaries                                        &boundaries;
  const WallConditions                                    &wall_conditions;
  const dealii::Mapping<dim>                              &mapping;
  const dealii::FiniteElement<dim>                        &flow_fe;
  const dealii::DoFHandler<dim>                           &flow_dof_handler;
  const dealii::FiniteElement<dim>                        &alpha_fe;
  const dealii::DoFHandler<dim>                           &alpha_dof_handler;
  // the lumped mass of the alpha_s space (m^3 per node, m^2 in 2D)
  const AlphaVector &lumped_mass;

  // the fields (ghosted): now, and at the start of the last accepted step
  const BlockVector &flow_solution, &flow_previous;
  const AlphaVector &alpha, &alpha_previous, &theta;

  // the models and the flow system
  const closures::ClosureEvaluator &closures;
  const closures::KineticTheory    *kinetic_theory; // null without kinetic theory
  const FlowSystem<dim>            &flow_system;
  dealii::Tensor<1, dim>            moving_wall_velocity; // zero without one

  // the time stepping
  double       time;
  double       time_step;           // of the last accepted step (0 before the first)
  double       inlet_velocity;      // U(time): the mean over the inlets, m/s
  double       inlet_peak_velocity; // the largest superficial speed on an inlet, m/s
  unsigned int step_number, rejected_steps, krylov_iterations;
  double       initial_solids_mass;
  double       solids_fed_mass; // through the inlets since t = 0 (inlet solids)
  // the vertical mixture momentum the compaction correction added in the last outer
  // iteration (N s, per metre depth in 2D)
  double               correction_momentum;
  GranularEnergyBudget granular_energy; // of the last Theta update
  // the peak speeds of these fields (evaluate_wave_speeds), evaluated once for each new
  // state: the time-step controller and monitors.csv read the same
  WaveSpeeds wave_speeds;
  // alpha_s's local time-error estimate of the last step (alpha_time_error; 0 before the
  // second step of a run or resume)
  double time_error;
  // the time averages (subsection statistics); null when they are off
  TimeAverages<dim> *time_averages;

  /** The solids mass (kg, per metre depth in 2D) of a field on the alpha_s space;
   * collective. */
  double solids_mass (const AlphaVector &a) const;
};
} // namespace wetbed
