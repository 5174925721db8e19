// T2 / T3-lite: manufactured-solution convergence of the monolithic (u_g, u_s, p')
// discretisation (Q2/Q2/Q1), 2D square and 3D cylinder (curved wall, MappingQ2).
//   single phase: alpha_s = 0 (T2);
//   two fluid:    linear alpha_s (represented exactly by the Q1 solids fraction, so the
//                 flow discretisation is measured alone), Wen-Yu drag, constant solids
//                 viscosity and the Johnson-Jackson frictional pressure active (T3-lite).
// Sources: the strong residual of the exact fields, differentiated with nested Sacado.
//   transient: the same fields times s(t) (BDF1/BDF2 rates in dt), see main().
#include "manufactured_hook.h"
#include "test_utilities.h"

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>
#include <wetbed/core/parameters.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/mpi.h>

#include <Sacado.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

using namespace wetbed;
using dealii::Point;
using dealii::Tensor;
using F1 = Sacado::Fad::DFad<double>;
using F2 = Sacado::Fad::DFad<F1>;

namespace
{
constexpr double pi = 3.14159265358979323846;

/** The exact fields, templated on the number type (x, y, z). */
template <int dim, typename Number>
struct ExactFields
{
  bool two_fluid;
  bool rotation; // T11: both phases rotate about the axis, omega(z) = 1 + z^2/2
  /** s(t) of a transient solution u(x) s(t), p(x) s(t) (1 when steady); with s'(t)
   * in its place the fields are the time derivatives */
  double scale = 1;
  /** quadratic velocities and a linear pressure: in the Q2/Q1 spaces on affine cells,
   * so that the discrete solution has no spatial error and a transient run measures
   * the time discretisation alone */
  bool polynomial = false;

  Number alpha_s (const Number *x) const
  {
    if (rotation)
      return Number (0.3);
    if (!two_fluid)
      return Number (0.0);
    const Number third = dim == 3 ? Number (0.04 * x[2]) : Number (0.0);
    return 0.3 + 0.1 * x[0] - 0.05 * x[1] + third;
  }
  /** omega(z) (-y, x, 0): u.n = 0 and zero tangential traction on the cylinder wall. */
  Number rotating (const Number *x, const unsigned int c) const
  {
    const Number omega = dim == 3 ? 1.0 + 0.5 * x[2] * x[2] : Number (1.0);
    return c == 0 ? -omega * x[1] : (c == 1 ? omega * x[0] : Number (0.0));
  }
  Number gas (const Number *x, const unsigned int c) const
  {
    using std::cos;
    using std::sin;
    if (rotation)
      return rotating (x, c);
    const Number z = dim == 3 ? x[2] : Number (0.0);
    if (polynomial)
    {
      if (c == 0)
        return scale * (0.5 * x[0] * x[1] + 0.2 * x[1] * x[1] + 0.1 + 0.1 * z * x[0]);
      if (c == 1)
        return scale * (0.3 - 0.5 * x[0] * x[0] + 0.25 * x[1]);
      return scale * (0.2 * x[0] * x[1] + 0.1 * z * z);
    }
    switch (c)
    {
    case 0:
      return scale * (0.5 * sin (pi * x[0]) * sin (pi * x[1]) + 0.2 * cos (z));
    case 1:
      return scale * (0.5 * cos (pi * x[0]) * cos (pi * x[1]) + 0.3);
    default:
      return scale * 0.4 * sin (pi * x[0]) * cos (pi * z) * x[1];
    }
  }
  Number solids (const Number *x, const unsigned int c) const
  {
    using std::cos;
    using std::sin;
    if (rotation)
      return rotating (x, c);
    const Number z = dim == 3 ? x[2] : Number (0.0);
    if (polynomial)
    {
      if (c == 0)
        return scale * (0.3 * x[0] * x[0] - 0.2 * x[1] + 0.05);
      if (c == 1)
        return scale * (0.1 + 0.2 * x[0] * x[1] - 0.1 * x[1] * x[1]);
      return scale * (0.1 * x[1] * z);
    }
    switch (c)
    {
    case 0:
      return scale * 0.3 * cos (pi * x[0]) * sin (pi * x[1]) * (1.0 + 0.5 * z);
    case 1:
      return scale * (-0.2 * sin (pi * x[0]) * cos (pi * x[1]) + 0.1);
    default:
      return scale * 0.2 * cos (pi * x[1]) * sin (pi * z);
    }
  }
  Number pressure (const Number *x) const
  {
    using std::cos;
    using std::sin;
    if (rotation)
      return 0.5 * (x[0] * x[0] + x[1] * x[1]) +
             (dim == 3 ? 0.1 * x[dim - 1] : Number (0));
    const Number z = dim == 3 ? x[2] : Number (0.0);
    if (polynomial)
      return scale * (2.0 * x[0] - x[1] + 0.5 * z);
    return scale * (2.0 * cos (pi * x[0]) * sin (pi * x[1]) + z * x[0]);
  }
};

template <int dim>
class ManufacturedTwoFluid : public ManufacturedSolution<dim>
{
public:
  ManufacturedTwoFluid (const bool        two_fluid,
                        const Parameters &p,
                        const bool        rotation   = false,
                        const bool        transient  = false,
                        const bool        polynomial = false)
      : two_fluid (two_fluid), rotation (rotation), transient (transient),
        polynomial (polynomial), parameters (p),
        drag (closures::create_drag_model (p.drag_model)),
        stress (closures::create_solids_stress_model (
            p.solids_stress, p.physical, p.kinetic_theory, p.wet))
  {
  }

