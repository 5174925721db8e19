#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/solver_state.h>

#include <deque>
#include <string>

namespace wetbed
{
/**
 * The checks an accepted step's state must pass besides a converged solve (`subsection
 * divergence checks`, doc/user_guide.md "Failures and exit codes"): phase speeds below
 * a multiple of the case's reference speed, |FI| below its limit, and no growth of
 * the kinetic energy by orders of magnitude within a few steps. It keeps the kinetic
 * energies of the last accepted steps (not checkpointed: a resumed run measures the
 * growth from its first step on).
 */
template <int dim>
class DivergenceChecks
{
public:
  struct Result
  {
    bool        passed = true;
    std::string reason; // one line: the check, the value, the limit and its parameter
    std::string where;  // the cells where it failed, worst first (report lines)
    double      kinetic_energy = 0; // of both phases, J (J per metre depth in 2D)
  };

  explicit DivergenceChecks (const Parameters &parameters);

  /** The reference speed of the case (m/s): `divergence checks/reference speed`, or
   * where that is 0 the largest of U(t)/(1 - maximum packing),
   * the single-particle terminal velocity, sqrt(2 g H) over the domain height H and
   * the moving wall's speed; collective. */
  double reference_speed (const SolverState<dim> &state) const;

  /** Checks the state (a step's result before it is accepted); collective. */
  Result check (const SolverState<dim> &state) const;

  /** An accepted step's kinetic energy joins the growth window. */
  void accept (double kinetic_energy);

private:
  Result check_speeds (const SolverState<dim> &state, double limit) const;

  const Parameters  &parameters;
  std::deque<double> energies; // of the last accepted steps
};
} // namespace wetbed
