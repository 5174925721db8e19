#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

namespace wetbed
{
/** `subsection physical properties`: both phases, gravity, packing limit. */
struct PhysicalProperties
{
  double               gas_density, gas_viscosity;
  double               particle_density, particle_diameter;
  double               maximum_packing;
  double               residual_solids_fraction; // floor of alpha_s in inertia and drag
  dealii::Tensor<1, 3> gravity;

  static void declare_parameters (dealii::ParameterHandler &prm);
  void        parse_parameters (dealii::ParameterHandler &prm);
};

/**
 * The unit vector against gravity in the space of the mesh (the in-plane part in 2D);
 * where gravity has no component there (a 2D mesh lying flat, gravity along z) the
 * last axis.
 */
template <int dim>
dealii::Tensor<1, dim> upward_direction (const dealii::Tensor<1, 3> &gravity)
{
  dealii::Tensor<1, dim> up;
  for (unsigned int d = 0; d < dim; ++d)
    up[d] = -gravity[d];
  if (up.norm () <= 1e-12 * gravity.norm ())
  {
    up          = dealii::Tensor<1, dim> ();
    up[dim - 1] = 1.0;
    return up;
  }
  return up / up.norm ();
}
} // namespace wetbed
