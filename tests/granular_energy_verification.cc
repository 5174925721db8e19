// T4, T5, T6: the granular energy equation in the full solver on homogeneous states
// (4 x 4 unit square, alpha_s = 0.3 held, fixed steps, converged outer iterations).
//   haff:    homogeneous cooling without gas, Theta = Theta0/(1 + t/t_H)^2;
//            BDF1 and BDF2 observed orders asserted (1 and 2, +-0.15).
//   damping: cooling with gas damping (Syamlal-O'Brien drag at zero slip),
//            3/2 alpha rho dTheta/dt = -K Theta^(3/2) - 3 beta Theta, analytic
//            Theta^(-1/2) = (Theta0^(-1/2) + a/b) exp(b t/2) - a/b; rel. error <= 2e-6,
//            BDF2 observed order >= 1.85.
//   wet:     wet homogeneous cooling without gas (seed-000 bridges, a thinner liquid,
//            mu_L = 5 mPa s, so that St > St* and e_wet = e_dry (1 - St*/St) varies with
//            Theta): 3/2 alpha rho dTheta/dt = -K(e_wet(Theta)) Theta^(3/2) against an
//            RK4 solution with 2e5 steps; rel. error <= 1e-5 at 1000 steps, BDF2 order
//            >= 1.85.
//   shear:   frozen homogeneous simple shear u_s = (0, G (x - 1/2)): Theta uniform and
//            equal to the production = dissipation balance (the algebraic model's
//            value), from the PDE run to steady state and from the algebraic model.
// usage: test_granular_energy_verification haff|damping|wet|shear SOURCE_DIR WORK_DIR
#include "test_utilities.h"

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>
#include <wetbed/core/parameters.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <iomanip>

using namespace wetbed;

