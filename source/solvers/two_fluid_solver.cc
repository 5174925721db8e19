#include <wetbed/assembly/flow/flow_terms.h>
#include <wetbed/core/expression_constants.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/stall_watchdog.h>
#include <wetbed/core/stop_signal.h>
#include <wetbed/postprocess/bed_monitors.h>
#include <wetbed/solvers/time_error.h>
#include <wetbed/solvers/two_fluid_solver.h>
#include <wetbed/solvers/wave_speeds.h>

#include <fstream>
#include <functional>
#include <sstream>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <random>
#include <sstream>

namespace wetbed
{
using namespace dealii;

namespace
{
/** The outer convergence test (doc/theory.md "Outer iterations") at iteration k >= 1:
 * the re-assembled flow residual against the step's own change r_0 (or at the linear
 * solver's floor), and from k = 2 on the alpha_s change of the last transport. */
bool outer_converged (const TimeSteppingParameters &ts,
                      const unsigned int            k,
                      const double                  residual,
                      const double                  step_residual,
                      const double                  alpha_change,
                      const double                  floor)
{
  return k > 0 &&
         (residual <= ts.outer_tolerance * step_residual || residual <= 10 * floor) &&
         (k == 1 || alpha_change <= ts.outer_alpha_tolerance);
}

/** max |a - b| over the owned entries of all ranks. */
double largest_change (const LinearAlgebra::distributed::Vector<double> &a,
                       const LinearAlgebra::distributed::Vector<double> &b,
                       const MPI_Comm                                    communicator)
{
  double change = 0;
  for (unsigned int i = 0; i < a.locally_owned_size (); ++i)
    change = std::max (change, std::abs (a.local_element (i) - b.local_element (i)));
  return Utilities::MPI::max (change, communicator);
}
} // namespace

template <int dim>
TwoFluidSolver<dim>::TwoFluidSolver (const Parameters &parameters, MPI_Comm communicator)
    : parameters (parameters), communicator (communicator),
      pcout (std::cout, Utilities::MPI::this_mpi_process (communicator) == 0),
      timer (pcout, TimerOutput::never, TimerOutput::wall_times),
      // the 2:1 balance by p4est alone: the adapted mesh does not depend on the partition
      triangulation (communicator), mapping (parameters.mesh.mapping_degree),
      flow_fe (FE_Q<dim> (2), 2 * dim, FE_Q<dim> (1), 1),
      flow_dof_handler (triangulation), alpha_fe (1), alpha_dof_handler (triangulation),
      flow_system (parameters, communicator, pcout, timer),
      granular_energy (parameters, communicator, timer),
      drag (closures::create_drag_model (parameters.drag_model)),
      solids_stress (closures::create_solids_stress_model (parameters.solids_stress,
                                                           parameters.physical,
                                                           parameters.kinetic_theory,
                                                           parameters.wet)),
      kinetic_theory (solids_stress->kinetic_theory ()),
      gas_particle{parameters.physical.gas_density,
                   parameters.physical.gas_viscosity,
                   parameters.physical.particle_diameter},
      closure_evaluator (*drag,
                         *solids_stress,
                         gas_particle,
                         parameters.physical.residual_solids_fraction),
      solids_transport (parameters, communicator, timer),
      time_step_controller (parameters.time), divergence_checks (this->parameters),
      mesh_adaptation (parameters),
      checkpointing (parameters, communicator, pcout, timer),
      field_output (parameters, timer),
      inlets (parameters.boundary,
              parameters.physical.gas_density,
              upward_direction<dim> (parameters.physical.gravity),
              parameters.time.end_time),
      initial_solids_mass (0), min_node_spacing (0)
{
  stepping.time_step = parameters.time.initial_time_step;
  held_velocity_function.initialize (
      "x,y,z,t", parameters.boundary.held_solids_velocity, expression_constants (), true);
  if (parameters.bed_monitors.pressure_probe_height >= 0)
    pressure_probe = std::make_unique<PressureProbe<dim>> (
        parameters.bed_monitors.pressure_probe_height);
  if (parameters.ect_sensor.enabled)
    ect_sensor = std::make_unique<EctSensor<dim>> (parameters.ect_sensor);
  if (parameters.statistics.time_averages)
    time_averages =
        std::make_unique<TimeAverages<dim>> (parameters.statistics.start_time);
  if (parameters.statistics.samples ())
    profiles = std::make_unique<Profiles<dim>> (parameters.statistics);
}

template <int dim>
TwoFluidSolver<dim>::~TwoFluidSolver ()
{
  flow_dof_handler.clear ();
  alpha_dof_handler.clear ();
}

template <int dim>
void TwoFluidSolver<dim>::set_verification_hook (
    std::shared_ptr<VerificationHook<dim>> hook)
{
  verification = std::move (hook);
  flow_system.set_assembler (nullptr); // the hook's sources join the terms
}

template <int dim>
double TwoFluidSolver<dim>::inlet_superficial_velocity (const double t) const
{
  return inlets.mean_superficial_velocity (t);
}

template <int dim>
void TwoFluidSolver<dim>::initialize (const std::function<void ()> &before_writing)
{
  const std::string folder = parameters.output.folder;
  if (Utilities::MPI::this_mpi_process (communicator) == 0)
  {
    std::error_code error;
    std::filesystem::create_directories (folder, error);
    require (!error && std::filesystem::is_directory (folder),
             "output/folder",
             "cannot create '" + folder + "'");
    const std::string probe = folder + "/.wetbed-write-test";
    std::ofstream     test (probe);
    require (
        static_cast<bool> (test), "output/folder", "'" + folder + "' is not writable");
    test.close ();
    std::filesystem::remove (probe);
  }
  MPI_Barrier (communicator);
  if (parameters.checkpoint.resume)
    resume_from_checkpoint ();
  else
  {
    // the run's identity (its checkpoints carry it): 16 hex digits, rank 0's
    std::ostringstream id;
    std::random_device random;
    id << std::hex << std::setw (16) << std::setfill ('0')
       << ((static_cast<unsigned long long> (random ()) << 32) ^ random ());
    run_id = Utilities::MPI::broadcast (communicator, id.str (), 0);
    pcout << "Run " << run_id << std::endl;
    boundaries = read_mesh<dim> (parameters.mesh,
                                 parameters.boundary.moving_wall_name,
                                 parameters.parameter_file_directory,
                                 folder,
                                 parameters.physical.gravity,
                                 triangulation);
    make_wall_conditions ();
    connect_load_balancing ();
    make_bubble_analysis ();
    setup_dofs ();
    set_initial_state ();
    // resolve the initial bed surface: adapt, then impose the initial state anew
    if (parameters.adaptive_refinement.enabled)
      for (unsigned int c = 0; c < parameters.adaptive_refinement.initial_cycles; ++c)
      {
        adapt_mesh ();
        set_initial_state ();
      }
    if (before_writing)
      before_writing ();
    monitors.open (folder + "/monitors.csv",
                   Utilities::MPI::this_mpi_process (communicator) == 0,
                   monitor_columns (),
                   run_id);
    bubble_analysis->open (folder, run_id);
    update_wave_speeds ();
    if (ect_sensor)
      ect_sensor->open (folder, state ());
    if (profiles)
      profiles->open (folder);
  }
  if (parameters.checkpoint.on_signal)
    catch_stop_signals ();
  initialized = true;
}

template <int dim>
void TwoFluidSolver<dim>::resume_from_checkpoint ()
{
  // the checked state, the coarse mesh, the saved mesh and partition, then the DoFs and
  // the fields on them, in the order the checkpoint was written
  const CheckpointState saved = checkpointing.read ();
  boundaries                  = checkpointing.read_coarse_mesh (saved, triangulation);
  make_wall_conditions ();
  make_bubble_analysis ();
  checkpointing.load_mesh (triangulation);
  connect_load_balancing ();
  setup_dofs ();
  FieldTransfer<dim> (flow_dof_handler, alpha_dof_handler)
      .receive (transferred_fields (), flow_owned, alpha_constraints, true);
  bubble_analysis->deserialize ();

  stepping.time               = saved.time;
  stepping.time_step          = saved.time_step;
  stepping.previous_time_step = saved.previous_time_step;
  stepping.step_number        = saved.step_number;
  stepping.rejected_steps     = saved.rejected_steps;
  initial_solids_mass         = saved.initial_solids_mass;
  solids_fed_mass             = saved.solids_fed_mass;
  run_id                      = saved.run_id;
  field_output.restore ({saved.next_output_time, saved.output_index, saved.xdmf_entries});
  make_flow_constraints (stepping.time);

  const std::string output = parameters.output.folder;
  monitors.reopen (output + "/monitors.csv",
                   Utilities::MPI::this_mpi_process (communicator) == 0,
                   saved.monitors_bytes,
                   monitor_columns (),
                   run_id);
  update_wave_speeds ();
  monitors.restore (evaluate_monitors (state ()));
  bubble_analysis->restore_state (saved.bubble_state, output, run_id);
  if (ect_sensor)
  {
    std::vector<std::pair<std::string, unsigned long long>> lengths;
    for (const AppendedFile &file : saved.appended_files)
      lengths.emplace_back (file.name, file.bytes);
    ect_sensor->reopen (output, lengths, state ());
  }
  if (profiles)
  {
    std::vector<std::pair<std::string, unsigned long long>> lengths;
    for (const AppendedFile &file : saved.appended_files)
      lengths.emplace_back (file.name, file.bytes);
    profiles->reopen (output, lengths);
  }
  resumed = true;
  pcout << "Resumed run " << run_id << " from " << checkpointing.source ()
        << " at t = " << stepping.time << " (step " << stepping.step_number << ")"
        << std::endl;
}

template <int dim>
void TwoFluidSolver<dim>::write_checkpoint ()
{
  checkpointing.write (state (),
                       transferred_fields (),
                       *bubble_analysis,
                       {stepping.time_step,
                        monitors.bytes_written (),
                        run_id,
                        field_output.counters (),
                        appended_files ()});
}

template <int dim>
TransferredFields<dim> TwoFluidSolver<dim>::transferred_fields ()
{
  TransferredFields<dim> moved{{&fields.flow, &fields.flow_old, &fields.flow_old2},
                               {&fields.alpha,
                                &fields.alpha_old,
                                &fields.alpha_old2,
                                &fields.theta,
                                &fields.theta_old,
                                &fields.theta_old2}};
  if (time_averages)
  {
    for (auto *v : time_averages->flow_fields ())
      moved.flow.push_back (v);
    for (auto *v : time_averages->scalar_fields ())
      moved.scalars.push_back (v);
  }
  return moved;
}

template <int dim>
void TwoFluidSolver<dim>::adapt_mesh ()
{
  // flags from the state, every field and its history moved with the mesh, then the
  // solids mass the coarsening lost given back (doc/theory.md, "Adaptive meshes")
  TimerOutput::Scope scope (timer, "adaptive refinement");
  // alpha_s at three levels and its time average keep their solids mass
  std::vector<AlphaVector *> levels{&fields.alpha, &fields.alpha_old, &fields.alpha_old2};
  if (time_averages)
    levels.push_back (time_averages->scalar_fields ()[0]);
  mesh_adaptation.prepare (
      state (),
      triangulation,
      std::vector<const AlphaVector *> (levels.begin (), levels.end ()));
  FieldTransfer<dim> transfer (flow_dof_handler, alpha_dof_handler);
  transfer.attach (transferred_fields (), false);
  bubble_analysis->prepare_for_mesh_change ();
  triangulation.execute_coarsening_and_refinement ();
  setup_dofs ();
  transfer.receive (transferred_fields (), flow_owned, alpha_constraints, false);
  bubble_analysis->after_mesh_change ();
  mesh_adaptation.restore_solids_mass (state (), alpha_constraints, levels);
}

template <int dim>
void TwoFluidSolver<dim>::make_wall_conditions ()
{
  wall_conditions = WallConditions (
      boundaries,
      parameters.boundary.wall_choices (),
      parameters.boundary.wall_settings (kinetic_theory, kinetic_theory != nullptr));
}

template <int dim>
MonitorColumns TwoFluidSolver<dim>::monitor_columns () const
{
  return {parameters.output.probe_heights,
          parameters.bed_monitors.pressure_drop_planes,
          static_cast<unsigned int> (parameters.bed_monitors.point_probes.size ()),
          parameters.bed_monitors.pressure_probe_height >= 0,
          parameters.boundary.feeds_solids ()};
}

template <int dim>
void TwoFluidSolver<dim>::set_initial_state ()
{
  const auto          &ic = parameters.initial;
  const Tensor<1, dim> up = upward_direction<dim> (parameters.physical.gravity);
  verification->set_time (stepping.time);

  // solids fraction at the vertices (Q1 nodes)
  const Point<dim>                       origin;
  std::vector<std::pair<double, double>> profile;
  if (ic.hydrostatic_bed)
  {
    // the distinct vertex heights of the whole mesh, ascending
    std::vector<double> local_heights;
    for (const auto &cell : triangulation.active_cell_iterators ())
      if (cell->is_locally_owned ())
        for (const unsigned int v : cell->vertex_indices ())
          local_heights.push_back ((cell->vertex (v) - origin) * up);
    std::vector<double> heights;
    for (const auto &part : Utilities::MPI::all_gather (communicator, local_heights))
      heights.insert (heights.end (), part.begin (), part.end ());
    std::sort (heights.begin (), heights.end ());
    const double merge = 1e-9 * std::max (ic.bed_height, 1e-12);
    heights.erase (std::unique (heights.begin (),
                                heights.end (),
                                [&] (double a, double b) { return b - a < merge; }),
                   heights.end ());
    profile = hydrostatic_profile (heights);
  }
  auto hydrostatic_fraction = [&] (const double height)
  {
    // profile is top down; linear interpolation between the tabulated heights
    for (unsigned int k = 0; k + 1 < profile.size (); ++k)
      if (height >= profile[k + 1].first)
      {
        const double w = (profile[k].first - height) /
                         std::max (profile[k].first - profile[k + 1].first, 1e-300);
        return (1 - std::clamp (w, 0.0, 1.0)) * profile[k].second +
               std::clamp (w, 0.0, 1.0) * profile[k + 1].second;
      }
    return profile.empty () ? 0.0 : profile.back ().second;
  };
  std::vector<types::global_dof_index> dofs (alpha_fe.n_dofs_per_cell ());
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      for (const unsigned int v : cell->vertex_indices ())
      {
        const Point<dim> x = cell->vertex (v);
        double           value;
        if (const Function<dim> *held = verification->held_solids_fraction ())
          value = held->value (x);
        else
        {
          const double height = (x - origin) * up;
          if (ic.hydrostatic_bed)
            value = height <= ic.bed_height + 1e-12 ? hydrostatic_fraction (height)
                                                    : ic.freeboard_solids_fraction;
          else
            value = height <= ic.bed_height + 1e-12 ? ic.bed_solids_fraction
                                                    : ic.freeboard_solids_fraction;
        }
        if (fields.alpha.locally_owned_elements ().is_element (dofs[v]))
          fields.alpha (dofs[v]) = value;
      }
    }
  fields.alpha.zero_out_ghost_values ();
  alpha_constraints.distribute (fields.alpha); // hanging nodes of an adapted mesh
  fields.alpha.update_ghost_values ();
  fields.alpha_old  = fields.alpha;
  fields.alpha_old2 = fields.alpha;
  fields.theta = kinetic_theory ? parameters.kinetic_theory.initial_temperature : 0.0;
  const Function<dim> *exact_theta = verification->exact_granular_temperature ();
  if (kinetic_theory && exact_theta)
    VectorTools::interpolate (mapping, alpha_dof_handler, *exact_theta, fields.theta);
  fields.theta.update_ghost_values ();
  fields.theta_old  = fields.theta;
  fields.theta_old2 = fields.theta;
  make_flow_constraints (0.0); // the inlet gas velocity depends on alpha_s

