#include <wetbed/postprocess/csv_append.h>
#include <wetbed/postprocess/monitors.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace wetbed
{
namespace
{
std::string header (const MonitorColumns &columns)
{
  std::ostringstream file;
  file
      << "step,time,time_step,inlet_superficial_velocity,krylov_iterations,rejected_"
         "steps,pressure_drop,"
         "fluidization_index,solids_mass,solids_mass_drift,alpha_s_min,alpha_s_max,"
         "gas_speed_max,solids_speed_max,bed_height,theta_min,theta_mean,theta_max,"
         "granular_production,granular_dissipation,granular_drag_exchange,"
         "granular_wall_flux,active_cells,bed_surface_height,expansion_ratio,"
         "wall_support_solids,wall_support_gas,distributor_support,outlet_support,"
         "mixture_momentum,continuity_defect,momentum_outflow,correction_force,"
         "inlet_reaction,wall_reaction,outlet_reaction,gas_inflow,gas_outflow,time_error";
  for (const double h : columns.probe_heights)
    file << ",alpha_s_plane_" << h;
  if (columns.pressure_drop_planes.size () == 2)
    file << ",pressure_drop_" << columns.pressure_drop_planes[0] << '_'
         << columns.pressure_drop_planes[1];
  for (unsigned int i = 0; i < columns.point_probes; ++i)
    file << ",probe_" << i << "_alpha_s,probe_" << i << "_pressure";
  if (columns.pressure_probe)
    file << ",probe_pressure_drop,probe_fluidization_index";
  if (columns.solids_feed)
    file << ",solids_fed_mass";
  file << ",run"; // the run's id, last: the columns before keep their places
  return file.str ();
}

std::vector<std::string> split (const std::string &line)
{
  std::vector<std::string> fields;
  std::istringstream       in (line);
  for (std::string field; std::getline (in, field, ',');)
    fields.push_back (field);
  if (!line.empty () && line.back () == ',')
    fields.emplace_back ();
  return fields;
}
} // namespace

void Monitors::open (const std::string    &filename,
                     const bool            write,
                     const MonitorColumns &columns,
                     const std::string    &run_id)
{
  run = run_id;
  if (!write)
    return;
  file.open (filename);
  file << header (columns) << '\n';
}

void Monitors::reopen (const std::string       &filename,
                       const bool               write,
                       const unsigned long long bytes,
                       const MonitorColumns    &columns,
                       const std::string       &run_id)
{
  run = run_id;
  if (!write)
    return;
  continue_csv (file, filename, bytes);
  file.close ();
  std::ifstream            in (filename);
  std::vector<std::string> lines;
  for (std::string line; std::getline (in, line);)
    lines.push_back (line);
  in.close ();
  const std::string current = header (columns);
  if (!lines.empty () && lines[0] != current)
  {
    // written by a version with other columns: the rows so far are rewritten under the
    // current header, each column found by name, the new ones left empty (the run
    // column gets the run's id: the checkpoint identified the rows as its own); into a
    // temporary file renamed over the old one, so a failure leaves the old file whole
    const std::vector<std::string> old_names = split (lines[0]), names = split (current);
    const std::string              temporary = filename + ".rewrite";
    {
      std::ofstream out (temporary);
      out << current << '\n';
      for (std::size_t l = 1; l < lines.size (); ++l)
      {
        const std::vector<std::string> values = split (lines[l]);
        for (std::size_t c = 0; c < names.size (); ++c)
        {
          const auto k = std::find (old_names.begin (), old_names.end (), names[c]) -
                         old_names.begin ();
          const bool found = k < static_cast<long> (old_names.size ()) &&
                             k < static_cast<long> (values.size ());
          out << (c > 0 ? "," : "")
              << (found               ? values[k]
                  : names[c] == "run" ? run
                                      : std::string ());
        }
        out << '\n';
      }
      if (!out)
        throw std::runtime_error ("checkpoint/resume: cannot rewrite " + filename +
                                  " with the current monitor columns");
    }
    std::filesystem::rename (temporary, filename);
  }
  file.open (filename, std::ios::app);
}

unsigned long long Monitors::bytes_written ()
{
  return file.is_open () ? static_cast<unsigned long long> (file.tellp ()) : 0;
}

void Monitors::add (const MonitorRow &r)
{
  rows.push_back (r);
  if (!file.is_open ())
    return;
  file << r.step << ',' << std::setprecision (15) << r.time << ',' << r.time_step << ','
       << r.inlet_velocity << ',' << r.krylov << ',' << r.rejected << ','
       << r.pressure_drop << ',' << r.fluidization << ',' << std::setprecision (15)
       << r.solids_mass << ',' << r.mass_drift << ',' << std::setprecision (15)
       << r.alpha_min << ',' << r.alpha_max << ',' << r.gas_speed_max << ','
       << r.solids_speed_max << ',' << r.bed_height << ',' << r.theta_min << ','
       << r.theta_mean << ',' << r.theta_max << ',' << r.granular_energy.production << ','
       << r.granular_energy.dissipation << ',' << r.granular_energy.drag_exchange << ','
       << r.granular_energy.wall_flux << ',' << r.active_cells << ','
       << r.bed_surface_height << ',' << r.expansion_ratio << ',' << r.wall_support_solids
       << ',' << r.wall_support_gas << ',' << r.distributor_support << ','
       << r.outlet_support << ',' << r.mixture_momentum << ',' << r.continuity_defect
       << ',' << r.momentum_outflow << ',' << r.correction_force << ','
       << r.inlet_reaction << ',' << r.wall_reaction << ',' << r.outlet_reaction << ','
       << r.gas_inflow << ',' << r.gas_outflow << ',' << r.time_error;
  for (const double a : r.plane_alpha)
    file << ',' << a;
  for (const double dp : r.plane_pressure_drop)
    file << ',' << dp;
  for (unsigned int i = 0; i < r.probe_alpha.size (); ++i)
    file << ',' << r.probe_alpha[i] << ',' << r.probe_pressure[i];
  for (const double value : r.pressure_probe)
    file << ',' << value;
  for (const double value : r.solids_fed)
    file << ',' << std::setprecision (15) << value;
  file << ',' << run << '\n';
  file.flush ();
}
} // namespace wetbed