  bool slip_walls () const override { return rotation; }

  /** s(t) = 1 + sin(2 pi t)/2 of the transient fields, s'(t); 1 and 0 when steady. */
  double scale () const
  {
    return transient ? 1.0 + 0.5 * std::sin (2 * pi * this->time ()) : 1.0;
  }
  double scale_rate () const
  {
    return transient ? pi * std::cos (2 * pi * this->time ()) : 0.0;
  }

  double solids_fraction (const Point<dim> &x) const override
  {
    double c[dim];
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = x[d];
    return ExactFields<dim, double>{two_fluid, rotation, scale (), polynomial}.alpha_s (
        c);
  }
  Tensor<1, dim> gas_velocity (const Point<dim> &x) const override
  {
    return velocity (x, true);
  }
  Tensor<1, dim> solids_velocity (const Point<dim> &x) const override
  {
    return velocity (x, false);
  }
  double pressure (const Point<dim> &x) const override
  {
    double c[dim];
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = x[d];
    return ExactFields<dim, double>{two_fluid, rotation, scale (), polynomial}.pressure (
        c);
  }
  Tensor<1, dim> gas_momentum_source (const Point<dim> &x) const override
  {
    return residual (x, true);
  }
  Tensor<1, dim> solids_momentum_source (const Point<dim> &x) const override
  {
    return residual (x, false);
  }
  double mixture_volume_source (const Point<dim> &x) const override
  {
    const Derived s   = derive (x);
    double        div = 0;
    for (unsigned int d = 0; d < dim; ++d)
      div += (1 - s.alpha) * s.grad_ug[d][d] - s.grad_alpha[d] * s.ug[d] +
             s.alpha * s.grad_us[d][d] + s.grad_alpha[d] * s.us[d];
    return div;
  }
  Tensor<1, dim> gas_traction (const Point<dim>     &x,
                               const Tensor<1, dim> &n) const override
  {
    const Derived s = derive (x);
    return stress_tensor (s, true) * n - (1 - s.alpha) * s.p * n;
  }
  Tensor<1, dim> solids_traction (const Point<dim>     &x,
                                  const Tensor<1, dim> &n) const override
  {
    const Derived s = derive (x);
    return stress_tensor (s, false) * n - (s.alpha * s.p + solids_pressure (s.alpha)) * n;
  }

private:
  struct Derived
  {
    double         alpha, p;
    Tensor<1, dim> grad_alpha, grad_p, ug, us;
    Tensor<2, dim> grad_ug, grad_us;     // grad[i][j] = d_j u_i
    Tensor<1, dim> div_tau_g, div_tau_s; // divergence of the viscous stresses
  };

