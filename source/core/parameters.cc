#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/parameters.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace wetbed
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::FileName;
using dealii::Patterns::Integer;
using dealii::Patterns::List;
using dealii::Patterns::Selection;

void PhysicalProperties::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("physical properties");
  prm.declare_entry ("gas density", "1.2", Double (), "rho_g (kg/m^3).");
  prm.declare_entry ("gas viscosity", "1.8e-5", Double (), "mu_g (Pa s).");
  prm.declare_entry ("particle density", "2500", Double (), "rho_s (kg/m^3).");
  prm.declare_entry ("particle diameter", "350e-6", Double (), "d (m).");
  prm.declare_entry ("maximum packing",
                     "0.61",
                     Double (),
                     "alpha_max: the solids volume fraction never exceeds it.");
  prm.declare_entry ("residual solids fraction",
                     "1e-6",
                     Double (),
                     "The solids inertia and drag are evaluated at max(alpha_s, this) "
                     "(OpenFOAM's residualAlpha): where there are no particles the "
                     "solids velocity relaxes to the gas velocity instead of being set "
                     "by a vanishing viscosity alone.");
  prm.declare_entry (
      "gravity",
      "0, -9.81, 0",
      Anything (),
      "Gravity vector (m/s^2), three comma-separated components; in 2D the "
      "third is ignored.");
  prm.leave_subsection ();
}

void PhysicalProperties::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("physical properties");
  gas_density              = prm.get_double ("gas density");
  gas_viscosity            = prm.get_double ("gas viscosity");
  particle_density         = prm.get_double ("particle density");
  particle_diameter        = prm.get_double ("particle diameter");
  maximum_packing          = prm.get_double ("maximum packing");
  residual_solids_fraction = prm.get_double ("residual solids fraction");
  const std::string g_text = prm.get ("gravity");
  prm.leave_subsection ();

  require_positive (gas_density, "physical properties/gas density");
  require_positive (gas_viscosity, "physical properties/gas viscosity");
  require_positive (particle_density, "physical properties/particle density");
  require_positive (particle_diameter, "physical properties/particle diameter");
  require (particle_density > gas_density,
           "physical properties/particle density",
           "must exceed the gas density");
  require (maximum_packing > 0.0 && maximum_packing < 1.0,
           "physical properties/maximum packing",
           "must lie in (0, 1)");
  require (residual_solids_fraction >= 0.0 && residual_solids_fraction <= 1e-2,
           "physical properties/residual solids fraction",
           "must lie in [0, 1e-2]");
  gravity = parse_vector (g_text, "physical properties/gravity");
  require (gravity.norm () > 0.0, "physical properties/gravity", "must not be zero");
}

void SolidsStressParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("solids stress");
  prm.declare_entry ("model",
                     "constant viscosity",
                     Selection (closures::solids_stress_model_names ()),
                     "Rheology of the particle phase, one of: " +
                         closures::solids_stress_model_names () + ".");
  prm.declare_entry ("shear viscosity", "0.5", Double (), "mu_s (Pa s), constant model.");
  prm.declare_entry ("frictional coefficient", "0.05", Double (), "Fr (Pa).");
  prm.declare_entry (
      "frictional exponent n", "2", Double (), "n in Fr(a-a_min)^n/(a_max-a)^p.");
  prm.declare_entry (
      "frictional exponent p", "3", Double (), "p in Fr(a-a_min)^n/(a_max-a)^p.");
  prm.declare_entry ("frictional onset",
                     "0.58",
                     Double (),
                     "alpha_fr,min: the frictional pressure is zero below it.");
  prm.declare_entry ("minimum packing distance",
                     "0.001",
                     Double (),
                     "Floor of (alpha_max - alpha) in the frictional pressure.");
  prm.leave_subsection ();
}

