#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace wetbed
{
/**
 * Source terms a verification run adds to the equations, and the exact fields it
 * imposes on the boundary and compares against. The solver calls these only when a
 * manufactured solution is attached (tests/), never in a production run.
 */
template <int dim>
class ManufacturedSolution
{
public:
  virtual ~ManufacturedSolution () = default;

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
};
} // namespace wetbed