  TrilinosWrappers::MPI::BlockVector owned_flow (flow_owned, communicator);
  if (const Function<dim> *exact = verification->exact_flow ())
    VectorTools::interpolate (mapping, flow_dof_handler, *exact, owned_flow);
  else if (ic.gas_at_inlet_velocity)
    gas_at_inlet_velocity (owned_flow);
  flow_constraints.distribute (owned_flow);
  fields.flow      = owned_flow;
  fields.flow_old  = owned_flow;
  fields.flow_old2 = owned_flow;

  initial_solids_mass = state ().solids_mass (fields.alpha);
}

template <int dim>
void TwoFluidSolver<dim>::gas_at_inlet_velocity (BlockVector &owned_flow) const
{
  const auto          &ic = parameters.initial;
  const Tensor<1, dim> up = upward_direction<dim> (parameters.physical.gravity);
  const Point<dim>     origin;
  // u_g = U/alpha_g (the superficial velocity carried by the local gas fraction)
  const double                         U           = inlet_superficial_velocity (0.0);
  const double                         alpha_g_bed = 1.0 - ic.bed_solids_fraction;
  const double                         alpha_g_top = 1.0 - ic.freeboard_solids_fraction;
  std::vector<types::global_dof_index> flow_dofs (flow_fe.n_dofs_per_cell ());
  const auto                          &support = flow_fe.get_unit_support_points ();
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (flow_dofs);
      for (unsigned int i = 0; i < flow_dofs.size (); ++i)
      {
        const unsigned int c = flow_fe.system_to_component_index (i).first;
        if (c >= dim || !owned_flow.in_local_range (flow_dofs[i]))
          continue;
        const Point<dim> x      = mapping.transform_unit_to_real_cell (cell, support[i]);
        const double     height = (x - origin) * up;
        const double     ag     = height <= ic.bed_height ? alpha_g_bed : alpha_g_top;
        owned_flow (flow_dofs[i]) = U / ag * up[c];
      }
    }
  owned_flow.compress (VectorOperation::insert);
}

