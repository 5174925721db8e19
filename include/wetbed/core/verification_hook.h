#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace wetbed
{
/**
 * What a verification run changes in the solver, asked by the solver at the few places
 * it matters: sources added to the equations, exact values imposed on the boundary and
 * initially, fields held at exact values instead of solved for, and the exact fields the
 * errors are measured against. The tests register one (the manufactured solutions of
 * tests/manufactured_hook.h, doc/verification.md); the solver always holds one, and this
 * base class is a production run's: it imposes, holds and adds nothing.
 *
 * Time: the solver sets the time the step solves for (t^{n+1}) before it builds the
 * step's constraints and sources, and 0 for the initial state; the errors after a run
 * are those at the end time.
 */
template <int dim>
class VerificationHook
{
public:
  virtual ~VerificationHook () = default;

  /** The time the exact fields and sources are taken at. */
  virtual void set_time (double /*t*/) {}

  /** The exact (u_g, u_s, p') on the flow system's 2 dim + 1 components: the initial
   * state, the velocities imposed on the inlet and, unless walls_keep_conditions(), the
   * walls; the reference of the errors. Null: none (the .prm's conditions). */
  virtual const dealii::Function<dim> *exact_flow () const { return nullptr; }
  /** true: the walls keep the .prm's conditions (the exact fields satisfy them, with
   * wall_traction_source() added); false: exact velocities on the walls. */
  virtual bool walls_keep_conditions () const { return true; }
  /** alpha_s imposed initially and held there at every step (its transport and the
   * granular temperature without an exact one are not solved). Null: solved. */
  virtual const dealii::Function<dim> *held_solids_fraction () const { return nullptr; }
  /** The exact Theta: imposed initially, solved for with the sources below, the
   * reference of the errors. Null: none. */
  virtual const dealii::Function<dim> *exact_granular_temperature () const
  {
    return nullptr;
  }
  /** true: every step runs all `time stepping/outer iterations` (no outer tolerance),
   * so that the errors measure the discretisation alone. */
  virtual bool runs_all_outer_iterations () const { return false; }

  /** true: the momentum and volume sources and the boundary tractions below join the
   * flow terms (an `imposed sources` term). */
  virtual bool has_flow_sources () const { return false; }
  /** Right-hand side of the momentum equation of phase k (0 gas, 1 solids). */
  virtual dealii::Tensor<1, dim> momentum_source (const dealii::Point<dim> & /*x*/,
                                                  unsigned int /*phase*/) const
  {
    return {};
  }
  /** div(alpha_g u_g + alpha_s u_s) of the exact fields. */
  virtual double mixture_volume_source (const dealii::Point<dim> & /*x*/) const
  {
    return 0;
  }
  /** Traction sigma_k n of phase k on the outlet. */
  virtual dealii::Tensor<1, dim> outlet_traction (const dealii::Point<dim> & /*x*/,
                                                  const dealii::Tensor<1, dim> & /*n*/,
                                                  unsigned int /*phase*/) const
  {
    return {};
  }
  /** With walls_keep_conditions(): the tangential traction of phase k on a wall that
   * the wall condition does not account for; added to the momentum rhs on the walls. */
  virtual dealii::Tensor<1, dim>
  wall_traction_source (const dealii::Point<dim> & /*x*/,
                        const dealii::Tensor<1, dim> & /*n*/,
                        unsigned int /*phase*/) const
  {
    return {};
  }

  /** With an exact Theta: the right-hand side of the granular-energy equation, and
   * kappa dTheta/dn on the boundary less the Johnson-Jackson wall flux where that
   * condition applies (the solver imposes it). */
  virtual double granular_energy_source (const dealii::Point<dim> & /*x*/) const
  {
    return 0;
  }
  virtual double granular_energy_boundary_source (const dealii::Point<dim> & /*x*/,
                                                  const dealii::Tensor<1, dim> & /*n*/,
                                                  bool /*johnson_jackson_wall*/) const
  {
    return 0;
  }
};
} // namespace wetbed
