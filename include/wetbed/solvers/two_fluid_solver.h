#pragma once

#include <wetbed/assembly/flow/flow_assembler.h>
#include <wetbed/boundary_conditions/inlet_conditions.h>
#include <wetbed/boundary_conditions/wall_conditions.h>
#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>
#include <wetbed/core/parameters.h>
#include <wetbed/core/time_integration.h>
#include <wetbed/core/verification_hook.h>
#include <wetbed/mesh/cell_weights.h>
#include <wetbed/mesh/mesh_input.h>
#include <wetbed/mesh/partition_independent_triangulation.h>
#include <wetbed/postprocess/bubble_analysis.h>
#include <wetbed/postprocess/ect_sensor.h>
#include <wetbed/postprocess/field_output.h>
#include <wetbed/postprocess/monitors.h>
#include <wetbed/postprocess/pressure_probe.h>
#include <wetbed/postprocess/profiles.h>
#include <wetbed/postprocess/time_averages.h>
#include <wetbed/solvers/checkpointing.h>
#include <wetbed/solvers/divergence_checks.h>
#include <wetbed/solvers/field_levels.h>
#include <wetbed/solvers/field_transfer.h>
#include <wetbed/solvers/flow_system.h>
#include <wetbed/solvers/granular_energy_solver.h>
#include <wetbed/solvers/mesh_adaptation.h>
#include <wetbed/solvers/solids_transport.h>
#include <wetbed/solvers/solve_history.h>
#include <wetbed/solvers/solver_state.h>
#include <wetbed/solvers/time_state.h>
#include <wetbed/solvers/time_step_controller.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <functional>
#include <memory>

namespace wetbed
{
/**
 * The two-fluid solver: gas and solids momentum with one shared pressure p' = p -
 * rho_g g.x, mixture continuity, solids continuity (explicit bounded transport with an
 * implicit solids-pressure correction), variable-step BDF2 with accept/reject.
 */
template <int dim>
class TwoFluidSolver
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  TwoFluidSolver (const Parameters &parameters, MPI_Comm communicator);
  ~TwoFluidSolver ();

  /** What a verification run imposes (tests/), registered before run(); a production
   * run keeps the base VerificationHook, which imposes nothing. */
  void set_verification_hook (std::shared_ptr<VerificationHook<dim>> hook);

  enum class RunEnd
  {
    finished,         // reached the end time
    stopped_by_signal // SIGTERM/SIGINT/SIGUSR2: the last completed step checkpointed
  };
  /** Reads the mesh, sets up and integrates to the end time. */
  RunEnd run ();

  /** Reads the mesh, sets up and imposes the initial state, or with checkpoint/resume
   * the saved state (run() calls it). A new run calls `before_writing` once its input
   * has been checked whole, before it opens its output files (the output folder's
   * verdict). */
  void initialize (const std::function<void ()> &before_writing = {});

  /** Saves the run state in <output folder>/checkpoint (Checkpointing); collective. */
  void write_checkpoint ();

  /** Advances one accepted time step (retrying smaller steps as needed). */
  void advance ();

  /** Errors of u_g, u_s (L2 and H1 seminorm), p' (L2) and, where the verification hook
   * has an exact one, Theta (L2 and H1 seminorm; else 0) against its exact fields. */
  struct Errors
  {
    double gas_velocity_l2, gas_velocity_h1, solids_velocity_l2, solids_velocity_h1,
        pressure_l2, granular_temperature_l2 = 0, granular_temperature_h1 = 0;
  };
  Errors compute_errors () const;

  /** The fields at the points, each u_g (dim), u_s (dim), p', alpha_s, Theta; NaN
   * outside the mesh (sample_fields, source/postprocess/point_sampling.cc);
   * collective. */
  std::vector<std::vector<double>>
  sample (const std::vector<dealii::Point<dim>> &points) const;