template <int dim>
std::vector<std::pair<double, double>>
TwoFluidSolver<dim>::hydrostatic_profile (const std::vector<double> &heights) const
{
  // The discrete rest state of the well-balanced compaction force (doc/theory.md):
  // from the top down, cell by cell between consecutive vertex heights,
  //   P_s(alpha_k) - P_s(alpha_above) = (z_above - z_k) (rho_s - rho_g)|g|
  //                                      (alpha_k + alpha_above) / 2,
  // with the freeboard fraction above the bed (or P_s = 0 where the bed fills the
  // domain). Each equation is monotone in alpha_k: bisection.
  const auto  &pp       = parameters.physical;
  const auto  &ic       = parameters.initial;
  const double weight   = (pp.particle_density - pp.gas_density) * pp.gravity.norm ();
  auto         pressure = [&] (const double a)
  { return closure_evaluator.compaction_pressure (a); };
  const double tolerance = 1e-9 * std::max (ic.bed_height, 1e-12);
  std::vector<std::pair<double, double>> profile; // (height, alpha), top down
  double                                 alpha_above = -1, z_above = 0;
  for (auto z = heights.rbegin (); z != heights.rend (); ++z)
  {
    if (*z > ic.bed_height + tolerance)
    {
      alpha_above = ic.freeboard_solids_fraction;
      z_above     = *z;
      continue;
    }
    double lo = 0.0, hi = pp.maximum_packing;
    for (unsigned int k = 0; k < 80; ++k)
    {
      const double mid = 0.5 * (lo + hi);
      const double residual =
          alpha_above < 0 ? pressure (mid)
                          : pressure (mid) - pressure (alpha_above) -
                                (z_above - *z) * weight * 0.5 * (mid + alpha_above);
      (residual <= 0 ? lo : hi) = mid;
    }
    alpha_above = 0.5 * (lo + hi);
    z_above     = *z;
    profile.emplace_back (*z, alpha_above);
  }
  return profile;
}