void SolidsStressParameters::parse_parameters (ParameterHandler &prm,
                                               const double      maximum_packing)
{
  prm.enter_subsection ("solids stress");
  model                    = prm.get ("model");
  shear_viscosity          = prm.get_double ("shear viscosity");
  frictional_coefficient   = prm.get_double ("frictional coefficient");
  frictional_exponent_n    = prm.get_double ("frictional exponent n");
  frictional_exponent_p    = prm.get_double ("frictional exponent p");
  frictional_onset         = prm.get_double ("frictional onset");
  minimum_packing_distance = prm.get_double ("minimum packing distance");
  prm.leave_subsection ();
  require_positive (shear_viscosity, "solids stress/shear viscosity");
  require_positive (frictional_coefficient, "solids stress/frictional coefficient");
  require (frictional_exponent_n >= 1.0,
           "solids stress/frictional exponent n",
           "must be >= 1");
  require (
      frictional_exponent_p > 0.0, "solids stress/frictional exponent p", "must be > 0");
  require (frictional_onset > 0.0 && frictional_onset < maximum_packing,
           "solids stress/frictional onset",
           "must lie in (0, physical properties/maximum packing)");
  require (minimum_packing_distance > 0.0 &&
               minimum_packing_distance < maximum_packing - frictional_onset,
           "solids stress/minimum packing distance",
           "must lie in (0, maximum packing - frictional onset)");
}

void InitialConditionParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("initial conditions");
  prm.declare_entry ("bed height",
                     "0.05",
                     Double (),
                     "Static bed height (m) along -gravity from the origin.");
  prm.declare_entry ("bed solids fraction", "0.58", Double (), "alpha_s in the bed.");
  prm.declare_entry (
      "freeboard solids fraction", "0", Double (), "alpha_s above the bed.");
  prm.declare_entry (
      "bed profile",
      "uniform",
      Selection ("uniform|hydrostatic"),
      "uniform: bed solids fraction up to the bed height. hydrostatic: a "
      "packed bed at rest, alpha_s(z) from dP_s/dz = -alpha_s (rho_s - "
      "rho_g) g with P_s = 0 at the bed height (needs a solids pressure).");
  prm.declare_entry ("gas at inlet velocity",
                     "true",
                     Bool (),
                     "Start with the gas at U/alpha_g along the column (else at rest).");
  prm.leave_subsection ();
}

void InitialConditionParameters::parse_parameters (ParameterHandler &prm,
                                                   const double      maximum_packing)
{
  prm.enter_subsection ("initial conditions");
  bed_height                = prm.get_double ("bed height");
  bed_solids_fraction       = prm.get_double ("bed solids fraction");
  freeboard_solids_fraction = prm.get_double ("freeboard solids fraction");
  gas_at_inlet_velocity     = prm.get_bool ("gas at inlet velocity");
  hydrostatic_bed           = prm.get ("bed profile") == "hydrostatic";
  prm.leave_subsection ();
  require (bed_height >= 0.0, "initial conditions/bed height", "must be >= 0");
  require (bed_solids_fraction >= 0.0 && bed_solids_fraction <= maximum_packing,
           "initial conditions/bed solids fraction",
           "must lie in [0, physical properties/maximum packing]");
  require (freeboard_solids_fraction >= 0.0 &&
               freeboard_solids_fraction <= maximum_packing,
           "initial conditions/freeboard solids fraction",
           "must lie in [0, physical properties/maximum packing]");
}

void TimeSteppingParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("time stepping");
  prm.declare_entry ("end time", "2", Double (), "Simulated time to reach (s).");
  prm.declare_entry ("initial time step", "1e-4", Double (), "First time step (s).");
  prm.declare_entry (
      "maximum time step", "2e-3", Double (), "Upper limit of the step (s).");
  prm.declare_entry ("minimum time step",
                     "1e-7",
                     Double (),
                     "Below this a rejected step stops the run (s).");
  prm.declare_entry (
      "cfl target",
      "0.5",
      Double (),
      "Target Courant number of the phase velocities per Q2 node spacing.");
  prm.declare_entry (
      "courant measure",
      "local",
      Selection ("local|global"),
      "local: the Courant number of each cell, its speeds on its own Q2 node spacing, "
      "the gas speed counted only in cells that hold solids (doc/theory.md \"Time "
      "step\"); global: the peak speeds of the whole mesh on its smallest node "
      "spacing.");
  prm.declare_entry (
      "time error tolerance",
      "0",
      Double (0),
      "The step is also limited so that the local time-error estimate of alpha_s "
      "(the RMS over the nodes holding solids of the difference between the step's "
      "alpha_s and its linear extrapolation from the last two steps, scaled to the "
      "error of a first-order step) stays at this value. 0: no error control, the "
      "Courant limit alone.");
  prm.declare_entry ("transport cfl",
                     "0.4",
                     Double (),
                     "Courant number of each explicit alpha_s sub-step (<= 1).");
  prm.declare_entry ("growth factor", "1.2", Double (), "Largest growth of the step.");
  prm.declare_entry (
      "bdf order", "2", Integer (1, 2), "1: backward Euler, 2: variable BDF2.");
  prm.declare_entry (
      "outer iterations",
      "2",
      Integer (1, 50),
      "The most transport/momentum (outer) iterations per time step. With `outer "
      "tolerance` = 0 every step makes exactly this many, each flow solve to `linear "
      "solver/relative tolerance`. The change of alpha_s between iterates is tested "
      "only with 3 or more.");
  prm.declare_entry (
      "outer tolerance",
      "0.1",
      Double (0, 1),
      "An outer iteration after the first stops the step before its flow solve when "
      "the flow system re-assembled at the latest iterate (alpha_s, Theta, velocities) "
      "has a residual |b - A x| below this fraction of the residual of x^n in the "
      "step's first system (or within 10x `linear solver/relative tolerance` of |b|), "
      "and alpha_s changed by at most `outer alpha tolerance` in the last iteration "
      "(doc/theory.md \"Outer iterations\"). A step that uses all `outer iterations` is "
      "accepted without testing its last iterate, and counted. 0: a fixed number of "
      "outer iterations.");
  prm.declare_entry ("outer alpha tolerance",
                     "1e-3",
                     Double (0, 1),
                     "With `outer tolerance` > 0: the largest change of alpha_s at a "
                     "node between the last two outer iterates of a converged step "
                     "(tested from the third outer iteration on).");
  prm.declare_entry (
      "outer forcing",
      "0.1",
      Double (1e-12, 1),
      "With `outer tolerance` > 0: each flow solve of an outer iteration stops at "
      "this fraction of the smaller of its initial residual and what the outer test "
      "accepts (an Eisenstat-Walker forcing term), never below `linear "
      "solver/relative tolerance` x |b|.");
  prm.declare_entry ("extrapolate initial guess",
                     "true",
                     Bool (),
                     "With `outer tolerance` > 0: the first flow solve of a step starts "
                     "from the flow extrapolated linearly from the last two steps.");
  prm.declare_entry ("adaptive", "true", Bool (), "Adapt the step to the CFL target.");
  prm.leave_subsection ();
}

void TimeSteppingParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("time stepping");
  end_time              = prm.get_double ("end time");
  initial_time_step     = prm.get_double ("initial time step");
  maximum_time_step     = prm.get_double ("maximum time step");
  minimum_time_step     = prm.get_double ("minimum time step");
  cfl_target            = prm.get_double ("cfl target");
  local_courant         = prm.get ("courant measure") == "local";
  time_error_tolerance  = prm.get_double ("time error tolerance");
  transport_cfl         = prm.get_double ("transport cfl");
  growth_factor         = prm.get_double ("growth factor");
  bdf_order             = prm.get_integer ("bdf order");
  outer_iterations      = prm.get_integer ("outer iterations");
  outer_tolerance       = prm.get_double ("outer tolerance");
  outer_alpha_tolerance = prm.get_double ("outer alpha tolerance");
  outer_forcing         = prm.get_double ("outer forcing");
  extrapolate_guess     = prm.get_bool ("extrapolate initial guess");
  adaptive              = prm.get_bool ("adaptive");
  prm.leave_subsection ();
  require_positive (end_time, "time stepping/end time");
  require_positive (initial_time_step, "time stepping/initial time step");
  require_positive (maximum_time_step, "time stepping/maximum time step");
  require_positive (minimum_time_step, "time stepping/minimum time step");
  require (minimum_time_step <= initial_time_step &&
               initial_time_step <= maximum_time_step,
           "time stepping/initial time step",
           "must lie in [minimum time step, maximum time step]");
  require_positive (cfl_target, "time stepping/cfl target");
  require (transport_cfl > 0.0 && transport_cfl <= 1.0,
           "time stepping/transport cfl",
           "must lie in (0, 1]");
  require (growth_factor >= 1.0, "time stepping/growth factor", "must be >= 1");
}