  Tensor<1, dim>
  velocity (const Point<dim> &x, const bool gas, const bool time_derivative = false) const
  {
    double c[dim];
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = x[d];
    ExactFields<dim, double> f{
        two_fluid, rotation, time_derivative ? scale_rate () : scale (), polynomial};
    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = gas ? f.gas (c, d) : f.solids (c, d);
    return u;
  }

  double solids_pressure (const double alpha) const
  {
    return two_fluid ? stress->evaluate ({alpha, 0.0, 0.0}).pressure : 0.0;
  }

  Tensor<2, dim> stress_tensor (const Derived &s, const bool gas) const
  {
    const double mu_g         = parameters.physical.gas_viscosity,
                 mu_s         = parameters.solids_stress.shear_viscosity;
    const Tensor<2, dim> &g   = gas ? s.grad_ug : s.grad_us;
    const double          mu  = gas ? (1 - s.alpha) * mu_g : mu_s;
    const double          div = dealii::trace (g);
    Tensor<2, dim>        tau = mu * (g + dealii::transpose (g));
    for (unsigned int d = 0; d < dim; ++d)
      tau[d][d] -= 2.0 / 3.0 * mu * div;
    return tau;
  }

  Derived derive (const Point<dim> &x) const
  {
    F2 c[dim];
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = F2 (dim, d, F1 (dim, d, x[d]));
    ExactFields<dim, F2> f{two_fluid, rotation, scale (), polynomial};
    Derived              s;
    const F2             a = f.alpha_s (c), p = f.pressure (c);
    s.alpha = a.val ().val ();
    s.p     = p.val ().val ();
    F2 ug[dim], us[dim];
    for (unsigned int i = 0; i < dim; ++i)
    {
      ug[i]           = f.gas (c, i);
      us[i]           = f.solids (c, i);
      s.ug[i]         = ug[i].val ().val ();
      s.us[i]         = us[i].val ().val ();
      s.grad_alpha[i] = a.dx (i).val ();
      s.grad_p[i]     = p.dx (i).val ();
      for (unsigned int j = 0; j < dim; ++j)
      {
        s.grad_ug[i][j] = ug[i].dx (j).val ();
        s.grad_us[i][j] = us[i].dx (j).val ();
      }
    }
    // div tau: tau_ij as first-order numbers, then d_j
    const double mu_g = parameters.physical.gas_viscosity,
                 mu_s = parameters.solids_stress.shear_viscosity;
    for (unsigned int phase = 0; phase < 2; ++phase)
    {
      const F2 *u = phase == 0 ? ug : us;
      F1        div (0.0);
      for (unsigned int d = 0; d < dim; ++d)
        div += u[d].dx (d);
      const F1 mu = phase == 0 ? F1 ((1.0 - a.val ()) * mu_g) : F1 (mu_s);
      for (unsigned int i = 0; i < dim; ++i)
      {
        double sum = 0;
        for (unsigned int j = 0; j < dim; ++j)
        {
          F1 tau = mu * (u[i].dx (j) + u[j].dx (i));
          if (i == j)
            tau -= 2.0 / 3.0 * mu * div;
          sum += tau.dx (j);
        }
        (phase == 0 ? s.div_tau_g : s.div_tau_s)[i] = sum;
      }
    }
    return s;
  }