template <int dim>
bool TwoFluidSolver<dim>::try_time_step (const double dt, const unsigned int bdf_order)
{
  const BDFCoefficients bdf =
      bdf_coefficients (bdf_order, dt, stepping.previous_time_step);
  make_flow_constraints (stepping.time + dt);
  stepping.last_krylov_iterations = 0;
  // doc/theory.md "Outer iterations": with an outer tolerance, each iteration after the
  // first tests the flow system re-assembled at the latest iterate before solving it,
  // and each flow solve is inexact (a forcing term of that tolerance)
  const auto &ts = parameters.time;
  const bool  adaptive =
      ts.outer_tolerance > 0 && !verification->runs_all_outer_iterations ();
  AlphaVector alpha_iterate; // alpha_s before the last transport (from k = 1)
  double      alpha_change       = std::numeric_limits<double>::max ();
  double      step_residual      = 0; // |b - A x^n| / |b| at the first iteration
  stepping.last_outer_converged  = !adaptive;
  stepping.last_outer_iterations = 0;
  for (unsigned int k = 0; k < ts.outer_iterations; ++k)
  {
    abandon_step_on_stop (communicator);
    solve_history.set_outer_iteration (k);
    // 1. closures at quadrature points + monolithic (u_g, u_s, p') solve with
    //    P_s(alpha_m) explicit, alpha_m the latest alpha_s (alpha_s^n at k = 0)
    assemble_flow_system (bdf, dt);
    const double floor  = parameters.linear_solver.relative_tolerance;
    double       target = floor;
    if (adaptive)
    {
      TimerOutput::Scope scope (timer, "outer residual");
      const double       residual =
          flow_system.relative_residual (fields.flow, flow_constraints);
      if (k == 0)
        step_residual = residual; // how far x^n is from solving the new step
      if (outer_converged (ts, k, residual, step_residual, alpha_change, floor))
      {
        stepping.last_outer_converged = true;
        break;
      }
      target = std::max (floor,
                         ts.outer_forcing *
                             std::min (residual, ts.outer_tolerance * step_residual));
      if (k == 0 && ts.extrapolate_guess && stepping.step_number > 0 &&
          stepping.previous_time_step > 0)
        extrapolate_flow (dt / stepping.previous_time_step);
    }
    ++stepping.last_outer_iterations;
    const unsigned int iterations =
        flow_system.solve (fields.flow, flow_constraints, target, dt, solve_history);
    if (iterations == numbers::invalid_unsigned_int)
    {
      rejection_reason = "FGMRES did not converge";
      return false;
    }
    stepping.last_krylov_iterations += iterations;
    if (verification->held_solids_fraction ())
    {
      // verification: alpha_s stays the exact field; Theta is solved for where it is
      // exact too
      if (kinetic_theory && verification->exact_granular_temperature () &&
          !update_granular_temperature (bdf, dt))
      {
        return false;
      }
      continue;
    }
    if (adaptive && k > 0 && k + 1 < ts.outer_iterations)
      alpha_iterate = fields.alpha;
    // 2.-3. alpha_s transport and compaction correction (held solids: alpha_s stays)
    if (!parameters.boundary.hold_solids && !advance_solids (bdf, dt))
      return false;
    if (adaptive && k > 0 && k + 1 < ts.outer_iterations)
      alpha_change = largest_change (fields.alpha, alpha_iterate, communicator);
    // 4. granular temperature with the new alpha_s and u_s (PDE or local equilibrium);
    //    it also evolves in a held solids velocity field
    if (kinetic_theory && !update_granular_temperature (bdf, dt))
    {
      return false;
    }
  }
  return admissible ();
}

