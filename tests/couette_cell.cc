// T12: the Johnson-Jackson Couette cell (prm/couette_cell_2d.prm): 1 mm beads between a
// wall sliding at V = 0.5 m/s (x = 0) and a fixed wall (x = W = 5 mm), periodic along
// the walls, kinetic theory with the Theta PDE, Johnson-Jackson walls (tangential Robin
// traction relative to the wall, wall energy flux G_w - D_w) with Nitsche no-penetration,
// no gas drag, gravity out of the plane. It settles to a 1D steady state (run to 0.6 s).
// Runs nx = 8, 16, 32 cells across the gap and a reference with 128 and asserts:
//   - steady and 1D: |u_s,x| <= 1e-4 V, the profiles at y = L/4 and L/2 equal (1e-8);
//   - the gas (no-slip walls, no drag, 100x its viscosity to settle in 0.02 s) carries
//     a uniform shear stress: u_g = V (1 - int 1/alpha_g / int_0^W 1/alpha_g) (1e-4 V);
//   - solids mass conserved (1e-12), alpha_s mean 0.3;
//   - the errors of u_s,y / V, Theta / max Theta, alpha_s against the reference (RMS
//     over 200 points across the gap) fall at observed rates >= 1.7 between the
//     three coarse meshes (design order 2: Q1 alpha_s and Theta feed the closures);
//   - the walls slip (Johnson-Jackson): 0 < slip < V at both walls.
// usage: test_couette_cell SOURCE_DIR WORK_DIR   (run with 1 or more MPI ranks)
#include "test_utilities.h"

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace wetbed;

namespace
{
constexpr double       width = 0.005, height = 0.000625, wall_speed = 0.5;
constexpr unsigned int n_points = 200;

struct Profile
{
  std::vector<double> solids_speed, theta, alpha, gas_speed;
  double              cross_speed_max = 0, gas_cross_speed_max = 0, gas_error_max = 0;
  double              y_difference_max = 0;
  double              mass_drift = 0, alpha_mean = 0;
};

Profile run (const unsigned int nx, const std::string &source, const std::string &work)
{
  const std::string folder = work + "/nx" + std::to_string (nx);
  const bool        root = dealii::Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0;
  if (root)
  {
    std::filesystem::create_directories (folder);
    std::ifstream      geo_in (source + "/meshes/couette_cell_2d.geo");
    std::ostringstream geo;
    geo << geo_in.rdbuf ();
    std::ofstream (folder + "/cell.geo") << std::regex_replace (
        geo.str (), std::regex ("nx = \\{16,"), "nx = {" + std::to_string (nx) + ",");
    std::ifstream      prm_in (source + "/prm/couette_cell_2d.prm");
    std::ostringstream prm;
    prm << prm_in.rdbuf () << "subsection mesh\n set file = " << folder
        << "/cell.geo\nend\n"
        << "subsection output\n set folder = " << folder
        << "\n set field interval = 0\n set progress interval = 100000\nend\n"
        << "subsection checkpoint\n set at end = false\nend\n"
        // the gas is decoupled (no drag): a 100x more viscous gas reaches its steady
        // Couette profile in 0.02 s instead of 2 s
        << "subsection physical properties\n set gas viscosity = 1.8e-3\nend\n"
        // the solids settle with a time constant of ~0.09 s: at 0.6 s the profile is
        // steady to ~1e-5 of its speed (the checks' tolerances are 1e-4); two outer
        // iterations at every step, each solve to 1e-8: the checks ask the algebra for
        // 1e-5 V, beyond what the default outer convergence test accepts
        << "subsection time stepping\n set end time = 0.6\n set outer tolerance = 0\n"
        << " set outer iterations = 2\nend\n";
    std::ofstream (folder + "/case.prm") << prm.str ();
  }
  MPI_Barrier (MPI_COMM_WORLD);
  dealii::ParameterHandler handler;
  const Parameters         parameters = Parameters::read (folder + "/case.prm", handler);
  TwoFluidSolver<2>        solver (parameters, MPI_COMM_WORLD);
  solver.run ();

  std::vector<dealii::Point<2>> points;
  for (unsigned int i = 0; i < n_points; ++i)
  {
    const double x = (i + 0.5) / n_points * width;
    points.emplace_back (x, 0.5 * height);
    points.emplace_back (x, 0.25 * height);
  }
  const auto values = solver.sample (points);
  Profile    p;
  for (unsigned int i = 0; i < n_points; ++i)
  {
    const auto &v = values[2 * i], &w = values[2 * i + 1]; // u_g, u_s, p', alpha_s, Theta
    p.solids_speed.push_back (v[3]);
    p.alpha.push_back (v[5]);
    p.theta.push_back (v[6]);
    p.cross_speed_max = std::max (p.cross_speed_max, std::abs (v[2]));
    p.gas_speed.push_back (v[1]);
    p.gas_cross_speed_max = std::max (p.gas_cross_speed_max, std::abs (v[0]));
    for (const unsigned int c : {3u, 5u, 6u})
      p.y_difference_max = std::max (
          p.y_difference_max, std::abs (v[c] - w[c]) / std::max (std::abs (v[c]), 1e-12));
    p.alpha_mean += v[5] / n_points;
  }
  // the gas (no drag, no-slip walls, no pressure gradient along the cell) carries a
  // uniform shear stress alpha_g mu_g du_g/dx: u_g = V (1 - int_0^x 1/alpha_g / int_0^W
  // 1/alpha_g), the integrals by the midpoint rule over the sample points
  std::vector<double> resistance (n_points + 1, 0.0);
  for (unsigned int i = 0; i < n_points; ++i)
    resistance[i + 1] = resistance[i] + 1.0 / (1.0 - p.alpha[i]);
  for (unsigned int i = 0; i < n_points; ++i)
  {
    const double exact = wall_speed * (1 - 0.5 * (resistance[i] + resistance[i + 1]) /
                                               resistance[n_points]);
    p.gas_error_max    = std::max (p.gas_error_max, std::abs (p.gas_speed[i] - exact));
  }
  p.mass_drift = solver.last_monitors ().mass_drift;
  return p;
}

double rms_difference (const std::vector<double> &a,
                       const std::vector<double> &b,
                       const double               scale)
{
  double sum = 0;
  for (unsigned int i = 0; i < a.size (); ++i)
    sum += std::pow ((a[i] - b[i]) / scale, 2);
  return std::sqrt (sum / a.size ());
}
} // namespace

