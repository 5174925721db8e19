#include <wetbed/postprocess/bed_monitors.h>
#include <wetbed/postprocess/point_sampling.h>
#include <wetbed/postprocess/spectrum.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/mpi.h>

#include <fstream>
#include <sstream>

/*
 * The solver's side of the postprocessing: the read-only view of its state that the
 * postprocessors (source/postprocess/) take, and when each runs.
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
SolverState<dim> TwoFluidSolver<dim>::state () const
{
  return SolverState<dim>{parameters,
                          communicator,
                          triangulation,
                          boundaries,
                          wall_conditions,
                          mapping,
                          flow_fe,
                          flow_dof_handler,
                          alpha_fe,
                          alpha_dof_handler,
                          solids_transport.lumped_mass (),
                          fields.flow,
                          fields.flow_old2, // after the step the history has shifted
                          fields.alpha,
                          fields.alpha_old2,
                          fields.theta,
                          closure_evaluator,
                          kinetic_theory,
                          flow_system,
                          moving_wall_velocity (),
                          stepping.time,
                          stepping.previous_time_step,
                          inlets.mean_superficial_velocity (stepping.time),
                          inlets.peak_superficial_velocity (stepping.time),
                          stepping.step_number,
                          stepping.rejected_steps,
                          stepping.last_krylov_iterations,
                          initial_solids_mass,
                          solids_fed_mass,
                          solids_transport.correction_momentum (),
                          granular_energy.budget (),
                          wave_speeds,
                          stepping.time_error,
                          time_averages.get ()};
}

template <int dim>
std::vector<std::vector<double>>
TwoFluidSolver<dim>::sample (const std::vector<Point<dim>> &points) const
{
  return sample_fields (state (), points);
}

template <int dim>
void TwoFluidSolver<dim>::record_monitors ()
{
  TimerOutput::Scope scope (timer, "monitors");
  MonitorRow         row = evaluate_monitors (state ());
  if (pressure_probe)
    pressure_probe->fill (state (), row);
  monitors.add (row);
  // rank 0 writes: all stop together when its file lost a row
  if (Utilities::MPI::broadcast (communicator, monitors.writing_failed (), 0))
    throw std::runtime_error (
        "output/folder: cannot append to '" + parameters.output.folder +
        "/monitors.csv' at t = " + std::to_string (stepping.time) +
        " (disk full or not writable); the last checkpoint is kept");
}

template <int dim>
void TwoFluidSolver<dim>::make_bubble_analysis ()
{
  BubbleCriteria criteria;
  criteria.gas_fraction_threshold = parameters.bubble_analysis.gas_fraction_threshold;
  criteria.minimum_diameter       = parameters.bubble_analysis.minimum_diameter;
  criteria.freeboard_boundaries   = boundaries.ids (BoundaryType::outlet);
  criteria.open_boundaries = boundaries.ids ({BoundaryType::inlet, BoundaryType::outlet});
  unsigned int         vertical = 0; // the axis gravity points along
  const Tensor<1, dim> up       = upward_direction<dim> (parameters.physical.gravity);
  for (unsigned int d = 1; d < dim; ++d)
    if (std::abs (up[d]) > std::abs (up[vertical]))
      vertical = d;
  bubble_analysis = std::make_unique<BubbleAnalysis<dim>> (
      parameters.bubble_analysis, criteria, triangulation, vertical, communicator);
}

template <int dim>
void TwoFluidSolver<dim>::analyse_bubbles ()
{
  if (!parameters.bubble_analysis.enabled ||
      stepping.step_number % parameters.bubble_analysis.interval != 0)
    return;
  TimerOutput::Scope scope (timer, "bubble analysis");
  fields.alpha.update_ghost_values ();
  bubble_analysis->analyse (
      stepping.step_number, stepping.time, mapping, alpha_dof_handler, fields.alpha);
}

template <int dim>
void TwoFluidSolver<dim>::record_ect ()
{
  if (!ect_sensor)
    return;
  TimerOutput::Scope scope (timer, "ECT sensor");
  fields.alpha.update_ghost_values ();
  ect_sensor->record (state (), stepping.time_step); // (the next step's, planned)
  if (Utilities::MPI::broadcast (communicator, ect_sensor->writing_failed (), 0))
    throw std::runtime_error (
        "output/folder: cannot append to '" + parameters.output.folder +
        "/ect.csv' at t = " + std::to_string (stepping.time) +
        " (disk full or not writable); the last checkpoint is kept");
}

template <int dim>
void TwoFluidSolver<dim>::accumulate_averages ()
{
  if (!time_averages)
    return;
  TimerOutput::Scope scope (timer, "time averages");
  BlockVector        owned (flow_owned, communicator);
  time_averages->add (stepping.time,
                      stepping.previous_time_step,
                      fields.flow,
                      fields.alpha,
                      fields.theta,
                      owned);
}

template <int dim>
void TwoFluidSolver<dim>::write_fields ()
{
  field_output.write (state ());
  if (!profiles)
    return;
  TimerOutput::Scope scope (timer, "profiles");
  profiles->write (state ());
  if (Utilities::MPI::broadcast (communicator, profiles->writing_failed (), 0))
    throw std::runtime_error (
        "output/folder: could not write the profiles in '" + parameters.output.folder +
        "/statistics' at t = " + std::to_string (stepping.time) + " (disk full?)");
}

template <int dim>
std::vector<std::pair<std::string, unsigned long long>>
TwoFluidSolver<dim>::appended_files ()
{
  std::vector<std::pair<std::string, unsigned long long>> files;
  if (ect_sensor)
    files = ect_sensor->file_lengths ();
  if (profiles)
    for (const auto &file : profiles->file_lengths ())
      files.push_back (file);
  return files;
}

template <int dim>
void TwoFluidSolver<dim>::write_spectra () const
{
  const auto &sp = parameters.spectrum;
  if (!sp.enabled || stepping.time <= sp.start_time ||
      Utilities::MPI::this_mpi_process (communicator) != 0)
    return;
  const std::string folder = parameters.output.folder;
  try
  {
    std::ostringstream table;
    write_monitor_spectra (
        folder + "/monitors.csv", {}, sp.start_time, sp.segments, table);
    std::ofstream (folder + "/spectrum.csv") << table.str ();
    std::istringstream lines (table.str ());
    for (std::string line; std::getline (lines, line) && line[0] == '#';)
      pcout << "Spectrum " << line.substr (2) << std::endl;
    if (ect_sensor)
    {
      std::ostringstream ect;
      write_monitor_spectra (folder + "/" + EctSensor<dim>::signal_file,
                             {"alpha_s_slab"},
                             sp.start_time,
                             sp.segments,
                             ect);
      std::ofstream (folder + "/ect_spectrum.csv") << ect.str ();
      std::istringstream ect_lines (ect.str ());
      std::string        line;
      if (std::getline (ect_lines, line) && line[0] == '#')
        pcout << "Spectrum (ECT) " << line.substr (2) << std::endl;
    }
  }
  catch (const std::invalid_argument &e) // too few samples: the run is too short
  {
    pcout << "Spectrum: not written (" << e.what () << ")" << std::endl;
  }
}

template SolverState<2> TwoFluidSolver<2>::state () const;
template SolverState<3> TwoFluidSolver<3>::state () const;
template std::vector<std::vector<double>>
TwoFluidSolver<2>::sample (const std::vector<Point<2>> &) const;
template std::vector<std::vector<double>>
              TwoFluidSolver<3>::sample (const std::vector<Point<3>> &) const;
template void TwoFluidSolver<2>::record_monitors ();
template void TwoFluidSolver<3>::record_monitors ();
template void TwoFluidSolver<2>::record_ect ();
template void TwoFluidSolver<3>::record_ect ();
template void TwoFluidSolver<2>::accumulate_averages ();
template void TwoFluidSolver<3>::accumulate_averages ();
template void TwoFluidSolver<2>::make_bubble_analysis ();
template void TwoFluidSolver<3>::make_bubble_analysis ();
template void TwoFluidSolver<2>::analyse_bubbles ();
template void TwoFluidSolver<3>::analyse_bubbles ();
template void TwoFluidSolver<2>::write_fields ();
template void TwoFluidSolver<3>::write_fields ();
template std::vector<std::pair<std::string, unsigned long long>>
TwoFluidSolver<2>::appended_files ();
template std::vector<std::pair<std::string, unsigned long long>>
              TwoFluidSolver<3>::appended_files ();
template void TwoFluidSolver<2>::write_spectra () const;
template void TwoFluidSolver<3>::write_spectra () const;
} // namespace wetbed