template <int dim>
bool TwoFluidSolver<dim>::update_granular_temperature (const BDFCoefficients &bdf,
                                                       const double           dt)
{
  const GranularEnergyInputs<dim> inputs{mapping,
                                         alpha_fe,
                                         alpha_dof_handler,
                                         flow_fe,
                                         flow_dof_handler,
                                         alpha_constraints,
                                         boundaries,
                                         wall_conditions,
                                         moving_wall_velocity (),
                                         fields.alpha,
                                         fields.flow,
                                         fields.theta_old,
                                         fields.theta_old2,
                                         closure_evaluator,
                                         *kinetic_theory,
                                         *verification,
                                         bdf,
                                         dt};
  return granular_energy.update (inputs, fields.theta, solve_history, rejection_reason);
}

template <int dim>
bool TwoFluidSolver<dim>::advance_solids (const BDFCoefficients &bdf, const double dt)
{
  return solids_transport.advance ({mapping,
                                    flow_fe,
                                    flow_dof_handler,
                                    flow_owned,
                                    flow_constraints,
                                    alpha_fe,
                                    alpha_dof_handler,
                                    alpha_constraints,
                                    fields.flow_old,
                                    fields.alpha_old,
                                    closure_evaluator,
                                    bdf,
                                    dt},
                                   fields.alpha,
                                   fields.flow,
                                   solve_history,
                                   rejection_reason);
}

template <int dim>
bool TwoFluidSolver<dim>::admissible ()
{
  double lo = std::numeric_limits<double>::max (), hi = -lo;
  for (unsigned int i = 0; i < fields.alpha.locally_owned_size (); ++i)
  {
    lo = std::min (lo, fields.alpha.local_element (i));
    hi = std::max (hi, fields.alpha.local_element (i));
  }
  lo = Utilities::MPI::min (lo, communicator);
  hi = Utilities::MPI::max (hi, communicator);
  BlockVector owned_solution (flow_owned, communicator);
  owned_solution         = fields.flow; // norms need the non-ghosted layout
  const double flow_norm = owned_solution.l2_norm ();
  if (!std::isfinite (flow_norm) || !std::isfinite (hi))
  {
    rejection_reason = "NaN in the solution";
    return false;
  }
  if (lo < -1e-10 || hi > parameters.physical.maximum_packing + 1e-10)
  {
    std::ostringstream reason;
    reason << "alpha_s left [0, maximum packing]: [" << lo << ", " << hi << "]";
    rejection_reason = reason.str ();
    return false;
  }
  return true;
}