int main (int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi (argc, argv, 1);
  const std::string                        source = argv[1], work = argv[2];
  const bool    root = dealii::Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0;
  const Profile reference = run (argc > 3 ? std::stoi (argv[3]) : 128, source, work);
  const double  theta_scale =
      *std::max_element (reference.theta.begin (), reference.theta.end ());
  std::vector<std::array<double, 3>> errors;
  std::vector<Profile>               coarse;
  for (const unsigned int nx : {8u, 16u, 32u})
  {
    coarse.push_back (run (nx, source, work));
    const Profile &p = coarse.back ();
    errors.push_back (std::array<double, 3>{
        rms_difference (p.solids_speed, reference.solids_speed, wall_speed),
        rms_difference (p.theta, reference.theta, theta_scale),
        rms_difference (p.alpha, reference.alpha, 0.3)});
  }
  const char *names[3] = {"u_s,y", "Theta", "alpha_s"};
  if (root)
  {
    std::cout << std::scientific << std::setprecision (3)
              << "reference (128 cells across): u_s,y at the moving wall "
              << reference.solids_speed.front () << " m/s (slip "
              << wall_speed - reference.solids_speed.front () << "), at the fixed wall "
              << reference.solids_speed.back () << " m/s; Theta "
              << reference.theta.front () << " .. " << reference.theta.back ()
              << " m^2/s^2; alpha_s " << reference.alpha.front () << " .. "
              << reference.alpha.back () << "\n";
    for (unsigned int k = 0; k < 3; ++k)
      std::cout << "nx = " << (8 << k) << ": errors u_s,y/V " << errors[k][0]
                << ", Theta " << errors[k][1] << ", alpha_s " << errors[k][2]
                << "; |u_s,x| max " << coarse[k].cross_speed_max << ", gas error "
                << coarse[k].gas_error_max << ", |u_g,x| max "
                << coarse[k].gas_cross_speed_max << ", y-variation "
                << coarse[k].y_difference_max << "\n";
  }
  for (unsigned int f = 0; f < 3; ++f)
    for (unsigned int k = 0; k + 1 < 3; ++k)
    {
      const double rate = std::log2 (errors[k][f] / errors[k + 1][f]);
      if (root)
        std::cout << names[f] << " rate " << (8 << k) << " -> " << (16 << k) << ": "
                  << std::fixed << std::setprecision (2) << rate << std::scientific
                  << std::setprecision (3) << "\n";
      testing::check (rate >= 1.7, std::string (names[f]) + " converges at order >= 1.7");
    }
  for (const Profile *p :
       std::vector<const Profile *>{&reference, &coarse[0], &coarse[1], &coarse[2]})
  {
    testing::check (
        p->cross_speed_max <= 1e-4 * wall_speed,
        "steady: |u_s,x| <= 1e-4 V (a discretisation residue, falling with h)");
    testing::check (p->y_difference_max <= 1e-8, "1D: the profiles do not depend on y");
    testing::check (p->gas_error_max <= 1e-4 * wall_speed &&
                        p->gas_cross_speed_max <= 1e-5 * wall_speed,
                    "gas: the exact Couette profile of uniform shear stress");
    testing::check (std::abs (p->mass_drift) <= 1e-12, "solids mass conserved");
  }
  testing::check (std::abs (reference.alpha_mean - 0.3) <= 1e-3, "mean alpha_s 0.3");
  const double slip_moving = wall_speed - reference.solids_speed.front ();
  testing::check (slip_moving > 0 && slip_moving < wall_speed &&
                      reference.solids_speed.back () > 0 &&
                      reference.solids_speed.back () < reference.solids_speed.front (),
                  "Johnson-Jackson slip at both walls, u_s,y decreasing across the gap");
  return root ? testing::finish ("couette_cell") : (testing::failure_count () ? 1 : 0);
}
