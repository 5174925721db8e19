#pragma once

// The manufactured solutions of the MMS tests and the verification hook that imposes
// them on the solver (doc/verification.md).
#include <wetbed/core/verification_hook.h>

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>

namespace wetbed
{
/** Gradient of an analytic field by central differences (step 1e-6: error ~1e-10, far
 * below the discretisation errors the manufactured solutions measure). */
template <int dim, typename Field>
dealii::Tensor<1, dim> central_difference_gradient (const Field              &f,
                                                    const dealii::Point<dim> &x)
{
  const double           h = 1e-6;
  dealii::Tensor<1, dim> g;
  for (unsigned int d = 0; d < dim; ++d)
  {
    dealii::Point<dim> plus = x, minus = x;
    plus[d] += h;
    minus[d] -= h;
    g[d] = (f (plus) - f (minus)) / (2 * h);
  }
  return g;
}

/**
 * Source terms a verification run adds to the equations, and the exact fields it
 * imposes on the boundary and compares against; ManufacturedHook hands them to the
 * solver.
 *
 * A time-dependent solution reads time(): the solver sets it to the time the step
 * solves for (t^{n+1}) before it builds the step's constraints and sources, to 0 for
 * the initial state; the errors after run() are those at the end time.
 */
template <int dim>
class ManufacturedSolution
{
public:
  virtual ~ManufacturedSolution () = default;
  void   set_time (const double t) { current_time = t; }
  double time () const { return current_time; }
  /** true: the walls keep the .prm's slip conditions (the exact fields satisfy u.n = 0
   * and a zero tangential traction there); false: exact velocities on the walls. */
  virtual bool slip_walls () const { return false; }

  virtual double                 solids_fraction (const dealii::Point<dim> &x) const = 0;
  virtual dealii::Tensor<1, dim> gas_velocity (const dealii::Point<dim> &x) const    = 0;
  virtual dealii::Tensor<1, dim> solids_velocity (const dealii::Point<dim> &x) const = 0;
  virtual double                 pressure (const dealii::Point<dim> &x) const        = 0;

  /** Right-hand sides of the gas and solids momentum equations. */
  virtual dealii::Tensor<1, dim>
  gas_momentum_source (const dealii::Point<dim> &x) const = 0;
  virtual dealii::Tensor<1, dim>
  solids_momentum_source (const dealii::Point<dim> &x) const = 0;
  /** div(alpha_g u_g + alpha_s u_s) of the exact fields. */
  virtual double mixture_volume_source (const dealii::Point<dim> &x) const = 0;
  /** Traction sigma_k n of phase k on the outlet (sigma_k = tau_k - alpha_k p' I - P_s
   * I). */
  virtual dealii::Tensor<1, dim> gas_traction (const dealii::Point<dim>     &x,
                                               const dealii::Tensor<1, dim> &n) const = 0;
  virtual dealii::Tensor<1, dim>
  solids_traction (const dealii::Point<dim>     &x,
                   const dealii::Tensor<1, dim> &n) const = 0;

  /** Only with slip_walls(): the tangential traction of phase k (0 gas, 1 solids) on a
   * wall that the wall condition does not account for, (sigma_k n)_t plus C_JJ u_s,t on
   * a Johnson-Jackson wall; added to the momentum right-hand side on the walls. */
  virtual dealii::Tensor<1, dim>
  wall_traction_source (const dealii::Point<dim> & /*x*/,
                        const dealii::Tensor<1, dim> & /*n*/,
                        const unsigned int /*phase*/) const
  {
    return {};
  }

  /** true: the granular temperature is manufactured too (the kinetic theory with the
   * PDE), imposed initially, solved for with the sources below and compared. */
  virtual bool   has_granular_temperature () const { return false; }
  virtual double granular_temperature (const dealii::Point<dim> & /*x*/) const
  {
    return 0;
  }
  /** Right-hand side of the granular-energy equation. */
  virtual double granular_energy_source (const dealii::Point<dim> & /*x*/) const
  {
    return 0;
  }
  /** kappa dTheta/dn of the exact fields on the boundary, less the Johnson-Jackson
   * wall flux G_w - D_w where that condition applies (the solver imposes it). */
  virtual double
  granular_energy_boundary_source (const dealii::Point<dim> & /*x*/,
                                   const dealii::Tensor<1, dim> & /*n*/,
                                   const bool /*johnson_jackson_wall*/) const
  {
    return 0;
  }

private:
  double current_time = 0;
};

/** The manufactured Theta as a deal.II Function (error norms, interpolation). */
template <int dim>
class ManufacturedTemperatureFunction : public dealii::Function<dim>
{
public:
  explicit ManufacturedTemperatureFunction (const ManufacturedSolution<dim> &m) : m (m) {}
  double value (const dealii::Point<dim> &x, const unsigned int = 0) const override
  {
    return m.granular_temperature (x);
  }
  dealii::Tensor<1, dim> gradient (const dealii::Point<dim> &x,
                                   const unsigned int = 0) const override
  {
    return central_difference_gradient<dim> (
        [this] (const dealii::Point<dim> &y) { return value (y); }, x);
  }

private:
  const ManufacturedSolution<dim> &m;
};

/**
 * The manufactured (u_g, u_s, p') as a deal.II Function on the flow system's 2 dim + 1
 * components, for boundary values, interpolation and error norms. The gradient is a
 * central difference of the analytic field (error ~1e-10, far below the discretisation
 * errors measured with it).
 */
template <int dim>
class ManufacturedFlowFunction : public dealii::Function<dim>
{
public:
  explicit ManufacturedFlowFunction (const ManufacturedSolution<dim> &m)
      : dealii::Function<dim> (2 * dim + 1), m (m)
  {
  }

