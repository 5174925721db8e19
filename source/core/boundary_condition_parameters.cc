#include <wetbed/core/boundary_condition_parameters.h>
#include <wetbed/core/expression_constants.h>
#include <wetbed/core/input_error.h>

#include <deal.II/base/function_parser.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

namespace
{
/**
 * Keeps std::cerr quiet while muparser parses: deal.II prints a parse error as five
 * lines (message, formula, token, position, code) before throwing, and wetbed reports
 * it as one line naming the parameter.
 */
class QuietStandardError
{
public:
  QuietStandardError () : saved (std::cerr.rdbuf (sink.rdbuf ())) {}
  ~QuietStandardError () { std::cerr.rdbuf (saved); }

private:
  std::ostringstream sink;
  std::streambuf    *saved;
};
} // namespace

void BoundaryConditionParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("boundary conditions");
  prm.declare_entry (
      "inlet superficial velocity",
      "0.8",
      Anything (),
      "Superficial gas velocity U at the inlet (m/s), a function of t; the "
      "gas enters at U/alpha_g with the local gas fraction "
      "(muparser syntax, e.g. 'min(0.8, 0.2*t)'). It applies to every inlet group "
      "without an entry in `inlet velocities` or `inlet mass flow rates`.");
  prm.declare_entry (
      "inlet velocities",
      "",
      Anything (),
      "Inlet groups with their own superficial gas velocity (m/s): ';'-separated "
      "`group: expression` entries, each a function of x, y, z (3D) and t, e.g. "
      "'jet: 30*(t > 0.1); distributor: 0.3'. The gas enters at U/alpha_g with the "
      "local gas fraction, along the group's direction. Empty: none.");
  prm.declare_entry (
      "inlet mass flow rates",
      "",
      Anything (),
      "Inlet groups fed a gas mass flow rate (kg/s; kg/s per metre depth in 2D): "
      "';'-separated `group: expression` entries, each a function of t. The "
      "superficial velocity is the rate over the gas density and the group's area "
      "projected on its direction. A group is in `inlet velocities` or here, not "
      "both. Empty: none.");
  prm.declare_entry ("inlet directions",
                     "",
                     Anything (),
                     "The direction in which the gas enters through an inlet group: "
                     "';'-separated `group: x y [z]` entries (normalised; it must point "
                     "into the domain). A group not named enters against gravity.");
  prm.declare_entry (
      "inlet solids",
      "",
      Anything (),
      "Inlet groups that feed solids: ';'-separated `group: alpha_s speed` entries, "
      "the solids fraction of the feed (0 < alpha_s < maximum packing) and its speed "
      "(m/s, > 0) along the group's direction (`inlet directions`, else against "
      "gravity), e.g. 'feed: 0.3 0.5'. The solids velocity is held at that speed on "
      "the group's faces and alpha_s u_s enters the solids continuity there; the fed "
      "mass is added up (monitors: solids_fed_mass) and taken out of "
      "solids_mass_drift. On the other inlets the solids velocity is zero. Empty: "
      "none.");
  const std::string names = closures::registered_names (wall_condition_registry ());
  const std::string per_group =
      " on the walls: one condition (" + names +
      ") for every wall group, or ';'-separated `group: condition` entries for named "
      "wall groups with at most one bare condition for the others (e.g. 'free-slip; "
      "side: Johnson-Jackson'). A moving wall's conditions apply relative to its "
      "motion.";
  prm.declare_entry (
      "gas wall condition", "no-slip", Anything (), "Gas velocity condition" + per_group);
  prm.declare_entry ("solids wall condition",
                     "free-slip",
                     Anything (),
                     "Solids velocity condition" + per_group +
                         " Johnson-Jackson needs solids stress/model = kinetic theory.");
  prm.declare_entry ("gas wall friction",
                     "0",
                     Double (0),
                     "Robin coefficient C (kg m^-2 s^-1) of the gas's partial-slip "
                     "traction -C u_slip.");
  prm.declare_entry ("solids wall friction",
                     "0",
                     Double (0),
                     "Robin coefficient C (kg m^-2 s^-1) of the solids' partial-slip "
                     "traction -C u_slip.");
  prm.declare_entry ("no-penetration",
                     "strong",
                     Selection ("Nitsche|strong"),
                     "How u.n = 0 is imposed on slip walls (free-slip, partial-slip, "
                     "Johnson-Jackson): symmetric Nitsche (weak, with the mapped "
                     "normal at the quadrature points) or strong no-normal-flux "
                     "constraints at the nodes. On curved 3D walls with the velocity "
                     "AMG (`linear solver/operator = assembled`) Nitsche needs "
                     "`linear solver/velocity smoother = block Gauss-Seidel`; its "
                     "velocity gradient converges more slowly there than with "
                     "`strong` (doc/theory.md, \"Solving Nitsche on a curved wall\").");
  prm.declare_entry ("Nitsche penalty",
                     "10",
                     Double (),
                     "gamma_0 of the Nitsche penalty gamma_0 (degree + 1)^2 mu*/h.");
  prm.declare_entry ("hold solids",
                     "false",
                     Bool (),
                     "Hold the solids velocity at 'held solids velocity' everywhere (a "
                     "fixed bed, e.g. the Ergun test, or a frozen shear); alpha_s is "
                     "then not transported, Theta still evolves.");
  prm.declare_entry ("held solids velocity",
                     "0; 0; 0",
                     Anything (),
                     "u_s (m/s) where solids are held: three ';'-separated expressions "
                     "in x, y, z, t (muparser); in 2D the third is ignored.");
  prm.declare_entry ("moving wall",
                     "",
                     Anything (),
                     "Physical group name of a wall that slides tangentially with "
                     "'moving wall velocity' (a shear cell, a Couette cell): the wall "
                     "conditions above apply to it relative to its motion. Empty: none.");
  prm.declare_entry ("moving wall velocity",
                     "0, 0, 0",
                     Anything (),
                     "Velocity of the moving wall (m/s), three comma-separated "
                     "components (the third ignored in 2D); it must be tangential to "
                     "the wall.");
  prm.leave_subsection ();
}

