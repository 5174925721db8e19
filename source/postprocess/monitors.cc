#include <wetbed/postprocess/csv_append.h>
#include <wetbed/postprocess/monitors.h>

#include <filesystem>
#include <iomanip>
#include <stdexcept>

namespace wetbed
{
void Monitors::open (const std::string    &filename,
                     const bool            write,
                     const MonitorColumns &columns)
{
  if (!write)
    return;
  file.open (filename);
  file << "step,time,time_step,inlet_superficial_velocity,krylov_iterations,rejected_"
          "steps,pressure_drop,"
          "fluidization_index,solids_mass,solids_mass_drift,alpha_s_min,alpha_s_max,"
          "gas_speed_max,solids_speed_max,bed_height,theta_min,theta_mean,theta_max,"
          "granular_production,granular_dissipation,granular_drag_exchange,"
          "granular_wall_flux,active_cells,bed_surface_height,expansion_ratio";
  for (const double h : columns.probe_heights)
    file << ",alpha_s_plane_" << h;
  if (columns.pressure_drop_planes.size () == 2)
    file << ",pressure_drop_" << columns.pressure_drop_planes[0] << '_'
         << columns.pressure_drop_planes[1];
  for (unsigned int i = 0; i < columns.point_probes; ++i)
    file << ",probe_" << i << "_alpha_s,probe_" << i << "_pressure";
  file << '\n';
}

void Monitors::reopen (const std::string       &filename,
                       const bool               write,
                       const unsigned long long bytes)
{
  if (!write)
    return;
  continue_csv (file, filename, bytes);
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
       << r.bed_surface_height << ',' << r.expansion_ratio;
  for (const double a : r.plane_alpha)
    file << ',' << a;
  for (const double dp : r.plane_pressure_drop)
    file << ',' << dp;
  for (unsigned int i = 0; i < r.probe_alpha.size (); ++i)
    file << ',' << r.probe_alpha[i] << ',' << r.probe_pressure[i];
  file << '\n';
  file.flush ();
}
} // namespace wetbed