  double value (const dealii::Point<dim> &x, const unsigned int c) const override
  {
    if (c < dim)
      return m.gas_velocity (x)[c];
    if (c < 2 * dim)
      return m.solids_velocity (x)[c - dim];
    return m.pressure (x);
  }

  dealii::Tensor<1, dim> gradient (const dealii::Point<dim> &x,
                                   const unsigned int        c) const override
  {
    return central_difference_gradient<dim> (
        [this, c] (const dealii::Point<dim> &y) { return value (y, c); }, x);
  }

private:
  const ManufacturedSolution<dim> &m;
};
/** The manufactured alpha_s as a deal.II Function (imposed and held). */
template <int dim>
class ManufacturedFractionFunction : public dealii::Function<dim>
{
public:
  explicit ManufacturedFractionFunction (const ManufacturedSolution<dim> &m) : m (m) {}
  double value (const dealii::Point<dim> &x, const unsigned int = 0) const override
  {
    return m.solids_fraction (x);
  }

private:
  const ManufacturedSolution<dim> &m;
};

/**
 * A manufactured solution as the solver's verification hook: its fields imposed
 * initially and on the boundary, alpha_s held, Theta solved where it is manufactured,
 * its sources added, every outer iteration run.
 */
template <int dim>
class ManufacturedHook : public VerificationHook<dim>
{
public:
  explicit ManufacturedHook (std::shared_ptr<ManufacturedSolution<dim>> solution)
      : solution (std::move (solution)), flow (*this->solution),
        fraction (*this->solution), theta (*this->solution)
  {
  }
  void set_time (const double t) override { solution->set_time (t); }
  const dealii::Function<dim> *exact_flow () const override { return &flow; }
  bool walls_keep_conditions () const override { return solution->slip_walls (); }
  const dealii::Function<dim> *held_solids_fraction () const override
  {
    return &fraction;
  }
  const dealii::Function<dim> *exact_granular_temperature () const override
  {
    return solution->has_granular_temperature () ? &theta : nullptr;
  }
  bool                   runs_all_outer_iterations () const override { return true; }
  bool                   has_flow_sources () const override { return true; }
  dealii::Tensor<1, dim> momentum_source (const dealii::Point<dim> &x,
                                          const unsigned int        phase) const override
  {
    return phase == 0 ? solution->gas_momentum_source (x)
                      : solution->solids_momentum_source (x);
  }
  double mixture_volume_source (const dealii::Point<dim> &x) const override
  {
    return solution->mixture_volume_source (x);
  }
  dealii::Tensor<1, dim> outlet_traction (const dealii::Point<dim>     &x,
                                          const dealii::Tensor<1, dim> &n,
                                          const unsigned int phase) const override
  {
    return phase == 0 ? solution->gas_traction (x, n) : solution->solids_traction (x, n);
  }
  dealii::Tensor<1, dim> wall_traction_source (const dealii::Point<dim>     &x,
                                               const dealii::Tensor<1, dim> &n,
                                               const unsigned int phase) const override
  {
    return solution->wall_traction_source (x, n, phase);
  }
  double granular_energy_source (const dealii::Point<dim> &x) const override
  {
    return solution->granular_energy_source (x);
  }
  double granular_energy_boundary_source (const dealii::Point<dim>     &x,
                                          const dealii::Tensor<1, dim> &n,
                                          const bool jj_wall) const override
  {
    return solution->granular_energy_boundary_source (x, n, jj_wall);
  }

private:
  std::shared_ptr<ManufacturedSolution<dim>> solution;
  ManufacturedFlowFunction<dim>              flow;
  ManufacturedFractionFunction<dim>          fraction;
  ManufacturedTemperatureFunction<dim>       theta;
};
} // namespace wetbed