void BoundaryConditionParameters::parse_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("boundary conditions");
  inlet_superficial_velocity = prm.get ("inlet superficial velocity");
  gas_wall                   = WallConditionChoice::parse (prm.get ("gas wall condition"),
                                         "boundary conditions/gas wall condition");
  solids_wall          = WallConditionChoice::parse (prm.get ("solids wall condition"),
                                            "boundary conditions/solids wall condition");
  gas_wall_friction    = prm.get_double ("gas wall friction");
  solids_wall_friction = prm.get_double ("solids wall friction");
  hold_solids          = prm.get_bool ("hold solids");
  nitsche              = prm.get ("no-penetration") == "Nitsche";
  nitsche_penalty      = prm.get_double ("Nitsche penalty");
  held_solids_velocity = prm.get ("held solids velocity");
  moving_wall_name     = prm.get ("moving wall");
  moving_wall_velocity = parse_vector (prm.get ("moving wall velocity"),
                                       "boundary conditions/moving wall velocity");
  inlet_groups.clear ();
  const auto group = [&] (const std::string &name) -> InletGroup &
  {
    for (InletGroup &g : inlet_groups)
      if (g.name == name)
        return g;
    inlet_groups.push_back ({name, "", "", {}, 0, 0});
    return inlet_groups.back ();
  };
  for (const char *list :
       {"inlet velocities", "inlet mass flow rates", "inlet directions", "inlet solids"})
  {
    const std::string        where = std::string ("boundary conditions/") + list;
    std::vector<std::string> named;
    for (const auto &item : dealii::Utilities::split_string_list (prm.get (list), ';'))
    {
      const auto colon = item.find (':');
      require (colon != std::string::npos && colon > 0,
               where,
               "'" + item + "' is not `group: value`");
      const std::string name  = dealii::Utilities::trim (item.substr (0, colon));
      const std::string value = dealii::Utilities::trim (item.substr (colon + 1));
      require (std::find (named.begin (), named.end (), name) == named.end (),
               where,
               "the group '" + name + "' is named twice");
      named.push_back (name);
      require (!value.empty (), where, "the group '" + name + "' has no value");
      InletGroup &g = group (name);
      if (std::string (list) == "inlet velocities")
        g.velocity = value;
      else if (std::string (list) == "inlet mass flow rates")
        g.mass_flow = value;
      else if (std::string (list) == "inlet solids")
      {
        std::istringstream  words (value);
        std::vector<double> numbers;
        for (std::string w; words >> w;)
          numbers.push_back (parse_number (w, where));
        require (numbers.size () == 2,
                 where,
                 "the group '" + name + "' needs `alpha_s speed`, two numbers");
        g.solids_fraction = numbers[0];
        g.solids_speed    = numbers[1];
        require (g.solids_fraction > 0,
                 where,
                 "the solids fraction of '" + name + "' must be > 0");
      }
      else
      {
        std::istringstream components (value);
        for (std::string c; components >> c;)
          g.direction.push_back (parse_number (c, where));
      }
    }
  }
  prm.leave_subsection ();
  QuietStandardError quiet;
  try
  {
    dealii::FunctionParser<3> f (3);
    f.initialize ("x,y,z,t", held_solids_velocity, expression_constants (), true);
    (void)f.value (dealii::Point<3> (), 0);
  }
  catch (...)
  {
    throw InputError ("boundary conditions/held solids velocity",
                      "'" + held_solids_velocity +
                          "' is not three ';'-separated expressions in x, y, z, t");
  }
  try
  {
    dealii::FunctionParser<1> f (1);
    f.initialize ("t", inlet_superficial_velocity, expression_constants ());
    (void)f.value (dealii::Point<1> (0.0));
  }
  catch (...)
  {
    throw InputError ("boundary conditions/inlet superficial velocity",
                      "'" + inlet_superficial_velocity +
                          "' is not a valid expression in t");
  }
  require (std::isfinite (nitsche_penalty) && nitsche_penalty >= 1.0,
           "boundary conditions/Nitsche penalty",
           "must be >= 1 (the symmetric form needs a large enough penalty)");
}

