#pragma once

#include <wetbed/assembly/granular_energy_budget.h>

#include <fstream>
#include <string>
#include <vector>

namespace wetbed
{
/** One row of monitors.csv: the state of the bed after an accepted step. */
struct MonitorRow
{
  unsigned int step           = 0;
  double       time           = 0;
  double       time_step      = 0;
  double       inlet_velocity = 0; // superficial gas velocity U(t) at the inlet (m/s)
  unsigned int krylov         = 0; // FGMRES iterations summed over the outer iterations
  unsigned int rejected       = 0; // rejected attempts so far
  double       pressure_drop = 0; // mean p' on the inlet minus mean p' on the outlet (Pa)
  double       fluidization  = 0; // pressure_drop * A / (buoyant bed weight)
  // the bed weight carried by the boundaries, as fractions of the buoyant bed weight
  // (time mean: FI + the three ~ 1): friction of the walls on the solids, viscous
  // traction of the walls on the gas, normal stress of the distributor and of the
  // outlet grid on the solids
  double wall_support_solids = 0, wall_support_gas = 0, distributor_support = 0,
         outlet_support = 0;
  // the inertial side of the budget (momentum_budget.cc): mixture momentum along -g over
  // the buoyant weight (s), and as shares of the weight the conservative momentum change
  // minus the assembled inertia and the momentum flux out of the domain; at every step
  // inlet + wall + outlet reactions + wall_support_solids + continuity_defect
  // - momentum_outflow + correction_force - d(mixture_momentum)/dt = 1
  double mixture_momentum = 0, continuity_defect = 0, momentum_outflow = 0;
  // the momentum the velocity half of the compaction correction added, per step length,
  // as a share of the weight (it is not a boundary force: with drag, only part of the
  // compaction force reaches the solids momentum)
  double correction_force = 0;
  // the consistent forces of the inlet, walls and outlet on the mixture (the reactions
  // of their velocity rows) as shares of the weight; inlet: the discrete counterpart of
  // FI + distributor_support
  double inlet_reaction = 0, wall_reaction = 0, outlet_reaction = 0;
  // the gas mass flows in through the inlets and out through the outlets (kg/s, per
  // metre depth in 2D)
  double gas_inflow = 0, gas_outflow = 0;
  double solids_mass = 0; // kg (per metre depth in 2D)
  double mass_drift  = 0; // relative change of the solids mass since t = 0, the
                          // fed mass taken out
  double alpha_min        = 0;
  double alpha_max        = 0;
  double gas_speed_max    = 0;
  double solids_speed_max = 0;
  double time_error       = 0; // alpha_s's local time-error estimate of the step
  double bed_height       = 0; // height below which 95% of the solids lie
  double theta_min = 0, theta_mean = 0, theta_max = 0; // Theta (mean: solids-weighted)
  double granular_sound_speed = 0; // max sqrt(2 P_kin/(alpha_s rho_s)) (m/s)
  GranularEnergyBudget granular_energy;
  std::vector<double>  plane_alpha;      // alpha_s averaged over the probe cell layers
  unsigned long long   active_cells = 0; // of the (adapted) mesh
  // bed monitors (subsection bed monitors)
  // layer-averaged p' at the first plane minus the second (one entry, or none)
  std::vector<double> plane_pressure_drop;
  double bed_surface_height = 0; // top of the highest slice with mean alpha_s above
  double expansion_ratio    = 0; // bed_surface_height / initial bed height
  std::vector<double> probe_alpha, probe_pressure; // at the point probes
  // the pressure probe (bed monitors/pressure probe height): the cross-section mean of
  // p' there minus the outlet's, and the FI from it (dP A over the buoyant bed weight);
  // empty without one
  std::vector<double> pressure_probe;
  // the solids mass fed through the inlets since t = 0 (kg, per metre depth in 2D);
  // empty when no inlet feeds solids
  std::vector<double> solids_fed;
};

/** The optional columns of monitors.csv. */
struct MonitorColumns
{
  std::vector<double> probe_heights;        // alpha_s_plane_<height>
  std::vector<double> pressure_drop_planes; // pressure_drop_<a>_<b> (two heights or none)
  unsigned int        point_probes = 0;     // probe_<i>_alpha_s, probe_<i>_pressure
  bool pressure_probe = false; // probe_pressure_drop, probe_fluidization_index
  bool solids_feed    = false; // solids_fed_mass
};

/** Collects MonitorRows and writes them (rank 0) to a CSV file; its last column, run,
 * holds the run's id on every row (the id its checkpoints carry). */
class Monitors
{
public:
  void open (const std::string    &filename,
             bool                  write,
             const MonitorColumns &columns,
             const std::string    &run_id);
  /** Continues `filename` of a resumed run: cut back to its first `bytes` (the rows up
   * to the checkpoint) and appended to from there. Rows written with other `columns`
   * (an earlier version) are rewritten under the current header, by column name, with
   * the columns they lack left empty (run: `run_id`). */
  void reopen (const std::string    &filename,
               bool                  write,
               unsigned long long    bytes,
               const MonitorColumns &columns,
               const std::string    &run_id);
  /** Bytes of monitors.csv written so far (rank 0; 0 elsewhere). */
  unsigned long long bytes_written ();
  /** Makes `row` the last row without writing it (a resumed run's last saved state). */
  void restore (const MonitorRow &row) { rows.push_back (row); }
  void add (const MonitorRow &row);
  /** Whether a write to the file has failed (disk full): rows are missing from it. */
  bool              writing_failed () const { return file.is_open () && !file; }
  const MonitorRow &last () const { return rows.back (); }
  const std::vector<MonitorRow> &all () const { return rows; }

private:
  std::ofstream           file;
  std::string             run; // the run's id
  std::vector<MonitorRow> rows;
};
} // namespace wetbed
