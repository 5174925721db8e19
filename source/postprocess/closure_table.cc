#include <wetbed/closures/closure_evaluator.h>
#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/kinetic_theory/kinetic_theory.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/parameters.h>
#include <wetbed/postprocess/closure_table.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace wetbed
{
namespace
{
std::vector<double> parse_list (const std::string &text, const std::string &option)
{
  std::vector<double> values;
  std::stringstream   stream (text);
  std::string         item;
  while (std::getline (stream, item, ','))
  {
    std::size_t used = 0;
    double      value;
    try
    {
      value = std::stod (item, &used);
    }
    catch (const std::exception &)
    {
      used = 0;
    }
    require (used == item.size () && used > 0 && std::isfinite (value),
             option,
             "'" + item + "' is not a number");
    values.push_back (value);
  }
  require (!values.empty (), option, "needs a comma-separated list of numbers");
  return values;
}

void check_point (const ClosurePoint &p,
                  const Parameters   &parameters,
                  const std::string  &where)
{
  require (p.alpha_s > 0 && p.alpha_s < parameters.physical.maximum_packing,
           where,
           "alpha_s must lie in (0, maximum packing)");
  require (p.theta > 0, where, "Theta must be > 0");
  require (p.shear_rate >= 0, where, "the shear rate must be >= 0");
}
} // namespace

std::vector<ClosurePoint> closure_points (const std::vector<std::string> &options,
                                          const Parameters               &parameters)
{
  std::vector<double> alphas, thetas = {1e-3}, shear_rates = {1.0};
  for (double a = 0.01; a < parameters.physical.maximum_packing - 1e-9; a += 0.01)
    alphas.push_back (a);
  std::vector<ClosurePoint> points;
  std::string               points_file;
  for (std::size_t i = 0; i < options.size (); i += 2)
  {
    const std::string &option = options[i];
    require (i + 1 < options.size (), option, "needs a value");
    const std::string &value = options[i + 1];
    if (option == "--alpha-s")
      alphas = parse_list (value, option);
    else if (option == "--theta")
      thetas = parse_list (value, option);
    else if (option == "--shear-rate")
      shear_rates = parse_list (value, option);
    else if (option == "--points")
      points_file = value;
    else
      throw InputError (
          option, "unknown option (known: --alpha-s, --theta, --shear-rate, --points)");
  }
  if (!points_file.empty ())
  {
    std::ifstream in (points_file);
    require (bool (in), points_file, "cannot be read");
    std::string  line;
    unsigned int number = 0;
    while (std::getline (in, line))
    {
      ++number;
      if (line.find_first_not_of (" \t\r") == std::string::npos || line[0] == '#')
        continue;
      std::istringstream row (line);
      ClosurePoint       p;
      require (bool (row >> p.alpha_s >> p.theta >> p.shear_rate),
               points_file + ":" + std::to_string (number),
               "expected three numbers: alpha_s theta shear_rate");
      check_point (p, parameters, points_file + ":" + std::to_string (number));
      points.push_back (p);
    }
    return points;
  }
  for (const double a : alphas)
    for (const double t : thetas)
      for (const double g : shear_rates)
      {
        points.push_back ({a, t, g});
        check_point (points.back (), parameters, "--alpha-s/--theta/--shear-rate");
      }
  return points;
}

void write_closure_table (const Parameters                &parameters,
                          const std::vector<ClosurePoint> &points,
                          std::ostream                    &out)
{
  const auto stress = closures::create_solids_stress_model (parameters.solids_stress,
                                                            parameters.physical,
                                                            parameters.kinetic_theory,
                                                            parameters.wet);
  const auto drag   = closures::create_drag_model (parameters.drag_model);
  // the closures with the solver's input convention (doc/theory.md, "Closure inputs")
  const closures::ClosureEvaluator evaluator (
      *drag,
      *stress,
      {parameters.physical.gas_density,
       parameters.physical.gas_viscosity,
       parameters.physical.particle_diameter},
      parameters.physical.residual_solids_fraction);
  const closures::KineticTheory *theory = evaluator.kinetic_theory ();
  require (theory != nullptr,
           "solids stress/model",
           "wetbed closures reports the kinetic theory: set model = kinetic theory");
  const closures::WetParticles *wet = theory->wet ();
  out << "alpha_s,theta,shear_rate,g0,kinetic_pressure,frictional_pressure,"
         "kinetic_collisional_viscosity,collisional_viscosity,frictional_viscosity,shear_"
         "viscosity,"
         "bulk_viscosity,conductivity,dissipation,restitution";
  if (wet)
    out << ",gap,rupture_distance,regime,approach_velocity,wet_pressure,wet_viscosity,"
           "stokes,critical_stokes,wet_restitution";
  out << "\n" << std::setprecision (10);
  for (const auto &p : points)
  {
    const auto c = theory->evaluate (p.alpha_s, p.theta);
    const auto s = evaluator.stress (p.alpha_s, p.theta, p.shear_rate);
    out << p.alpha_s << ',' << p.theta << ',' << p.shear_rate << ',' << c.g0 << ','
        << s.kinetic_pressure << ',' << s.pressure << ',' << c.shear_viscosity << ','
        << c.collisional_viscosity << ',' << s.frictional_viscosity << ','
        << s.shear_viscosity << ',' << s.bulk_viscosity << ',' << c.conductivity << ','
        << c.dissipation_factor * std::pow (p.theta, 1.5) << ',' << c.restitution;
    if (wet)
    {
      // at div u_s = 0: the lubrication stress acts in full in either reading
      const auto w =
          wet->evaluate (p.alpha_s, p.theta, 0.25 * p.shear_rate * p.shear_rate, 0.0);
      out << ',' << w.gap << ',' << w.rupture_distance << ','
          << w.regime (wet->liquid ().asperity) << ',' << w.approach_velocity << ','
          << w.pressure << ',' << w.viscosity << ',' << w.stokes << ','
          << w.critical_stokes << ',' << w.restitution;
    }
    out << "\n";
  }
}
} // namespace wetbed