namespace
{
constexpr double alpha_s = 0.3;

struct Case
{
  std::string  drag = "none", granular_temperature = "PDE", held_velocity = "0; 0; 0";
  double       restitution = 0.9, initial_temperature = 1e-2;
  double       end_time = 1e-2, time_step = 1e-3;
  unsigned int bdf_order = 2;
  std::string  extra; // further subsections (the wet particles)
};

std::string
case_text (const Case &c, const std::string &source, const std::string &folder)
{
  std::ostringstream s;
  s << std::setprecision (17) << "set dimension = 2\n"
    << "subsection mesh\n set file = " << source << "/tests/meshes/square.geo\nend\n"
    << "subsection drag\n set model = " << c.drag << "\nend\n"
    << "subsection solids stress\n set model = kinetic theory\nend\n"
    << "subsection kinetic theory\n set granular temperature = " << c.granular_temperature
    << "\n set restitution coefficient = " << c.restitution
    << "\n set initial granular temperature = " << c.initial_temperature << "\nend\n"
    << "subsection boundary conditions\n set inlet superficial velocity = 0\n"
    << " set hold solids = true\n set held solids velocity = " << c.held_velocity
    << "\nend\n"
    << "subsection initial conditions\n set bed height = 1\n set bed solids fraction = "
    << alpha_s << "\n set gas at inlet velocity = false\nend\n"
    << "subsection time stepping\n set end time = " << c.end_time
    << "\n set initial time step = " << c.time_step
    << "\n set maximum time step = " << c.time_step << "\n set adaptive = false\n"
    << " set bdf order = " << c.bdf_order
    << "\n set outer iterations = 4\n set outer tolerance = 0\nend\n"
    << "subsection linear solver\n set scalar tolerance = 1e-13\nend\n"
    << "subsection output\n set folder = " << folder
    << "\n set field interval = 0\n set progress interval = 100000\nend\n"
    << c.extra;
  return s.str ();
}

struct Result
{
  double     theta_min, theta_mean, theta_max;
  Parameters parameters;
};

Result run (const Case &c, const std::string &source, const std::string &folder)
{
  std::filesystem::create_directories (folder);
  const std::string prm_file = folder + "/case.prm";
  std::ofstream (prm_file) << case_text (c, source, folder);
  dealii::ParameterHandler prm;
  const Parameters         parameters = Parameters::read (prm_file, prm);
  TwoFluidSolver<2>        solver (parameters, MPI_COMM_WORLD);
  solver.run ();
  const auto &row = solver.last_monitors ();
  return {row.theta_min, row.theta_mean, row.theta_max, parameters};
}

/** Collisional dissipation K (gamma = K Theta^(3/2)) and beta at zero slip. */
std::pair<double, double> sink_coefficients (const Parameters &p)
{
  const auto stress = closures::create_solids_stress_model (
      p.solids_stress, p.physical, p.kinetic_theory, p.wet);
  const auto                            drag = closures::create_drag_model (p.drag_model);
  const closures::GasParticleProperties gp{
      p.physical.gas_density, p.physical.gas_viscosity, p.physical.particle_diameter};
  return {stress->kinetic_theory ()->evaluate (alpha_s, 1.0).dissipation_factor,
          drag->coefficient (alpha_s, 0.0, gp)};
}

double observed_order (const std::vector<double> &errors)
{
  const unsigned int n = errors.size () - 1;
  return std::log2 (errors[n - 1] / errors[n]);
}

void check_uniform (const Result &r, const std::string &what)
{
  testing::check ((r.theta_max - r.theta_min) <= 1e-10 * r.theta_mean,
                  what + ": Theta not uniform");
}

void haff (const std::string &source, const std::string &work)
{
  for (const unsigned int order : {1u, 2u})
  {
    std::vector<double> errors;
    for (const unsigned int steps : {10u, 20u, 40u, 80u})
    {
      Case c;
      c.bdf_order           = order;
      c.time_step           = c.end_time / steps;
      const Result r        = run (c,
                            source,
                            work + "/haff_bdf" + std::to_string (order) + "_" +
                                std::to_string (steps));
      const double capacity = 1.5 * alpha_s * r.parameters.physical.particle_density;
      const double a        = sink_coefficients (r.parameters).first / capacity;
      const double t_haff   = 2.0 / (a * std::sqrt (c.initial_temperature));
      const double exact =
          c.initial_temperature / std::pow (1.0 + c.end_time / t_haff, 2);
      check_uniform (r, "Haff");
      errors.push_back (std::abs (r.theta_mean - exact) / exact);
      std::cout << "Haff BDF" << order << " dt = " << std::scientific
                << std::setprecision (3) << c.time_step
                << "  t/t_H = " << c.end_time / t_haff
                << "  Theta = " << std::setprecision (10) << r.theta_mean << " exact "
                << exact << "  rel. error " << std::setprecision (3) << errors.back ()
                << std::endl;
    }
    const double rate = observed_order (errors);
    std::cout << "Haff BDF" << order << " observed order " << std::fixed
              << std::setprecision (3) << rate << std::endl;
    testing::check (std::abs (rate - order) <= 0.15,
                    "Haff BDF" + std::to_string (order) + " order " +
                        std::to_string (rate));
  }
}

void damping (const std::string &source, const std::string &work)
{
  Case c;
  c.drag                = "Syamlal-O'Brien";
  c.restitution         = 0.99;
  c.initial_temperature = 1e-3;
  c.end_time            = 0.2;
  std::vector<double> errors;
  for (const unsigned int steps : {250u, 500u, 1000u})
  {
    c.time_step           = c.end_time / steps;
    const Result r        = run (c, source, work + "/damping_" + std::to_string (steps));
    const auto [K, beta]  = sink_coefficients (r.parameters);
    const double capacity = 1.5 * alpha_s * r.parameters.physical.particle_density;
    const double a = K / capacity, b = 3 * beta / capacity;
    const double y = (1 / std::sqrt (c.initial_temperature) + a / b) *
                         std::exp (0.5 * b * c.end_time) -
                     a / b;
    const double exact = 1 / (y * y);
    check_uniform (r, "damping");
    errors.push_back (std::abs (r.theta_mean - exact) / exact);
    std::cout << "damping dt = " << std::scientific << std::setprecision (3)
              << c.time_step
              << "  a sqrt(Theta0) = " << a * std::sqrt (c.initial_temperature)
              << " 1/s, b = " << b << " 1/s  Theta = " << std::setprecision (10)
              << r.theta_mean << " exact " << exact << "  rel. error "
              << std::setprecision (3) << errors.back () << std::endl;
  }
  std::cout << "damping BDF2 observed order " << std::fixed << std::setprecision (3)
            << observed_order (errors) << std::endl;
  // 1.27e-6 at 1000 steps, order 2.01 (before the Theta GMRES was right-preconditioned
  // its loose true residual showed as 7.1e-7 and a spurious order 2.54)
  testing::check (errors.back () <= 2e-6,
                  "damping: rel. error " + std::to_string (errors.back ()) + " > 2e-6");
  testing::check (observed_order (errors) >= 1.85, "damping: order");
}

void wet (const std::string &source, const std::string &work)
{
  Case c;
  c.initial_temperature = 1e-2;
  c.end_time            = 2e-3;
  c.extra =
      "subsection wet particles\n set liquid loading = 5e-3\n set liquid viscosity = "
      "5e-3\nend\n";
  std::vector<double> errors;
  for (const unsigned int steps : {250u, 500u, 1000u})
  {
    c.time_step       = c.end_time / steps;
    const Result r    = run (c, source, work + "/wet_" + std::to_string (steps));
    const auto stress = closures::create_solids_stress_model (r.parameters.solids_stress,
                                                              r.parameters.physical,
                                                              r.parameters.kinetic_theory,
                                                              r.parameters.wet);
    const closures::KineticTheory &theory = *stress->kinetic_theory ();
    const double capacity = 1.5 * alpha_s * r.parameters.physical.particle_density;
    // reference: RK4 on dTheta/dt = -K(e_wet(Theta)) Theta^(3/2) / capacity
    const auto rate = [&] (const double theta)
    {
      return -theory.evaluate (alpha_s, theta).dissipation_factor *
             std::pow (theta, 1.5) / capacity;
    };
    const unsigned int n     = 200000;
    const double       h     = c.end_time / n;
    double             exact = c.initial_temperature;
    for (unsigned int k = 0; k < n; ++k)
    {
      const double k1 = rate (exact), k2 = rate (exact + 0.5 * h * k1),
                   k3 = rate (exact + 0.5 * h * k2), k4 = rate (exact + h * k3);
      exact += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    check_uniform (r, "wet cooling");
    errors.push_back (std::abs (r.theta_mean - exact) / exact);
    std::cout << "wet cooling dt = " << std::scientific << std::setprecision (3)
              << c.time_step << "  e_wet " << std::setprecision (4)
              << theory.evaluate (alpha_s, c.initial_temperature).restitution << " -> "
              << theory.evaluate (alpha_s, exact).restitution
              << "  Theta = " << std::setprecision (10) << r.theta_mean << " RK4 "
              << exact << "  rel. error " << std::setprecision (3) << errors.back ()
              << std::endl;
  }
  std::cout << "wet cooling BDF2 observed order " << std::fixed << std::setprecision (3)
            << observed_order (errors) << std::endl;
  testing::check (errors.back () <= 1e-5,
                  "wet cooling: rel. error " + std::to_string (errors.back ()) +
                      " > 1e-5");
  testing::check (observed_order (errors) >= 1.85, "wet cooling: order");
}

void shear (const std::string &source, const std::string &work)
{
  const double shear_rate = 100;
  Case         c;
  c.held_velocity        = "0; " + std::to_string (shear_rate) + " * (x - 0.5); 0";
  c.initial_temperature  = 1e-2;
  c.end_time             = 1;
  c.time_step            = 0.02;
  const Result pde       = run (c, source, work + "/shear_pde");
  c.granular_temperature = "algebraic";
  c.end_time             = 0.02;
  const Result algebraic = run (c, source, work + "/shear_algebraic");

  const auto stress = closures::create_solids_stress_model (pde.parameters.solids_stress,
                                                            pde.parameters.physical,
                                                            pde.parameters.kinetic_theory,
                                                            pde.parameters.wet);
  // D = sym(grad u_s): D_xy = G/2, D:D = G^2/2, tr D = 0
  const double balance = stress->kinetic_theory ()->algebraic_temperature (
      alpha_s, 0.0, 0.5 * shear_rate * shear_rate, 0.0);
  const auto   k          = stress->kinetic_theory ()->evaluate (alpha_s, pde.theta_mean);
  const double production = k.shear_viscosity * shear_rate * shear_rate,
               dissipation = k.dissipation_factor * std::pow (pde.theta_mean, 1.5);
  std::cout << std::scientific << std::setprecision (10) << "shear G = " << shear_rate
            << " 1/s: Theta PDE " << pde.theta_mean << " [" << pde.theta_min << ", "
            << pde.theta_max << "], algebraic " << algebraic.theta_mean << ", balance "
            << balance << "; production " << production << " dissipation " << dissipation
            << " W/m^3" << std::endl;
  check_uniform (pde, "shear PDE");
  check_uniform (algebraic, "shear algebraic");
  testing::check_close (pde.theta_mean, balance, 1e-8, "shear: PDE steady Theta");
  testing::check_close (algebraic.theta_mean, balance, 1e-10, "shear: algebraic Theta");
  testing::check_close (production, dissipation, 1e-7, "shear: production = dissipation");
}
} // namespace

int main (int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi (argc, argv, 1);
  const std::string which = argv[1], source = argv[2], work = argv[3];
  if (which == "haff")
    haff (source, work);
  else if (which == "damping")
    damping (source, work);
  else if (which == "wet")
    wet (source, work);
  else if (which == "shear")
    shear (source, work);
  else
  {
    std::cout << "unknown case '" << which << "'" << std::endl;
    return 1;
  }
  return testing::finish ("granular_energy_verification " + which);
}
