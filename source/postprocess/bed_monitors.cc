#include <wetbed/postprocess/spectrum.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <fstream>
#include <sstream>

namespace wetbed
{
using namespace dealii;

/**
 * Monitors of the bed after a step: pressure drop (mean p' over the inlet minus the
 * mean over the outlet), fluidization index FI = dP A / ((M_s (1 - rho_g/rho_s)) |g|)
 * (p' excludes the gas hydrostatic part, so the bed weight is taken net of buoyancy),
 * the shares of the bed weight the walls and the distributor carry (wall_forces.cc),
 * solids mass and drift, bounds, peak speeds, the bed height (95% of the solids below
 * it) and, at each probe height, alpha_s averaged over the layer of cells that contains
 * it (heights along -g from the coordinate origin, the inlet plane of the shipped
 * meshes; the cells straddling the height, volume-weighted).
 */
template <int dim>
MonitorRow TwoFluidSolver<dim>::evaluate_monitors () const
{
  MonitorRow row;
  row.active_cells   = triangulation.n_global_active_cells ();
  row.step           = step_number;
  row.time           = time;
  row.time_step      = previous_time_step;
  row.inlet_velocity = inlet_superficial_velocity (time);
  row.krylov         = last_krylov_iterations;
  row.rejected       = rejected_steps;

  const QGauss<dim - 1> face_quadrature (3);
  FEFaceValues<dim>     face_values (
      mapping, flow_fe, face_quadrature, update_values | update_JxW_values);
  const FEValuesExtractors::Scalar pressure (2 * dim);
  std::vector<double>              p (face_quadrature.size ());
  double inlet_integral = 0, inlet_area = 0, outlet_integral = 0, outlet_area = 0;
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
      for (const auto &face : cell->face_iterators ())
        if (face->at_boundary () &&
            (boundaries.is (face->boundary_id (), BoundaryType::inlet) ||
             boundaries.is (face->boundary_id (), BoundaryType::outlet)))
        {
          face_values.reinit (cell, face);
          face_values[pressure].get_function_values (flow_solution, p);
          const bool inlet = boundaries.is (face->boundary_id (), BoundaryType::inlet);
          for (unsigned int q = 0; q < face_quadrature.size (); ++q)
          {
            (inlet ? inlet_integral : outlet_integral) += p[q] * face_values.JxW (q);
            (inlet ? inlet_area : outlet_area) += face_values.JxW (q);
          }
        }
  inlet_integral  = Utilities::MPI::sum (inlet_integral, communicator);
  inlet_area      = Utilities::MPI::sum (inlet_area, communicator);
  outlet_integral = Utilities::MPI::sum (outlet_integral, communicator);
  outlet_area     = Utilities::MPI::sum (outlet_area, communicator);
  // a closed or periodic domain has no inlet or outlet: no pressure drop, no FI
  row.pressure_drop = inlet_area > 0 && outlet_area > 0
                          ? inlet_integral / inlet_area - outlet_integral / outlet_area
                          : 0.0;

  const auto &pp  = parameters.physical;
  row.solids_mass = solids_mass (alpha);
  row.mass_drift =
      initial_solids_mass > 0 ? row.solids_mass / initial_solids_mass - 1 : 0;
  const double weight =
      row.solids_mass * (1 - pp.gas_density / pp.particle_density) * pp.gravity.norm ();
  row.fluidization = weight > 0 ? row.pressure_drop * inlet_area / weight : 0;
  if (weight > 0)
  {
    const WallForces forces               = evaluate_wall_forces ();
    row.wall_support_solids               = forces.solids_wall / weight;
    row.wall_support_gas                  = forces.gas_wall / weight;
    row.distributor_support               = forces.distributor / weight;
    row.outlet_support                    = forces.outlet / weight;
    const InertialBudget inertia          = evaluate_inertial_budget (previous_time_step);
    row.mixture_momentum                  = inertia.momentum / weight;
    row.continuity_defect                 = inertia.continuity_defect / weight;
    row.momentum_outflow                  = inertia.momentum_outflow / weight;
    const std::array<double, 3> reactions = evaluate_boundary_reactions ();
    row.inlet_reaction                    = reactions[0] / weight;
    row.wall_reaction                     = reactions[1] / weight;
    row.outlet_reaction                   = reactions[2] / weight;
    row.correction_force =
        previous_time_step > 0 ? correction_momentum / (previous_time_step * weight) : 0;
  }

  double lo = std::numeric_limits<double>::max (), hi = -lo;
  for (unsigned int i = 0; i < alpha.locally_owned_size (); ++i)
  {
    lo = std::min (lo, alpha.local_element (i));
    hi = std::max (hi, alpha.local_element (i));
  }
  row.alpha_min = Utilities::MPI::min (lo, communicator);
  row.alpha_max = Utilities::MPI::max (hi, communicator);

  const WaveSpeeds speeds  = evaluate_wave_speeds ();
  row.gas_speed_max        = speeds.gas;
  row.solids_speed_max     = speeds.solids;
  row.granular_sound_speed = speeds.granular_sound;

  // bed height: 95% of the solids lie below it (nodal masses sorted by height)
  const Tensor<1, dim>                   up = upward_direction<dim> (pp.gravity);
  std::vector<std::pair<double, double>> height_mass;
  const auto                            &mass = transport.lumped_mass ();
  std::vector<types::global_dof_index>   alpha_dofs (alpha_fe.n_dofs_per_cell ());
  std::vector<bool>                      seen (alpha.locally_owned_size (), false);
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (alpha_dofs);
      for (const unsigned int v : cell->vertex_indices ())
        if (alpha.locally_owned_elements ().is_element (alpha_dofs[v]))
        {
          const unsigned int local =
              alpha.get_partitioner ()->global_to_local (alpha_dofs[v]);
          if (seen[local])
            continue;
          seen[local] = true;
          height_mass.emplace_back (cell->vertex (v) * up,
                                    mass.local_element (local) *
                                        alpha.local_element (local));
        }
    }
  const auto all = Utilities::MPI::all_gather (communicator, height_mass);
  std::vector<std::pair<double, double>> merged;
  for (const auto &part : all)
    merged.insert (merged.end (), part.begin (), part.end ());
  std::sort (merged.begin (), merged.end ());