template <int dim>
void TwoFluidSolver<dim>::extrapolate_flow (const double ratio)
{
  // x^n + ratio (x^n - x^{n-1}): the linear extrapolation to t_{n+1}; constrained
  // entries are reset by the solve
  BlockVector guess (flow_owned, communicator), older (flow_owned, communicator);
  guess = fields.flow_old;
  older = fields.flow_old2;
  guess.sadd (1.0 + ratio, -ratio, older);
  fields.flow = guess;
}

/**
 * The Oseen-linearised two-fluid system at t_{n+1} about the latest iterate
 * (doc/theory.md, "Discrete flow system"), by the flow terms of this case.
 */
template <int dim>
void TwoFluidSolver<dim>::assemble_flow_system (const BDFCoefficients &bdf,
                                                const double           dt)
{
  if (!flow_system.has_assembler ())
    flow_system.set_assembler (make_flow_assembler<dim> (parameters,
                                                         mapping,
                                                         flow_dof_handler,
                                                         alpha_dof_handler,
                                                         closure_evaluator,
                                                         boundaries,
                                                         wall_conditions,
                                                         moving_wall_velocity (),
                                                         verification));
  const FlowAssemblyState<dim> state{bdf,
                                     dt,
                                     &fields.flow,
                                     &fields.flow_old,
                                     &fields.flow_old2,
                                     &fields.alpha,
                                     &fields.alpha_old,
                                     &fields.alpha_old2,
                                     &fields.theta};
  flow_system.assemble (state, flow_constraints, schur_constraints);
}

template <int dim>
void TwoFluidSolver<dim>::update_wave_speeds ()
{
  wave_speeds = evaluate_wave_speeds (state ());
}

template <int dim>
double TwoFluidSolver<dim>::next_time_step (const double dt) const
{
  if (!parameters.time.adaptive)
    return dt;
  return time_step_controller.next (
      dt, wave_speeds, min_node_spacing, stepping.time_error);
}

template <int dim>
void TwoFluidSolver<dim>::advance ()
{
  const auto &ts = parameters.time;
  double      dt = TimeStepController::step_towards_end (
      stepping.time_step, stepping.time, ts.end_time);
  // save the state to retry from
  const BlockVector saved_flow (fields.flow);
  unsigned int      order         = (stepping.step_number == 0) ? 1 : ts.bdf_order;
  unsigned int      failed_checks = 0; // rejections by a divergence check in a row
  const auto        restore       = [&] ()
  {
    fields.flow  = saved_flow;
    fields.alpha = fields.alpha_old;
    fields.theta = fields.theta_old;
  };
  solve_history.clear ();
  typename DivergenceChecks<dim>::Result checked;
  while (true)
  {
    solve_history.begin_attempt (dt, order);
    bool accepted = false;
    try
    {
      accepted = try_time_step (dt, order);
    }
    catch (const StepInterrupted &)
    {
      // back to the last accepted step, which the run checkpoints
      restore ();
      throw;
    }
    catch (const SolverControl::NoConvergence &failure)
    {
      std::ostringstream reason;
      reason << "a linear solve did not converge (" << failure.last_step
             << " iterations, residual " << failure.last_residual << ")";
      rejection_reason = reason.str ();
      accepted         = false;
    }
    checked = {};
    if (accepted && parameters.divergence_checks.enabled)
    {
      // a converged step must also be physically sane
      TimerOutput::Scope scope (timer, "divergence checks");
      checked = divergence_checks.check (state ());
      if (!checked.passed)
      {
        accepted         = false;
        rejection_reason = checked.reason;
        ++failed_checks;
      }
    }
    if (accepted)
      break;
    solve_history.reject (rejection_reason);
    ++stepping.rejected_steps;
    dt *= 0.5;
    order = 1;
    pcout << "  step rejected at t = " << stepping.time << " (" << rejection_reason
          << "); retrying with dt = " << dt << std::endl;
    if (dt < ts.minimum_time_step)
      stop_diverged ("time step fell below time stepping/minimum time step",
                     checked.where,
                     2 * dt,
                     restore);
    if (!checked.passed && failed_checks > parameters.divergence_checks.retries)
      stop_diverged ("a divergence check failed " + std::to_string (failed_checks) +
                         " times in a row (divergence checks/retries = " +
                         std::to_string (parameters.divergence_checks.retries) + ")",
                     checked.where,
                     2 * dt,
                     restore);
    restore ();
  }
  accept_step (dt, checked.kinetic_energy);
}

