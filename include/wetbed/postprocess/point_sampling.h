#pragma once

#include <wetbed/solvers/solver_state.h>

#include <deal.II/base/point.h>

#include <vector>

namespace wetbed
{
/** The fields of `state` at the points, each u_g (dim), u_s (dim), p', alpha_s, Theta;
 * NaN outside the mesh (source/postprocess/point_sampling.cc); collective. */
template <int dim>
std::vector<std::vector<double>>
sample_fields (const SolverState<dim>                &state,
               const std::vector<dealii::Point<dim>> &points);
} // namespace wetbed