namespace
{
/** The entries of `linear solver` for ML (the velocity AMG of the assembled path and
 * the p-multigrid's coarse AMG). */
void declare_amg_entries (ParameterHandler &prm)
{
  prm.declare_entry (
      "velocity smoother",
      "Chebyshev",
      Selection ("Chebyshev|ILU|block Gauss-Seidel"),
      "ML smoother on the velocity block, with `velocity preconditioner = "
      "AMG` (the assembled path). Chebyshev (default): more FGMRES "
      "iterations than ILU but cheaper ones, less wall time overall "
      "(doc/theory.md \"Smoother and hierarchy reuse\"); ILU sees the drag "
      "coupling of the two velocities inside a node. block Gauss-Seidel: "
      "symmetric Gauss-Seidel on node blocks (all velocity components of a "
      "support point solved together); needed for Nitsche no-penetration on "
      "curved walls with the AMG, whose point smoothers stall on the "
      "penalty's coupling of a wall node's components (doc/theory.md "
      "\"Solving Nitsche on a curved wall\"). The p-multigrid's node-block "
      "smoother needs no such choice.");
  prm.declare_entry (
      "rotation modes",
      "false",
      Bool (),
      "Give the velocity AMG the rigid rotations of each phase as "
      "near-null modes besides the translations of each component (for "
      "slip walls on curved boundaries, where a rotation is nearly free).");
  prm.declare_entry ("smoother sweeps",
                     "4",
                     Integer (1, 10),
                     "ML smoother sweeps (the Chebyshev degree). More sweeps make each "
                     "V-cycle costlier but cut the FGMRES iterations; 4 rather than 2 "
                     "saves wall time on the bubbling 2D bed (doc/benchmarks.md "
                     "\"Where the FGMRES iterations come from (2D bed, start-up)\").");
  prm.declare_entry (
      "aggregation threshold", "1e-4", Double (0, 1), "ML aggregation threshold.");
}
} // namespace

void LinearSolverParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("linear solver");
  prm.declare_entry (
      "relative tolerance", "1e-8", Double (), "FGMRES stop: |r| <= tol |b|.");
  prm.declare_entry ("scalar tolerance",
                     "1e-12",
                     Double (),
                     "Relative tolerance of the scalar (alpha correction) solves.");
  prm.declare_entry ("maximum iterations", "300", Integer (1), "FGMRES iteration limit.");
  prm.declare_entry ("restart", "100", Integer (1), "FGMRES restart length.");
  declare_amg_entries (prm);
  prm.declare_entry ("inner solves",
                     "V-cycle",
                     Selection ("V-cycle|exact|exact velocity|exact coarse"),
                     "V-cycle: one AMG V-cycle per block (the product). exact: the "
                     "velocity block by a sparse direct solver (Amesos KLU) and the "
                     "pressure Schur approximation by CG to 1e-10, to tell how many "
                     "FGMRES iterations the Schur approximation itself costs (slow; "
                     "for diagnosis, see benchmarks/solver_diagnosis.py). exact "
                     "velocity: the direct velocity solve with the Schur V-cycle, to "
                     "tell the velocity V-cycle's iterations from the Schur "
                     "approximation's (with `rebuild interval = 1`, else the "
                     "factorisation is reused like the AMG). With `velocity "
                     "preconditioner = p-multigrid` the velocity block is solved by "
                     "GMRES with the V-cycle to 1e-10 instead of a direct solver (its "
                     "iterations printed with `verbose`), and `exact coarse` solves "
                     "the V-cycle's Q1 problem by GMRES with ML to 1e-10, to tell the "
                     "coarse ML's part.");
  prm.declare_entry (
      "rebuild growth",
      "1.3",
      Double (1),
      "Rebuild the velocity and Schur AMGs when Krylov iterations exceed this factor "
      "times those right after the last rebuild.");
  prm.declare_entry (
      "rebuild interval",
      "10",
      Integer (1),
      "Rebuild the velocity AMG (with the p-multigrid: its coarse AMG and "
      "smoother, whose coarse matrix is assembled only for such a solve) and "
      "the Schur AMG at least every this many linear solves (1: at every "
      "solve). A solve with a reused hierarchy gets an iteration cap from the "
      "convergence rate right after its build; if it misses that the "
      "hierarchy is rebuilt and the solve repeated. Reuse pays where a build "
      "is expensive against a solve, as in 3D (doc/theory.md \"Smoother and "
      "hierarchy reuse\").");
  prm.declare_entry ("verbose", "false", Bool (), "Print every linear solve.");
  prm.declare_entry (
      "operator",
      "automatic",
      Selection ("automatic|assembled|matrix-free"),
      "How FGMRES applies the flow system: `assembled` (the Trilinos "
      "matrix) or `matrix-free` (sum-factorised cell and face integrals "
      "of the same bilinear form, doc/theory.md \"Matrix-free flow "
      "operator\"). `automatic`: matrix-free with the p-multigrid in 2D and "
      "3D, the faster path on the shipped cases, by more in 3D and on finer "
      "meshes (doc/benchmarks.md \"Cost of the 3D column by flow-solve path\" "
      "and \"The 2D beds by flow-solve path\").");
  prm.declare_entry (
      "velocity preconditioner",
      "automatic",
      Selection ("automatic|AMG|p-multigrid"),
      "The velocity part of the block preconditioner: `AMG` (one ML V-cycle "
      "on the assembled Q2 velocity block) or `p-multigrid` (needs "
      "`operator = matrix-free`: Chebyshev with node-block Jacobi on the "
      "matrix-free Q2 operator and one ML V-cycle on the Q1 velocity "
      "matrix of the same bilinear form, doc/theory.md \"Velocity "
      "p-multigrid\"; no Q2 matrix is assembled). `automatic`: p-multigrid with "
      "the matrix-free operator, AMG with the assembled one.");
  prm.declare_entry (
      "multigrid smoother degree",
      "3",
      Integer (1, 10),
      "With `velocity preconditioner = p-multigrid`: the degree of its Chebyshev "
      "smoother on the Q2 operator (operator products per pre- or post-smoothing). "
      "A higher degree makes each V-cycle costlier and cuts the FGMRES "
      "iterations: 3 suits the 3D column, 4 can be slightly faster on small 2D "
      "beds, 2 needs many more iterations on fine meshes (doc/theory.md "
      "\"Velocity p-multigrid\").");
  prm.declare_entry ("check operator",
                     "false",
                     Bool (),
                     "With `operator = matrix-free`: after each assembly, apply both "
                     "operators to a random vector and print their largest relative "
                     "difference (a verification, it costs one assembled product).");
  prm.leave_subsection ();
}

void LinearSolverParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("linear solver");
  relative_tolerance         = prm.get_double ("relative tolerance");
  scalar_tolerance           = prm.get_double ("scalar tolerance");
  maximum_iterations         = prm.get_integer ("maximum iterations");
  restart                    = prm.get_integer ("restart");
  smoother                   = prm.get ("velocity smoother");
  smoother_sweeps            = prm.get_integer ("smoother sweeps");
  multigrid_degree           = prm.get_integer ("multigrid smoother degree");
  rotation_modes             = prm.get_bool ("rotation modes");
  inner_solves               = prm.get ("inner solves");
  aggregation_threshold      = prm.get_double ("aggregation threshold");
  rebuild_growth             = prm.get_double ("rebuild growth");
  rebuild_interval           = prm.get_integer ("rebuild interval");
  verbose                    = prm.get_bool ("verbose");
  const std::string op       = prm.get ("operator");
  const std::string velocity = prm.get ("velocity preconditioner");
  matrix_free                = op == "matrix-free" || op == "automatic";
  check_operator             = prm.get_bool ("check operator");
  p_multigrid = velocity == "p-multigrid" || (velocity == "automatic" && matrix_free);
  prm.leave_subsection ();
  require (!p_multigrid || matrix_free,
           "linear solver/velocity preconditioner",
           "p-multigrid needs 'linear solver/operator = matrix-free'");
  require (inner_solves != "exact coarse" || p_multigrid,
           "linear solver/inner solves",
           "'exact coarse' needs 'linear solver/velocity preconditioner = p-multigrid'");
  require (relative_tolerance > 0 && relative_tolerance < 1,
           "linear solver/relative tolerance",
           "must lie in (0, 1)");
  require (scalar_tolerance > 0 && scalar_tolerance < 1,
           "linear solver/scalar tolerance",
           "must lie in (0, 1)");
}

void OutputParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("output");
  prm.declare_entry ("folder",
                     "output",
                     Anything (),
                     "Output folder (created if missing, once the input has been "
                     "checked). A run holds an exclusive lock on it (the file "
                     ".wetbed.lock) until it ends: a second run into the same folder "
                     "exits with status 2.");
  prm.declare_entry ("overwrite",
                     "false",
                     Bool (),
                     "A new run (not checkpoint/resume) into a folder that holds a "
                     "previous run's results (monitors.csv or checkpoint/) exits with "
                     "status 2 unless this is true (or the command line has "
                     "--overwrite); the previous run's files are then replaced and its "
                     "checkpoint removed once the new run's input and mesh are "
                     "accepted.");
  prm.declare_entry ("field interval",
                     "0.05",
                     Double (0),
                     "Simulated seconds between field outputs (0: first and last only).");
  prm.declare_entry (
      "monitor interval",
      "1",
      Integer (1),
      "Steps between monitors.csv rows (and a row after the last step); the "
      "spectra are computed from these rows.");
  prm.declare_entry (
      "progress interval", "20", Integer (1), "Steps between progress lines.");
  prm.declare_entry (
      "probe heights",
      "",
      List (Double (0)),
      "Heights along -gravity from the origin (m) at which monitors.csv records the "
      "cross-section average of alpha_s over the cell layer containing the "
      "height (columns alpha_s_plane_<height>; seed 000 probes 0.076 m); "
      "empty: none.");
  prm.declare_entry ("field format",
                     "vtu",
                     Selection ("vtu|hdf5|vtu and hdf5"),
                     "vtu: fields_NNN.pvtu with one .vtu piece per rank; hdf5: one "
                     "fields_NNN.h5 per output (parallel HDF5) indexed by fields.xdmf "
                     "(open it in ParaView or VisIt); or both.");
  prm.leave_subsection ();
}

void OutputParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("output");
  folder            = prm.get ("folder");
  overwrite         = prm.get_bool ("overwrite");
  field_interval    = prm.get_double ("field interval");
  monitor_interval  = prm.get_integer ("monitor interval");
  progress_interval = prm.get_integer ("progress interval");
  probe_heights.clear ();
  for (const auto &item :
       dealii::Utilities::split_string_list (prm.get ("probe heights")))
    probe_heights.push_back (dealii::Utilities::string_to_double (item));
  const std::string format = prm.get ("field format");
  vtu                      = format != "hdf5";
  hdf5                     = format != "vtu";
  prm.leave_subsection ();
  require (!folder.empty (), "output/folder", "is empty");
}

void Parameters::declare_parameters (ParameterHandler &prm)
{
  prm.declare_entry ("dimension", "2", Integer (2, 3), "Spatial dimension (2 or 3).");
  MeshParameters::declare_parameters (prm);
  PhysicalProperties::declare_parameters (prm);
  prm.enter_subsection ("drag");
  prm.declare_entry ("model",
                     "Syamlal-O'Brien",
                     Selection (closures::drag_model_names ()),
                     "Gas-solid drag law, one of: " + closures::drag_model_names () +
                         ".");
  prm.leave_subsection ();
  SolidsStressParameters::declare_parameters (prm);
  KineticTheoryParameters::declare_parameters (prm);
  WetParticleParameters::declare_parameters (prm);
  prm.enter_subsection ("stabilization");
  prm.declare_entry ("enabled",
                     "true",
                     Bool (),
                     "SUPG on both momentum equations (tau includes the drag rate) and "
                     "backflow stabilization on the outlet. Off only for verification.");
  prm.leave_subsection ();
  prm.enter_subsection ("momentum equations");
  prm.declare_entry (
      "form",
      "skew-symmetric",
      Selection ("conservative|advective|skew-symmetric"),
      "skew-symmetric: the mean of the conservative and the advective form, with "
      "rho_k div(alpha_k u_k) u_k / 2 implicit; tested with the velocity, inertia and "
      "convection change only the kinetic energy, whatever the continuity residual of "
      "the discrete alpha_s, so a cell that empties within a step cannot hand its "
      "momentum to the little mass left in it (doc/theory.md, \"Time discretisation\"). "
      "conservative: d(alpha_k rho_k u_k)/dt + div(alpha_k rho_k u_k u_k) with each time "
      "level's own volume fraction; the mixture momentum changes only by forces, but the "
      "kinetic energy is not bounded where alpha_s falls by orders of magnitude within a "
      "step. advective: alpha_k rho_k Du_k/Dt, which differs from the conservative form "
      "by rho_k u_k times the continuity residual of the discrete alpha_s, a spurious "
      "force on the mixture.");
  prm.leave_subsection ();
  BoundaryConditionParameters::declare_parameters (prm);
  InitialConditionParameters::declare_parameters (prm);
  TimeSteppingParameters::declare_parameters (prm);
  LinearSolverParameters::declare_parameters (prm);
  OutputParameters::declare_parameters (prm);
  CheckpointParameters::declare_parameters (prm);
  AdaptiveRefinementParameters::declare_parameters (prm);
  BubbleAnalysisParameters::declare_parameters (prm);
  SpectrumParameters::declare_parameters (prm);
  EctSensorParameters::declare_parameters (prm);
  StatisticsParameters::declare_parameters (prm);
  DivergenceCheckParameters::declare_parameters (prm);
  BedMonitorParameters::declare_parameters (prm);
}