template <int dim>
void TwoFluidSolver<dim>::accept_step (const double dt, const double kinetic_energy)
{
  const auto &ts = parameters.time;
  divergence_checks.accept (kinetic_energy);
  stepping.outer_iterations_run += stepping.last_outer_iterations;
  stepping.krylov_iterations_run += stepping.last_krylov_iterations;
  solids_fed_mass +=
      parameters.physical.particle_density * solids_transport.inflow_volume ();
  if (!stepping.last_outer_converged)
    ++stepping.unconverged_steps;
  stepping.time_error = stepping.step_number > 0
                            ? alpha_time_error (fields.alpha,
                                                fields.alpha_old,
                                                fields.alpha_old2,
                                                solids_transport.lumped_mass (),
                                                dt,
                                                stepping.previous_time_step,
                                                communicator)
                            : 0.0;
  // shift history
  fields.flow_old2  = fields.flow_old;
  fields.flow_old   = fields.flow;
  fields.alpha_old2 = fields.alpha_old;
  fields.alpha_old  = fields.alpha;
  fields.theta_old2 = fields.theta_old;
  fields.theta_old  = fields.theta;
  stepping.time += dt;
  stepping.previous_time_step = dt;
  ++stepping.step_number;
  update_wave_speeds ();
  const bool last_step = stepping.time >= parameters.time.end_time * (1 - 1e-12);
  if (stepping.step_number % parameters.output.monitor_interval == 0 || last_step)
    record_monitors ();
  stepping.time_step = next_time_step (dt);
  if (!last_step && stepping.time_step < ts.minimum_time_step)
  {
    // the speeds (or the time error) grew until the next step is below the smallest
    // allowed: the accepted state is the last good one
    std::ostringstream reason;
    reason << "the next time step " << stepping.time_step
           << " s fell below time stepping/minimum time step (Courant limit "
           << time_step_controller.courant_limit (wave_speeds, min_node_spacing)
           << " s; peak speeds: gas " << wave_speeds.gas << " m/s, solids "
           << wave_speeds.solids << " m/s, granular sound " << wave_speeds.granular_sound
           << " m/s; alpha_s time error " << stepping.time_error << ")";
    rejection_reason = reason.str ();
    stop_diverged (reason.str (), "", stepping.time_step, [] () {});
  }
}

template <int dim>
void TwoFluidSolver<dim>::stop_diverged (const std::string            &why,
                                         const std::string            &where,
                                         const double                  dt,
                                         const std::function<void ()> &restore)
{
  // the diagnosis of the failed state, then the last good state saved as fields and as
  // a checkpoint; status 3
  const std::string report = describe_failed_state (dt, where);
  const std::string file   = parameters.output.folder + "/failure_report.txt";
  if (Utilities::MPI::this_mpi_process (communicator) == 0)
    std::ofstream (file) << report;
  pcout << report;
  restore ();
  write_fields ();
  write_checkpoint ();
  throw std::runtime_error (
      why + " at t = " + std::to_string (stepping.time) + " (" + rejection_reason +
      "); diagnosis in " + file + ", the last good state (t = " +
      std::to_string (stepping.time) + ") in checkpoint/ and the last field output");
}

template <int dim>
double TwoFluidSolver<dim>::RunClock::elapsed () const
{
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start)
      .count ();
}

template <int dim>
typename TwoFluidSolver<dim>::RunEnd TwoFluidSolver<dim>::run ()
{
  if (!initialized)
    initialize ();
  const auto &ts = parameters.time;
  RunClock clock{std::chrono::steady_clock::now (), stepping.time, stepping.step_number};
  if (!resumed)
  {
    record_monitors ();
    analyse_bubbles ();
    if (parameters.output.field_interval >= 0)
      write_fields ();
  }
  while (stepping.time < ts.end_time * (1 - 1e-12))
  {
    try
    {
      advance ();
    }
    catch (const StepInterrupted &)
    {
      const auto stopping = std::chrono::steady_clock::now ();
      write_checkpoint ();
      pcout << "Stop requested by a signal during step " << stepping.step_number + 1
            << ": the step was abandoned, the checkpoint holds t = " << stepping.time
            << " (step " << stepping.step_number << "), written in "
            << std::chrono::duration<double> (std::chrono::steady_clock::now () -
                                              stopping)
                   .count ()
            << " s" << std::endl;
      return RunEnd::stopped_by_signal;
    }
    postprocess_step ();
    if (checkpoint_or_stop (clock))
      return RunEnd::stopped_by_signal;
    if (stepping.step_number % parameters.output.progress_interval == 0 ||
        stepping.time >= ts.end_time * (1 - 1e-12))
      report_progress (clock);
  }
  finish_run (clock);
  return RunEnd::finished;
}

template <int dim>
void TwoFluidSolver<dim>::postprocess_step ()
{
  if (parameters.adaptive_refinement.enabled &&
      stepping.step_number % parameters.adaptive_refinement.interval == 0)
  {
    adapt_mesh ();
    update_wave_speeds ();
    stepping.time_step =
        next_time_step (stepping.previous_time_step); // the CFL of the new mesh
  }
  StallWatchdog::report_progress ();
  analyse_bubbles ();
  record_ect ();
  accumulate_averages ();
  // the fields before the checkpoint of the same step: its counters then include this
  // output, which a resumed run would otherwise skip (and write the next one under its
  // number)
  if (field_output.due (stepping.time))
    write_fields ();
}