  const MonitorRow &last_monitors () const { return monitors.last (); }
  double            current_time () const { return stepping.time; }
  unsigned int      n_cells () const { return triangulation.n_global_active_cells (); }

private:
  // set-up (two_fluid_solver.cc)
  void setup_dofs ();
  // its parts (source/solvers/dof_setup.cc)
  /** The smallest node spacing (the CFL limit) and the moving wall's tangency check. */
  void measure_mesh ();
  /** The mesh and DoF counts and, on several ranks, the partition's balance. */
  void
  report_mesh (const std::vector<dealii::types::global_dof_index> &dofs_per_block) const;
  void make_flow_constraints (double at_time);
  // its parts (source/solvers/flow_constraints.cc)
  /** No slip, a moving wall's velocity, or strong no penetration on the walls. */
  void constrain_walls ();
  /** Every solids velocity DoF at `boundary conditions/held solids velocity`. */
  void constrain_held_solids (double at_time);
  /** The inlet gas velocity U(t)/alpha_g against gravity at each inlet node. */
  void constrain_inlet_gas (double at_time);
  /** Without an outlet: p' = 0 at the first free pressure DoF (returned; else
   * invalid). */
  dealii::types::global_dof_index pin_pressure (const dealii::IndexSet &relevant);
  /** The Schur preconditioner's pressure fixed on the outlet (or at `pinned`). */
  void make_schur_constraints (const dealii::IndexSet         &relevant,
                               dealii::types::global_dof_index pinned);
  void set_initial_state ();
  /** `initial conditions`' gas velocity U/alpha_g against gravity, into `owned_flow`. */
  void gas_at_inlet_velocity (BlockVector &owned_flow) const;
  /** The fields a mesh change or a checkpoint carries, in their fixed order. */
  TransferredFields<dim> transferred_fields ();
  /** Adapts the mesh (MeshAdaptation), moves every field and its history with it
   * (FieldTransfer) and rebuilds the DoFs (two_fluid_solver.cc). */
  void adapt_mesh ();
  /** Connects the cell weights (mesh/wall face weight) once the walls are known and,
   * where they are not uniform on several ranks, repartitions the mesh by them
   * (dof_setup.cc). */
  void connect_load_balancing ();
  /** Each phase's condition on each wall group, once the mesh's boundaries are known. */
  void make_wall_conditions ();
  /** Mesh, fields and time-stepping state from the checkpoint (Checkpointing, its
   * parts in order; two_fluid_solver.cc). */
  void resume_from_checkpoint ();
  /** One attempt at a step of length dt: the outer iterations (doc/theory.md "One time
   * step"); false, with rejection_reason, when a solve fails or the result is not
   * admissible. */
  bool try_time_step (double dt, unsigned int bdf_order);
  /** Theta (PDE or local equilibrium) from the latest alpha_s and u_s; false (with
   * rejection_reason) when its solve failed. */
  bool update_granular_temperature (const BDFCoefficients &bdf, double dt);
  /** The alpha_s transport and the compaction correction (SolidsTransport::advance);
   * false (with rejection_reason) when the transport would need too many sub-steps. */
  bool advance_solids (const BDFCoefficients &bdf, double dt);
  /** Whether the new fields are finite and alpha_s lies in [0, maximum packing]; else
   * false with rejection_reason. */
  bool admissible ();
  /** The accepted step of length dt: counters, the alpha_s time error, the history
   * shift, the monitors, the next step (which stops the run below the minimum). */
  void accept_step (double dt, double kinetic_energy);

  /** The wall clock of run() and where it started (a resumed run: not at 0). */
  struct RunClock
  {
    std::chrono::steady_clock::time_point start;
    double                                start_time;
    unsigned int                          first_step;
    double next_wall_checkpoint = 1; // in multiples of the wall time interval
    double elapsed () const;
  };
  /** After an accepted step: mesh adaptation, bubbles, ECT, averages, field output. */
  void postprocess_step ();
  /** A checkpoint when due (step count, wall clock, signal); true when a signal asks
   * the run to stop (after its checkpoint). */
  bool checkpoint_or_stop (RunClock &clock);
  /** The progress line. */
  void report_progress (const RunClock &clock) const;
  /** The end of a run: the last outputs and checkpoint, the cost report, spectra. */
  void finish_run (const RunClock &clock);
  /** Steps, outer iterations, cost per simulated second and per DoF, memory. */
  void report_cost (const RunClock &clock) const;
  /** flow_solution = x^n + ratio (x^n - x^{n-1}): the first flow solve's initial guess.
   */
  void extrapolate_flow (double ratio);
  /** The peak speeds of the current fields into `wave_speeds` (once for each new
   * state: after the initial state, each step, each mesh change). */
  void update_wave_speeds ();
  /** The next step after one of length dt (TimeStepController, on `wave_speeds` and
   * `time_error`). */
  double next_time_step (double dt) const;
  /** A read-only view of the current state, for the postprocessors and the time-step
   * controller (source/solvers/postprocessing.cc). */
  SolverState<dim> state () const;
  /** Adds a monitors.csv row of the current state (every `monitor interval` steps). */
  void record_monitors ();

  /** The flow system linearised about the current iterate (FlowSystem::assemble; its
   * assembler from make_flow_assembler on first use). */
  void assemble_flow_system (const BDFCoefficients &bdf, double dt);

  // postprocessing: the components in source/postprocess/ read state(); their
  // orchestration (source/solvers/postprocessing.cc)
  /** The optional columns of monitors.csv this case asks for. */
  MonitorColumns monitor_columns () const;
  /** The bubble analysis of this mesh (its boundary ids), made right after the mesh is
   * read. */
  void make_bubble_analysis ();
  /** Detects and tracks bubbles if enabled and due at this step. */
  void analyse_bubbles ();
  /** The ECT sensor's frames since the last accepted step, if it is enabled. */
  void record_ect ();
  /** The last accepted step into the time averages, if they are on. */
  void accumulate_averages ();
  /** The field files and the profiles of the current state; collective. */
  void write_fields ();
  /** (name, bytes) of the files the checkpoint cuts back to on resume, besides
   * monitors.csv and the bubble files. */
  std::vector<std::pair<std::string, unsigned long long>> appended_files ();
  /** spectrum.csv from monitors.csv (and ect_spectrum.csv from ect.csv), at the end of a
   * run that lasted past the spectrum start time (rank 0). */
  void write_spectra () const;