  // granular temperature: extremes over the nodes, mean weighted by the solids mass
  if (kinetic_theory)
  {
    double lo = std::numeric_limits<double>::max (), hi = 0, weighted = 0, weight = 0;
    for (unsigned int i = 0; i < theta.locally_owned_size (); ++i)
    {
      lo             = std::min (lo, theta.local_element (i));
      hi             = std::max (hi, theta.local_element (i));
      const double m = mass.local_element (i) * alpha.local_element (i);
      weighted += m * theta.local_element (i);
      weight += m;
    }
    row.theta_min = Utilities::MPI::min (lo, communicator);
    row.theta_max = Utilities::MPI::max (hi, communicator);
    weight        = Utilities::MPI::sum (weight, communicator);
    row.theta_mean =
        weight > 0 ? Utilities::MPI::sum (weighted, communicator) / weight : 0;
    row.granular_energy = granular_energy_budget;
  }
  evaluate_bed_profile (row);
  double total = 0;
  for (const auto &hm : merged)
    total += hm.second;
  double running = 0;
  for (const auto &hm : merged)
  {
    running += hm.second;
    if (running >= 0.95 * total)
    {
      row.bed_height = hm.first;
      break;
    }
  }
  return row;
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
      step_number % parameters.bubble_analysis.interval != 0)
    return;
  TimerOutput::Scope scope (timer, "bubble analysis");
  alpha.update_ghost_values ();
  bubble_analysis->analyse (step_number, time, mapping, alpha_dof_handler, alpha);
}

template <int dim>
void TwoFluidSolver<dim>::write_spectra () const
{
  const auto &sp = parameters.spectrum;
  if (!sp.enabled || time <= sp.start_time ||
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
  }
  catch (const std::invalid_argument &e) // too few samples: the run is too short
  {
    pcout << "Spectrum: not written (" << e.what () << ")" << std::endl;
  }
}

template MonitorRow TwoFluidSolver<2>::evaluate_monitors () const;
template MonitorRow TwoFluidSolver<3>::evaluate_monitors () const;
template void       TwoFluidSolver<2>::make_bubble_analysis ();
template void       TwoFluidSolver<3>::make_bubble_analysis ();
template void       TwoFluidSolver<2>::analyse_bubbles ();
template void       TwoFluidSolver<3>::analyse_bubbles ();
template void       TwoFluidSolver<2>::write_spectra () const;
template void       TwoFluidSolver<3>::write_spectra () const;
} // namespace wetbed