void BoundaryConditionParameters::check_wall_conditions (
    const bool has_kinetic_theory) const
{
  const auto choices  = wall_choices ();
  const auto settings = wall_settings (nullptr, has_kinetic_theory);
  for (unsigned int k = 0; k < 2; ++k)
    for (const std::string &name : choices[k].names ())
      (void)wall_condition_registry ().at (name) (settings[k]);
}

bool BoundaryConditionParameters::feeds_solids () const
{
  return std::any_of (inlet_groups.begin (),
                      inlet_groups.end (),
                      [] (const InletGroup &g) { return g.feeds_solids (); });
}

void BoundaryConditionParameters::check_inlet_groups (
    const std::vector<std::string> &inlet_names,
    const unsigned int              dim,
    const double                    maximum_packing)
{
  QuietStandardError quiet;
  std::string        known;
  for (const auto &name : inlet_names)
    known += (known.empty () ? "" : ", ") + name;
  for (InletGroup &g : inlet_groups)
  {
    const std::string where = "boundary conditions/" +
                              std::string (!g.mass_flow.empty () ? "inlet mass flow rates"
                                           : !g.velocity.empty () ? "inlet velocities"
                                           : g.feeds_solids ()    ? "inlet solids"
                                                                  : "inlet directions");
    require (std::find (inlet_names.begin (), inlet_names.end (), g.name) !=
                 inlet_names.end (),
             where,
             "'" + g.name + "' is not an inlet group (mesh/inlet: " +
                 (known.empty () ? "none" : known) + ")");
    require (g.velocity.empty () || g.mass_flow.empty (),
             "boundary conditions/inlet mass flow rates",
             "the group '" + g.name + "' also has an entry in `inlet velocities`");
    if (g.feeds_solids ())
    {
      require (g.solids_fraction < maximum_packing,
               "boundary conditions/inlet solids",
               "the solids fraction of '" + g.name +
                   "' must be below physical properties/maximum packing");
      require (std::isfinite (g.solids_speed) && g.solids_speed > 0,
               "boundary conditions/inlet solids",
               "the solids speed of '" + g.name + "' must be a positive number");
    }
    const std::string variables = dim == 3 ? "x,y,z,t" : "x,y,t";
    for (const bool mass : {false, true})
    {
      const std::string &expression = mass ? g.mass_flow : g.velocity;
      if (expression.empty ())
        continue;
      try
      {
        if (mass)
        {
          dealii::FunctionParser<1> f (1);
          f.initialize ("t", expression, expression_constants ());
          (void)f.value (dealii::Point<1> (0.0));
        }
        else if (dim == 3)
        {
          dealii::FunctionParser<3> f (1);
          f.initialize (variables, expression, expression_constants (), true);
          (void)f.value (dealii::Point<3> ());
        }
        else
        {
          dealii::FunctionParser<2> f (1);
          f.initialize (variables, expression, expression_constants (), true);
          (void)f.value (dealii::Point<2> ());
        }
      }
      catch (...)
      {
        throw InputError (mass ? "boundary conditions/inlet mass flow rates"
                               : "boundary conditions/inlet velocities",
                          "'" + expression + "' of the group '" + g.name +
                              "' is not a valid expression in " +
                              (mass ? std::string ("t") : variables));
      }
    }
    if (!g.direction.empty ())
    {
      require (g.direction.size () == dim,
               "boundary conditions/inlet directions",
               "the direction of '" + g.name + "' needs " + std::to_string (dim) +
                   " components");
      double norm = 0;
      for (const double c : g.direction)
        norm += c * c;
      require (norm > 0,
               "boundary conditions/inlet directions",
               "the direction of '" + g.name + "' is zero");
      for (double &c : g.direction)
        c /= std::sqrt (norm);
    }
  }
}

void BoundaryConditionParameters::check_time_span (const double end_time) const
{
  QuietStandardError        quiet;
  dealii::FunctionParser<1> f (1);
  f.initialize ("t", inlet_superficial_velocity, expression_constants ());
  const unsigned int samples = 400;
  for (unsigned int i = 0; i <= samples; ++i)
  {
    const double t     = end_time * i / samples;
    const double value = f.value (dealii::Point<1> (t));
    if (!std::isfinite (value))
    {
      std::ostringstream where;
      where << "'" << inlet_superficial_velocity << "' is " << value << " at t = " << t
            << " s (it must be finite over [0, time stepping/end time])";
      throw InputError ("boundary conditions/inlet superficial velocity", where.str ());
    }
  }
}
} // namespace wetbed