template <int dim>
bool TwoFluidSolver<dim>::checkpoint_or_stop (RunClock &clock)
{
  // a checkpoint on the step count, the wall clock (rank 0's, for all) or SIGUSR1;
  // SIGTERM/SIGINT/SIGUSR2 write one and stop
  const auto         &checkpoint = parameters.checkpoint;
  const SignalRequest request =
      checkpoint.on_signal ? signal_request (communicator) : SignalRequest::none;
  const double wall = Utilities::MPI::broadcast (communicator, clock.elapsed (), 0);
  const bool   on_clock =
      checkpoint.wall_time_interval > 0 &&
      wall >= clock.next_wall_checkpoint * checkpoint.wall_time_interval;
  if (on_clock)
    clock.next_wall_checkpoint = std::floor (wall / checkpoint.wall_time_interval) + 1;
  if ((checkpoint.interval > 0 && stepping.step_number % checkpoint.interval == 0) ||
      on_clock || request != SignalRequest::none)
    write_checkpoint ();
  if (request == SignalRequest::stop)
  {
    pcout << "Stop requested by a signal at t = " << stepping.time << " (step "
          << stepping.step_number << ")" << std::endl;
    return true;
  }
  return false;
}

template <int dim>
void TwoFluidSolver<dim>::report_progress (const RunClock &clock) const
{
  const double elapsed = clock.elapsed ();
  const double eta     = elapsed / (stepping.time - clock.start_time) *
                     (parameters.time.end_time - stepping.time);
  const auto &row = monitors.last ();
  pcout << "step " << std::setw (6) << stepping.step_number << "  t = " << std::setw (9)
        << std::setprecision (5) << stepping.time << " s  dt = " << std::setw (9)
        << row.time_step << "  outer " << stepping.last_outer_iterations << "  Krylov "
        << std::setw (3) << row.krylov << "  FI " << std::setw (7) << row.fluidization
        << "  alpha_s [" << row.alpha_min << ", " << row.alpha_max << "]  mass drift "
        << std::setprecision (2) << row.mass_drift << "  wall " << std::setprecision (4)
        << elapsed << " s  ETA " << eta << " s" << std::endl;
}

template <int dim>
void TwoFluidSolver<dim>::finish_run (const RunClock &clock)
{
  const auto &checkpoint = parameters.checkpoint;
  if (parameters.output.field_interval == 0)
    write_fields ();
  if (profiles) // at the end too (an output at this time is not repeated)
    profiles->write (state ());
  if (checkpoint.at_end &&
      !(checkpoint.interval > 0 && stepping.step_number % checkpoint.interval == 0))
    write_checkpoint ();
  report_cost (clock);
  timer.print_wall_time_statistics (communicator);
  write_spectra ();
}

template <int dim>
void TwoFluidSolver<dim>::report_cost (const RunClock &clock) const
{
  const auto        &ts         = parameters.time;
  const double       elapsed    = clock.elapsed ();
  const double       start_time = clock.start_time;
  const unsigned int first_step = clock.first_step;
  pcout << "Finished: " << stepping.step_number << " steps (" << stepping.rejected_steps
        << " rejected), wall " << elapsed << " s, "
        << elapsed / std::max (stepping.time - start_time, 1e-300)
        << " s per simulated second, "
        << 1e6 * elapsed / std::max (1u, stepping.step_number - first_step) /
               triangulation.n_global_active_cells ()
        << " us per cell per step (" << triangulation.n_global_active_cells ()
        << " cells at the end); velocity AMG builds " << flow_system.velocity_builds ()
        << std::endl;
  pcout << "Outer iterations: "
        << static_cast<double> (stepping.outer_iterations_run) /
               std::max (1u, stepping.step_number - first_step)
        << " per step";
  if (ts.outer_tolerance > 0 && !verification->runs_all_outer_iterations ())
    pcout << " (" << stepping.unconverged_steps << " steps used all "
          << ts.outer_iterations << ", their last iterate not tested)";
  pcout << "; FGMRES iterations "
        << static_cast<double> (stepping.krylov_iterations_run) /
               std::max (1u, stepping.step_number - first_step)
        << " per step, "
        << static_cast<double> (stepping.krylov_iterations_run) /
               std::max (1u, stepping.outer_iterations_run)
        << " per flow solve" << std::endl;
  {
    dealii::Utilities::System::MemoryStats memory;
    dealii::Utilities::System::get_memory_stats (memory);
    const auto peak =
        dealii::Utilities::MPI::min_max_avg (memory.VmHWM / 1024.0, communicator);
    pcout << "Cost: "
          << 1e6 * elapsed / std::max (1u, stepping.step_number - first_step) /
                 flow_dof_handler.n_dofs ()
          << " us per flow DoF per step (" << flow_dof_handler.n_dofs ()
          << " flow DoFs, operator " << flow_system.krylov_operator ().name ()
          << "), peak memory " << peak.max << " MB per rank (max), " << peak.sum
          << " MB in all = " << 1024.0 * peak.sum / flow_dof_handler.n_dofs ()
          << " kB per flow DoF" << std::endl;
    const auto parts = flow_system.memory_consumption ();
    const auto sum   = [&] (const std::size_t bytes)
    { return dealii::Utilities::MPI::sum (static_cast<double> (bytes), communicator); };
    const double n = flow_dof_handler.n_dofs ();
    pcout << "Flow solve memory (all ranks, bytes per flow DoF): operator "
          << sum (parts.op) / n << ", L_c " << sum (parts.schur) / n << ", p-multigrid "
          << sum (parts.multigrid) / n << ", vectors " << sum (parts.vectors) / n
          << " (ML hierarchies not counted)" << std::endl;
  }
}

template class TwoFluidSolver<2>;
template class TwoFluidSolver<3>;
} // namespace wetbed