  /** The cause of the last rejection and where the failed state is extreme
   * (source/solvers/failure_report.cc); collective. */
  std::string describe_failed_state (double dt, const std::string &where) const;
  /** Stops a run that cannot go on: failure_report.txt (`why`, `where` the check
   * failed, the failed state), then `restore` and the last good state written as
   * fields and checkpoint; throws (status 3). */
  [[noreturn]] void stop_diverged (const std::string            &why,
                                   const std::string            &where,
                                   double                        dt,
                                   const std::function<void ()> &restore);

  double inlet_superficial_velocity (double t) const;
  /** Hanging-node and periodicity constraints of a space on this mesh, into
   * `constraints` (not closed; source/solvers/dof_setup.cc). */
  void make_mesh_constraints (const dealii::DoFHandler<dim>     &dof_handler,
                              dealii::AffineConstraints<double> &constraints) const;
  /** The velocity of the moving wall in the mesh's dimensions (zero without one). */
  dealii::Tensor<1, dim> moving_wall_velocity () const;
  /** (height, alpha_s) of the discrete rest state at the given vertex heights, top down.
   */
  std::vector<std::pair<double, double>>
  hydrostatic_profile (const std::vector<double> &heights) const;

  const Parameters            parameters;
  MPI_Comm                    communicator;
  dealii::ConditionalOStream  pcout;
  mutable dealii::TimerOutput timer;

  PartitionIndependentTriangulation<dim> triangulation;
  Boundaries                             boundaries;
  WallConditions                         wall_conditions;
  // the partition's cost model (mesh/wall face weight); unconnected: balance by count
  boost::signals2::scoped_connection cell_weights;
  // MappingQ's support points of every cell, computed once per mesh (setup_dofs): the
  // transfinite/cylindrical manifold of a curved column is not evaluated again at
  // every FEValues::reinit
  dealii::MappingQCache<dim> mapping;

  dealii::FESystem<dim>   flow_fe;
  dealii::DoFHandler<dim> flow_dof_handler;
  dealii::FE_Q<dim>       alpha_fe;
  dealii::DoFHandler<dim> alpha_dof_handler;

  std::vector<dealii::IndexSet>     flow_owned, flow_relevant;
  dealii::AffineConstraints<double> flow_constraints, schur_constraints;
  // hanging nodes of the alpha_s/Theta space (empty on uniform meshes)
  dealii::AffineConstraints<double> alpha_constraints;

  FlowSystem<dim> flow_system;
  // the granular temperature update (PDE or algebraic), its matrix and budget
  GranularEnergySolver<dim> granular_energy;
  // the unknowns at the current iterate, t_n and t_{n-1}
  FieldLevels fields;

  std::unique_ptr<closures::DragModel>         drag;
  std::unique_ptr<closures::SolidsStressModel> solids_stress;
  const closures::KineticTheory               *kinetic_theory; // null without KTGF
  closures::GasParticleProperties              gas_particle;
  closures::ClosureEvaluator                   closure_evaluator;
  dealii::FunctionParser<3> held_velocity_function{3}; // u_s(x, y, z, t) where held
  std::shared_ptr<VerificationHook<dim>> verification =
      std::make_shared<VerificationHook<dim>> ();

  // the alpha_s transport and compaction correction, its operators and the momentum
  // its velocity correction added
  SolidsTransport<dim> solids_transport;
  TimeStepController   time_step_controller;
  // the sanity of each step's result (speeds, FI, kinetic energy growth)
  DivergenceChecks<dim> divergence_checks;

  MeshAdaptation<dim> mesh_adaptation;
  Checkpointing<dim>  checkpointing;

  Monitors                             monitors;
  std::unique_ptr<BubbleAnalysis<dim>> bubble_analysis;
  // the seed's instruments, when the case asks for them
  std::unique_ptr<PressureProbe<dim>> pressure_probe;
  std::unique_ptr<EctSensor<dim>>     ect_sensor;
  // the time-averaged fields and the profiles (subsection statistics), when asked for
  std::unique_ptr<TimeAverages<dim>> time_averages;
  std::unique_ptr<Profiles<dim>>     profiles;
  // the field files and their counters
  FieldOutput<dim> field_output;
  // the gas inflow of each inlet group
  InletConditions<dim> inlets;
  // the time, the steps and their counters (a checkpoint keeps part of it)
  TimeState    stepping;
  WaveSpeeds   wave_speeds; // of the current fields (update_wave_speeds)
  double       initial_solids_mass;
  double       solids_fed_mass = 0; // through the inlets since t = 0 (inlet solids)
  double       min_node_spacing;
  bool         initialized = false;
  bool         resumed     = false; // the state came from a checkpoint
  std::string  run_id;              // new for each run, kept by its resumes
  std::string  rejection_reason;    // why the last attempted step was rejected
  SolveHistory solve_history;       // the linear solves of the current step
};
} // namespace wetbed