  Tensor<1, dim> residual (const Point<dim> &x, const bool gas) const
  {
    const Derived s  = derive (x);
    const auto   &pp = parameters.physical;
    // the solids inertia and drag at no less than the residual fraction, as assembled
    const double          alpha_inertia = std::max (s.alpha, pp.residual_solids_fraction);
    const double          alpha_k       = gas ? 1 - s.alpha : s.alpha;
    const double          inertia_k     = gas ? 1 - s.alpha : alpha_inertia;
    const double          rho_k         = gas ? pp.gas_density : pp.particle_density;
    const Tensor<1, dim> &u             = gas ? s.ug : s.us;
    const Tensor<2, dim> &g             = gas ? s.grad_ug : s.grad_us;
    const closures::GasParticleProperties gp{
        pp.gas_density, pp.gas_viscosity, pp.particle_diameter};
    const double beta = drag->coefficient (alpha_inertia, (s.ug - s.us).norm (), gp);
    // alpha_s is steady: d(alpha_k u_k)/dt = alpha_k du_k/dt in both forms (the
    // rotation is steady and ignores the scale)
    const Tensor<1, dim> dudt = transient ? velocity (x, gas, true) : Tensor<1, dim> ();
    Tensor<1, dim>       r    = inertia_k * rho_k * (dudt + g * u) -
                       (gas ? s.div_tau_g : s.div_tau_s) + alpha_k * s.grad_p;
    // the conservative form's rho_k div(alpha_k u_k) u_k (steady: the time parts vanish)
    if (parameters.continuity_weight () > 0)
    {
      const double slope =
          gas ? -1.0 : (s.alpha > pp.residual_solids_fraction ? 1.0 : 0.0);
      r += parameters.continuity_weight () * rho_k *
           (inertia_k * trace (g) + slope * (s.grad_alpha * u)) * u;
    }
    if (gas)
      r += beta * (s.ug - s.us);
    else
    {
      Tensor<1, dim> gravity;
      for (unsigned int d = 0; d < dim; ++d)
        gravity[d] = pp.gravity[d];
      const double slope =
          two_fluid ? stress->evaluate ({s.alpha, 0.0, 0.0}).pressure_derivative : 0.0;
      r += slope * s.grad_alpha - beta * (s.ug - s.us) -
           s.alpha * (pp.particle_density - pp.gas_density) * gravity;
    }
    return r;
  }

  bool                                         two_fluid, rotation, transient, polynomial;
  Parameters                                   parameters;
  std::unique_ptr<closures::DragModel>         drag;
  std::unique_ptr<closures::SolidsStressModel> stress;
};

/** Time stepping of a run: steady (one step of 1e4, BDF1) or a transient ladder rung. */
struct TimeStepping
{
  double       end_time  = 1e4;
  unsigned int steps     = 1;
  unsigned int bdf_order = 1;
};

std::string case_text (const int           dim,
                       const std::string  &mesh,
                       const unsigned int  refinement,
                       const std::string  &folder,
                       const std::string  &no_penetration,
                       const TimeStepping &time)
{
  std::ostringstream s;
  s << "set dimension = " << dim << "\n"
    << "subsection mesh\n set file = " << mesh
    << "\n set initial refinement = " << refinement
    << "\n set cylindrical wall = " << (dim == 3 ? "true" : "false") << "\nend\n"
    << "subsection physical properties\n set gas density = 1\n set gas viscosity = 0.05\n"
    << " set particle density = 2\n set particle diameter = 0.01\n set maximum packing = "
       "0.61\n"
    << " set gravity = 0, " << (dim == 2 ? "-1, 0" : "0, -1") << "\nend\n"
    << "subsection drag\n set model = Wen-Yu\nend\n"
    << "subsection solids stress\n set shear viscosity = 0.1\n set frictional "
       "coefficient = 0.5\n"
    << " set frictional onset = 0.15\nend\n"
    << "subsection stabilization\n set enabled = false\nend\n"
    << "subsection boundary conditions\n set inlet superficial velocity = 0\n"
    << " set gas wall condition = " << (no_penetration.empty () ? "no-slip" : "free-slip")
    << "\n set solids wall condition = free-slip\n set no-penetration = "
    << (no_penetration.empty () ? "Nitsche" : no_penetration) << "\nend\n"
    << "subsection time stepping\n set end time = " << time.end_time
    << "\n set initial time step = " << time.end_time / time.steps
    << "\n set maximum time step = " << time.end_time / time.steps
    << "\n set bdf order = " << time.bdf_order
    << "\n set outer iterations = 6\n set adaptive = false\nend\n"
    << "subsection linear solver\n set relative tolerance = 1e-12\n set maximum "
       "iterations = 5000\n"
    // the Nitsche penalty on the curved wall couples the components of a node: node
    // blocks relaxed exactly (point smoothers stall, doc/theory.md)
    << (no_penetration == "Nitsche" ? " set velocity smoother = block Gauss-Seidel\n"
                                    : "")
    << "end\n"
    << "subsection output\n set folder = " << folder
    << "\n set field interval = 0\nend\n";
  return s.str ();
}

/**
 * Settings that refine the cells below y = 1/2 once more than `refinement` at the start
 * (the adaptive refinement's distributor band; no indicator-driven refinement or
 * coarsening): a mesh with hanging nodes along y = 1/2.
 */
std::string hanging_nodes_text (const unsigned int refinement)
{
  std::ostringstream s;
  s << "subsection adaptive refinement\n set enabled = true\n set minimum level = "
    << refinement << "\n set maximum level = " << refinement + 1
    << "\n set distributor band height = 0.5\n set refine threshold = 1e30\n"
    << " set coarsen threshold = 0\n set initial cycles = 1\n set interval = "
       "1000000\nend\n";
  return s.str ();
}

/** Errors (u_g L2, H1, u_s L2, H1, p' L2) and the cell count of one refinement level. */
template <int dim>
std::pair<std::array<double, 5>, double> run_level (const Parameters &parameters,
                                                    const bool        two_fluid,
                                                    const bool        rotation,
                                                    const bool        transient,
                                                    const bool        polynomial)
{
  TwoFluidSolver<dim> solver (parameters, MPI_COMM_WORLD);
  solver.set_verification_hook (std::make_shared<ManufacturedHook<dim>> (
      std::make_shared<ManufacturedTwoFluid<dim>> (
          two_fluid, parameters, rotation, transient, polynomial)));
  solver.run ();
  const auto r = solver.compute_errors ();
  return {{r.gas_velocity_l2,
           r.gas_velocity_h1,
           r.solids_velocity_l2,
           r.solids_velocity_h1,
           r.pressure_l2},
          double (solver.n_cells ())};
}
} // namespace