double Parameters::continuity_weight () const
{
  return momentum_form == MomentumForm::conservative     ? 1.0
         : momentum_form == MomentumForm::skew_symmetric ? 0.5
                                                         : 0.0;
}

void Parameters::parse_parameters (ParameterHandler &prm)
{
  dimension = prm.get_integer ("dimension");
  mesh.parse_parameters (prm);
  physical.parse_parameters (prm);
  prm.enter_subsection ("drag");
  drag_model = prm.get ("model");
  prm.leave_subsection ();
  solids_stress.parse_parameters (prm, physical.maximum_packing);
  kinetic_theory.parse_parameters (prm, physical.maximum_packing);
  wet.parse_parameters (
      prm, solids_stress.model == "kinetic theory", kinetic_theory.algebraic);
  prm.enter_subsection ("stabilization");
  stabilization = prm.get_bool ("enabled");
  prm.leave_subsection ();
  prm.enter_subsection ("momentum equations");
  const std::string form = prm.get ("form");
  momentum_form          = form == "conservative" ? MomentumForm::conservative
                           : form == "advective"  ? MomentumForm::advective
                                                  : MomentumForm::skew_symmetric;
  prm.leave_subsection ();
  boundary.parse_parameters (prm);
  boundary.check_wall_conditions (solids_stress.model == "kinetic theory");
  initial.parse_parameters (prm, physical.maximum_packing);
  time.parse_parameters (prm);
  linear_solver.parse_parameters (prm);
  output.parse_parameters (prm);
  checkpoint.parse_parameters (prm);
  adaptive_refinement.parse_parameters (prm, mesh.initial_refinement);
  bubble_analysis.parse_parameters (prm);
  spectrum.parse_parameters (prm);
  ect_sensor.parse_parameters (prm);
  statistics.parse_parameters (prm, dimension);
  divergence_checks.parse_parameters (prm);
  bed_monitors.parse_parameters (prm, dimension);
  boundary.check_time_span (time.end_time);
  boundary.check_inlet_groups (mesh.inlet_names, dimension, physical.maximum_packing);
  collect_domain_checks ();
}

void Parameters::collect_domain_checks ()
{
  DomainChecks &checks = mesh.checks;
  checks               = DomainChecks ();
  checks.heights.push_back ({"initial conditions/bed height", initial.bed_height, true});
  for (const double h : output.probe_heights)
    checks.heights.push_back ({"output/probe heights", h, false});
  for (const double h : bed_monitors.pressure_drop_planes)
    checks.heights.push_back ({"bed monitors/pressure drop between", h, false});
  if (bed_monitors.pressure_probe_height >= 0)
    checks.heights.push_back ({"bed monitors/pressure probe height",
                               bed_monitors.pressure_probe_height,
                               false});
  if (ect_sensor.enabled)
    checks.heights.push_back ({"ECT sensor/centre height (the top of the slab)",
                               ect_sensor.centre_height + ect_sensor.thickness / 2,
                               false});
  checks.point_probes = bed_monitors.point_probes;
  checks.held_solids_velocity =
      boundary.hold_solids ? boundary.held_solids_velocity : std::string ();
  checks.end_time           = time.end_time;
  checks.assembled_operator = !linear_solver.matrix_free;
  checks.refinement_levels.emplace_back ("mesh/initial refinement",
                                         mesh.initial_refinement);
  if (adaptive_refinement.enabled)
  {
    checks.refinement_levels.emplace_back ("adaptive refinement/minimum level",
                                           adaptive_refinement.minimum_level);
    checks.refinement_levels.emplace_back ("adaptive refinement/maximum level",
                                           adaptive_refinement.maximum_level);
  }
}

