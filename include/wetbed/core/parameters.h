#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <wetbed/core/adaptive_refinement_parameters.h>
#include <wetbed/core/bed_monitor_parameters.h>
#include <wetbed/core/boundary_condition_parameters.h>
#include <wetbed/core/bubble_analysis_parameters.h>
#include <wetbed/core/checkpoint_parameters.h>
#include <wetbed/core/divergence_check_parameters.h>
#include <wetbed/core/ect_sensor_parameters.h>
#include <wetbed/core/kinetic_theory_parameters.h>
#include <wetbed/core/mesh_parameters.h>
#include <wetbed/core/momentum_form.h>
#include <wetbed/core/physical_properties.h>
#include <wetbed/core/solids_stress_parameters.h>
#include <wetbed/core/spectrum_parameters.h>
#include <wetbed/core/statistics_parameters.h>
#include <wetbed/core/wet_particle_parameters.h>

#include <map>
#include <string>

namespace wetbed
{
/** `subsection initial conditions`. */
struct InitialConditionParameters
{
  double bed_height;
  double bed_solids_fraction;
  double freeboard_solids_fraction;
  bool   gas_at_inlet_velocity; // start with u_g = U/alpha_g everywhere
  bool   hydrostatic_bed;       // alpha_s(z) from dP_s/dz = -alpha_s (rho_s - rho_g) g

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm, double maximum_packing);
};

/** `subsection time stepping`. */
struct TimeSteppingParameters
{
  double       end_time, initial_time_step, maximum_time_step, minimum_time_step;
  double       cfl_target;           // on the phase velocities per Q2 node spacing
  bool         local_courant;        // each cell's speeds on its own node spacing
  double       time_error_tolerance; // of the alpha_s local error estimate (0: off)
  double       transport_cfl;        // per explicit alpha sub-step
  double       growth_factor;        // largest step-to-step growth
  unsigned int bdf_order;            // 1 or 2
  unsigned int outer_iterations;     // the most per step
  double       outer_tolerance;      // converged: relative flow residual (0: fixed count)
  double       outer_alpha_tolerance; // and max |alpha_s change| between iterates
  double       outer_forcing;     // linear solves to this fraction of the outer tolerance
  bool         extrapolate_guess; // first solve from the extrapolated flow iterate
  bool         adaptive;

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};

/** `subsection linear solver`. */
struct LinearSolverParameters
{
  double       relative_tolerance, scalar_tolerance;
  unsigned int maximum_iterations, restart;
  std::string  smoother;
  std::string  inner_solves; // V-cycle (default), exact or exact velocity (diagnosis)
  unsigned int smoother_sweeps;
  unsigned int multigrid_degree; // Chebyshev degree of the velocity p-multigrid
  bool         rotation_modes;   // rigid rotations in the velocity AMG's near-null space
  double       aggregation_threshold;
  double       rebuild_growth; // rebuild the AMG when iterations grow by this factor
  unsigned int rebuild_interval;
  bool         verbose;
  bool         matrix_free;    // FGMRES applies the matrix-free flow operator
  bool         check_operator; // compare it with the assembled one after each assembly
  bool         p_multigrid;    // velocity preconditioner: p-multigrid instead of ML

  static void declare_parameters (dealii::ParameterHandler &prm);
  /** `operator` and `velocity preconditioner` = automatic resolved: matrix-free with
   * the p-multigrid (2D and 3D). */
  void parse_parameters (dealii::ParameterHandler &prm);
};

/** `subsection output`. */
struct OutputParameters
{
  std::string         folder;
  bool                overwrite;      // a new run may replace a previous run's results
  double              field_interval; // simulated seconds between VTU outputs (0: none)
  unsigned int        monitor_interval, progress_interval;
  bool                vtu, hdf5; // field formats: pvtu/vtu pieces, parallel HDF5 + XDMF
  std::vector<double> probe_heights; // cross-section averages of alpha_s (m above inlet)

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};

/** Everything a run reads from its .prm file. */
struct Parameters
{
  unsigned int                 dimension;
  MeshParameters               mesh;
  PhysicalProperties           physical;
  std::string                  drag_model;
  SolidsStressParameters       solids_stress;
  KineticTheoryParameters      kinetic_theory;
  WetParticleParameters        wet;
  BoundaryConditionParameters  boundary;
  InitialConditionParameters   initial;
  TimeSteppingParameters       time;
  DivergenceCheckParameters    divergence_checks;
  LinearSolverParameters       linear_solver;
  OutputParameters             output;
  CheckpointParameters         checkpoint;
  AdaptiveRefinementParameters adaptive_refinement;
  BubbleAnalysisParameters     bubble_analysis;
  SpectrumParameters           spectrum;
  EctSensorParameters          ect_sensor;
  StatisticsParameters         statistics;
  BedMonitorParameters         bed_monitors;
  bool                         stabilization; // SUPG + outlet backflow terms
  // momentum equations/form: the weight of rho_k div(alpha_k u_k) u_k in the convection
  // (1 conservative, 1/2 skew-symmetric, 0 advective)
  MomentumForm momentum_form;
  double       continuity_weight () const;
  std::string  parameter_file_directory;
  // every `subsection/parameter` and its value as read, in the file's order (what a
  // checkpoint records of the run)
  std::vector<std::pair<std::string, std::string>> values;
  // every `subsection/parameter` and its declared default (a checkpoint written before
  // a parameter existed resumes if the case leaves it at its default)
  std::map<std::string, std::string> defaults;

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
  /** Fills mesh.checks: what the other subsections place in the domain. */
  void collect_domain_checks ();

  /** Reads `set dimension` alone (2 or 3) from a .prm file. */
  static unsigned int read_dimension (const std::string &filename);

  /** Declares, reads and checks the whole file; throws InputError on bad input. */
  static Parameters read (const std::string &filename, dealii::ParameterHandler &prm);
};
} // namespace wetbed
