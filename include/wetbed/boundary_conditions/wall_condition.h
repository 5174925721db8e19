#pragma once

#include <memory>
#include <string>

namespace wetbed
{
namespace closures
{
class KineticTheory;
}

/** The two phases, in the order of the flow system's velocity blocks. */
enum class Phase
{
  gas    = 0,
  solids = 1
};

/** "gas" or "solids", as the parameter names say it. */
inline std::string to_string (const Phase phase)
{
  return phase == Phase::gas ? "gas" : "solids";
}

/** The state at a wall point that a wall condition's traction depends on. */
struct WallPoint
{
  double alpha_s; // solids fraction (>= 0)
  double theta;   // granular temperature (>= 0; zero without kinetic theory)
};

/** What a wall condition is built from (`boundary conditions`). */
struct WallConditionSettings
{
  Phase                          phase;
  double                         friction;           // `<phase> wall friction`
  const closures::KineticTheory *kinetic_theory;     // null without kinetic theory
  bool                           has_kinetic_theory; // solids stress/model
};

/**
 * How one phase meets a group of walls (doc/theory.md, "Wall conditions"). Either the
 * phase takes the wall's velocity (no slip, imposed as constraints), or it does not
 * penetrate the wall (strongly at the nodes or by Nitsche, `boundary conditions/
 * no-penetration`) and feels the tangential traction -C P_t (u - u_w) with a friction
 * coefficient C >= 0 (free slip: none). The flow's face term (WallFrictionTerm), the
 * granular-energy wall flux and the wall forces of monitors.csv all ask the condition;
 * none knows the conditions by name.
 *
 * A new condition: a class deriving from this one with a `model_name` and
 * `static std::unique_ptr<WallCondition> create (const WallConditionSettings &)`, and
 * its name in the list of wall_conditions.h.
 */
class WallCondition
{
public:
  virtual ~WallCondition () = default;

  /** The name as the parameter file says it. */
  virtual std::string name () const = 0;
  /** The phase takes the wall's velocity (Dirichlet constraints). */
  virtual bool prescribes_velocity () const { return false; }
  /** A tangential friction traction acts (friction() may be nonzero). */
  virtual bool has_friction () const { return false; }
  /** The friction coefficient C (kg m^-2 s^-1) at a wall point. */
  virtual double friction (const WallPoint &) const { return 0; }
  /** The wall exchanges granular energy (production by slip, dissipation by
   * inelastic collisions with the wall): the Theta equation's wall flux. */
  virtual bool has_granular_energy_flux () const { return false; }
};
} // namespace wetbed