namespace
{
/**
 * Every number in the file finite: each value's items (split at commas, semicolons,
 * colons and blanks) that read as a number must be finite; `inf`, `nan` or `1e999`
 * anywhere numeric is an InputError naming the parameter. Names (files, physical
 * groups, the folder) are not numbers and are skipped.
 */
/** Every `subsection/parameter` of `prm` and its value, in print order. */
std::vector<std::pair<std::string, std::string>>
parameter_values (const ParameterHandler &prm)
{
  std::ostringstream text;
  prm.print_parameters (text, ParameterHandler::ShortPRM);
  std::istringstream                               lines (text.str ());
  std::vector<std::string>                         path;
  std::vector<std::pair<std::string, std::string>> values;
  for (std::string line; std::getline (lines, line);)
  {
    const std::string trimmed = dealii::Utilities::trim (line);
    if (trimmed.rfind ("subsection ", 0) == 0)
      path.push_back (dealii::Utilities::trim (trimmed.substr (11)));
    else if (trimmed == "end" && !path.empty ())
      path.pop_back ();
    else if (trimmed.rfind ("set ", 0) == 0 && trimmed.find ('=') != std::string::npos)
    {
      const auto  equals = trimmed.find ('=');
      std::string where;
      for (const auto &p : path)
        where += p + "/";
      where += dealii::Utilities::trim (trimmed.substr (4, equals - 4));
      values.emplace_back (where, dealii::Utilities::trim (trimmed.substr (equals + 1)));
    }
  }
  return values;
}

/**
 * Every number in the file finite: each value's items (split at commas, semicolons,
 * colons and blanks) that read as a number must be finite; `inf`, `nan` or `1e999`
 * anywhere numeric is an InputError naming the parameter. Names (files, physical
 * groups, the folder) are not numbers and are skipped.
 */
void check_finite_values (const std::vector<std::pair<std::string, std::string>> &values)
{
  const std::vector<std::string> names = {"mesh/file",
                                          "mesh/inlet",
                                          "mesh/outlet",
                                          "mesh/wall",
                                          "mesh/periodic boundaries",
                                          "boundary conditions/moving wall",
                                          "output/folder"};
  for (const auto &[where, value] : values)
  {
    if (std::find (names.begin (), names.end (), where) != names.end ())
      continue;
    std::string item;
    for (std::size_t i = 0; i <= value.size (); ++i)
    {
      const char c = i < value.size () ? value[i] : ' ';
      if (c == ',' || c == ';' || c == ':' ||
          std::isspace (static_cast<unsigned char> (c)))
      {
        if (!item.empty ())
        {
          char *end            = nullptr;
          errno                = 0;
          const double number  = std::strtod (item.c_str (), &end);
          const bool   numeric = end != nullptr && *end == '\0';
          require (!numeric || std::isfinite (number),
                   where,
                   "'" + item + "' is not a finite number");
          // deal.II refuses what strtod can only round to a subnormal or to 0
          require (!numeric || errno != ERANGE,
                   where,
                   "'" + item + "' is too small to be represented (below 2.2e-308)");
        }
        item.clear ();
      }
      else
        item += c;
    }
  }
}
} // namespace

unsigned int Parameters::read_dimension (const std::string &filename)
{
  ParameterHandler prm;
  prm.declare_entry ("dimension", "2", Integer (2, 3), "");
  prm.parse_input (filename, "", true);
  return prm.get_integer ("dimension");
}

Parameters Parameters::read (const std::string &filename, ParameterHandler &prm)
{
  require (
      std::filesystem::is_regular_file (filename), filename, "parameter file not found");
  declare_parameters (prm);
  try
  {
    prm.parse_input (filename);
  }
  catch (const dealii::ExceptionBase &e)
  {
    std::ostringstream message;
    e.print_info (message);
    std::string text = message.str ();
    // keep the message on one line
    for (char &c : text)
      if (c == '\n')
        c = ' ';
    throw InputError (filename, "cannot be parsed:" + text);
  }
  const auto values = parameter_values (prm);
  check_finite_values (values);
  Parameters parameters;
  parameters.parse_parameters (prm);
  parameters.values = values;
  ParameterHandler declared;
  declare_parameters (declared);
  for (const auto &[name, value] : parameter_values (declared))
    parameters.defaults[name] = value;
  parameters.parameter_file_directory =
      std::filesystem::absolute (filename).parent_path ().string ();
  return parameters;
}
} // namespace wetbed