/** "1,2,3" -> {1, 2, 3} */
std::vector<unsigned int> numbers (const std::string &list)
{
  std::vector<unsigned int> values;
  std::stringstream         in (list);
  for (std::string item; std::getline (in, item, ',');)
    values.push_back (std::stoul (item));
  return values;
}

// usage: test_mms_convergence DIM KIND SOURCE_DIR WORK_DIR [EXTRA_SETTINGS.prm|-]
//                             [LEVELS] [STEPS]
//   KIND: single | two-fluid | rotation-Nitsche | rotation-strong: steady, a ladder of
//           LEVELS (default 1,2,3 in 2D, 0,1,2 in 3D);
//         two-fluid-hanging: two-fluid with the cells below y = 1/2 one level finer
//           (hanging nodes along y = 1/2 on every mesh of the ladder);
//         transient-bdf1 | transient-bdf2: quadratic velocities and a linear pressure
//           (in the discrete spaces on affine cells: no spatial error) times
//           s(t) = 1 + sin(2 pi t)/2 over 0 < t <= 0.3, on the first of LEVELS, a ladder
//           of STEPS time steps (default 12,24,48): the rate of the time discretisation;
//           the frictional pressure is off (onset 0.5 above the fields' alpha_s), as its
//           discrete gradient is not exact for these fields;
//         space-time-bdf1 | space-time-bdf2: the two-fluid fields times s(t), LEVELS
//           and STEPS paired (default 3,6,12 steps): space and time refined together
//   LEVELS, STEPS: comma-separated lists replacing the defaults (work-precision study,
//         benchmarks/mms_work_precision.py); each run prints a "run:" line with its
//         cells, steps, errors and wall time
//   --reference=SETTINGS.prm (anywhere after KIND): the first runs of the ladder (two,
//         or N with --reference-runs=N) repeated with these settings appended as well
//         (another operator or preconditioner): their errors must equal the ladder's to
//         1e-5 (the same discretisation, FGMRES to 1e-12, 6 outer iterations of the
//         nonlinear closures; 2D two-fluid, second mesh: 2.3e-7 apart measured, and
//         2.2e-5 with FGMRES to 1e-10, whose residual leaves ~4e-10 of the O(1) fields
//         against errors of 1.6e-5), or to --reference-tolerance=X
//   --check-runs=N: the operator check of EXTRA_SETTINGS (`check operator = true`) on
//         the first N runs of the ladder only (its cost grows with the assembled matrix;
//         the check is per assembly, not per mesh size)
int main (int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi (argc, argv, 1);
  std::string                              reference_settings;
  unsigned int                             reference_runs = 2;
  unsigned int check_runs          = std::numeric_limits<unsigned int>::max ();
  double       reference_tolerance = 1e-5;
  {
    const std::string flag = "--reference=", runs_flag = "--reference-runs=",
                      tolerance_flag = "--reference-tolerance=",
                      check_flag     = "--check-runs=";
    int kept                         = 1;
    for (int i = 1; i < argc; ++i)
    {
      const std::string argument = argv[i];
      if (argument.rfind (flag, 0) == 0)
        reference_settings = argument.substr (flag.size ());
      else if (argument.rfind (runs_flag, 0) == 0)
        reference_runs = std::stoul (argument.substr (runs_flag.size ()));
      else if (argument.rfind (tolerance_flag, 0) == 0)
        reference_tolerance = std::stod (argument.substr (tolerance_flag.size ()));
      else if (argument.rfind (check_flag, 0) == 0)
        check_runs = std::stoul (argument.substr (check_flag.size ()));
      else
        argv[kept++] = argv[i];
    }
    argc = kept;
  }
  const int         dim  = std::stoi (argv[1]);
  const std::string kind = argv[2];
  // transient-*: polynomial fields in space (the time error alone); space-time-*: the
  // trigonometric fields of two-fluid times s(t) (space and time errors together)
  const bool polynomial = kind.rfind ("transient", 0) == 0;
  const bool transient  = polynomial || kind.rfind ("space-time", 0) == 0;
  const bool two_fluid = kind != "single", rotation = kind.rfind ("rotation", 0) == 0;
  // two-fluid-hanging: the lower half of the square one level finer than the upper half
  // (the distributor band of the adaptive refinement), so every mesh has a line of
  // hanging nodes at y = 1/2 across the flow
  const bool        hanging        = kind == "two-fluid-hanging";
  const std::string no_penetration = rotation ? kind.substr (kind.find ('-') + 1) : "";
  const std::string source = argv[3], work = argv[4];
  // diagnosis: a file of further settings appended to every level's case
  std::string extra_settings = testing::extra_settings (argc, argv, 5);
  if (polynomial)
    extra_settings =
        "subsection solids stress\n set frictional onset = 0.5\nend\n" + extra_settings;
  const std::string mesh =
      source + (dim == 2 ? "/tests/meshes/square.geo" : "/tests/meshes/cylinder.geo");
  std::vector<unsigned int> levels =
      dim == 2 ? std::vector<unsigned int>{1, 2, 3} : std::vector<unsigned int>{0, 1, 2};
  if (argc > 6)
    levels = numbers (argv[6]);
  // transient: the finest mesh, where the spatial error is well below the temporal one
  std::vector<unsigned int> steps = polynomial
                                        ? std::vector<unsigned int>{12, 24, 48}
                                        : (transient ? std::vector<unsigned int>{3, 6, 12}
                                                     : std::vector<unsigned int>{1});
  if (argc > 7)
    steps = numbers (argv[7]);
  const unsigned int bdf_order = kind.back () == '2' ? 2 : 1;
  // the (level, steps) pairs: a time ladder on one mesh, a space ladder at one step, or
  // (space-time) both refined together
  std::vector<std::pair<unsigned int, unsigned int>> runs;
  if (polynomial)
    for (const unsigned int n : steps)
      runs.emplace_back (levels.front (), n); // no spatial error: the coarsest mesh
  else if (transient)
  {
    if (levels.size () != steps.size ())
    {
      std::cerr << "space-time runs need as many LEVELS as STEPS\n";
      return 1;
    }
    for (unsigned int i = 0; i < levels.size (); ++i)
      runs.emplace_back (levels[i], steps[i]);
  }
  else
    for (const unsigned int level : levels)
      runs.emplace_back (level, 1);

  constexpr double transient_end = 0.3; // s
  // one run of the ladder (or of the reference, with its settings appended): its errors
  // and cell count
  const auto run_case = [&] (const unsigned int level,
                             const unsigned int n_steps,
                             const std::string &settings,
                             const std::string &suffix)
  {
    TimeStepping time;
    if (transient)
      time = TimeStepping{transient_end, n_steps, bdf_order};
    const std::string folder = work + "/mms_" + std::to_string (dim) + "d_" + kind + "_" +
                               std::to_string (level) +
                               (transient ? "_" + std::to_string (n_steps) : "") + suffix;
    std::filesystem::create_directories (folder);
    const std::string prm_file = folder + "/case.prm";
    std::ofstream (prm_file) << case_text (dim, mesh, level, folder, no_penetration, time)
                             << (hanging ? hanging_nodes_text (level) : "") << settings;
    dealii::ParameterHandler prm;
    const Parameters         parameters = Parameters::read (prm_file, prm);
    const auto               start      = std::chrono::steady_clock::now ();
    const auto               result =
        dim == 2 ? run_level<2> (parameters, two_fluid, rotation, transient, polynomial)
                               : run_level<3> (parameters, two_fluid, rotation, transient, polynomial);
    const double wall =
        std::chrono::duration<double> (std::chrono::steady_clock::now () - start)
            .count ();
    std::cout << std::defaultfloat << "run" << suffix << ": level " << level << " cells "
              << static_cast<unsigned long> (result.second) << " steps " << n_steps
              << " bdf " << bdf_order << " wall " << wall << " errors";
    for (const double value : result.first)
      std::cout << " " << std::setprecision (6) << std::scientific << value;
    std::cout << std::defaultfloat << std::endl;
    return result;
  };

  std::vector<std::array<double, 5>> errors;
  std::vector<double>                sizes;
  for (const auto &[level, n_steps] : runs)
  {
    const bool checked = errors.size () < check_runs;
    const auto [e, n_cells] =
        run_case (level,
                  n_steps,
                  extra_settings + (checked ? ""
                                            : "subsection linear solver\n set check "
                                              "operator = false\nend\n"),
                  "");
    // the hanging nodes are there: more cells than the uniform mesh of the level (the
    // square has 16 cells at level 0), fewer than the next level's
    if (hanging)
      testing::check (n_cells > 16 * std::pow (4.0, level) &&
                          n_cells < 16 * std::pow (4.0, level + 1),
                      "a locally refined mesh at level " + std::to_string (level));
    errors.push_back (e);
    sizes.push_back (polynomial ? transient_end / n_steps
                                : std::pow (n_cells, -1.0 / dim));
  }

  const std::array<std::string, 5> names = {
      "|u_g|_L2", "|grad u_g|_L2", "|u_s|_L2", "|grad u_s|_L2", "|p'|_L2"};
  // Nitsche on the curved wall: on the three meshes a 3D test can afford (24, 192, 1536
  // cells) the velocity converges at 2.6 (L2) and 1.56 (H1) against 3.6 and 2.6 with
  // the strong constraints; asserted as measured, the gap is discussed in
  // doc/theory.md ("No penetration by symmetric Nitsche")
  std::array<double, 5> expected = no_penetration == "Nitsche"
                                       ? std::array<double, 5>{2.7, 1.7, 2.7, 1.7, 2}
                                       : std::array<double, 5>{3, 2, 3, 2, 2};
  if (polynomial)
    expected.fill (bdf_order);
  std::cout << "MMS " << dim << "D " << argv[2] << (polynomial ? " (rates in dt)" : "")
            << "\n";
  if (errors.size () > 1)
    testing::report_rates (errors, sizes, names, expected);
  if (!reference_settings.empty ())
  {
    const std::string settings = extra_settings + testing::file_text (reference_settings);
    for (unsigned int i = 0; i < std::min<std::size_t> (reference_runs, runs.size ());
         ++i)
    {
      const auto e =
          run_case (runs[i].first, runs[i].second, settings, "_reference").first;
      double difference = 0;
      for (unsigned int k = 0; k < e.size (); ++k)
        difference = std::max (difference, std::abs (e[k] - errors[i][k]) / errors[i][k]);
      std::cout << "reference " << reference_settings << ", level " << runs[i].first
                << ": errors equal to " << std::scientific << std::setprecision (2)
                << difference << " (relative)" << std::defaultfloat << "\n";
      testing::check (difference <= reference_tolerance,
                      "the errors with the reference settings, level " +
                          std::to_string (runs[i].first) + ", differ by " +
                          std::to_string (difference));
    }
  }
  return testing::finish ("mms_convergence");
}
