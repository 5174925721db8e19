#pragma once

#include <wetbed/solvers/solver_state.h>

#include <deal.II/base/mpi_remote_point_evaluation.h>

#include <vector>

namespace wetbed
{
/**
 * Horizontal cross-sections of the domain sampled on a grid of points: at each height
 * (along -g from the coordinate origin) `resolution` x `resolution` points (3D;
 * `resolution` in 2D) at the centres of the pixels of the domain's horizontal bounding
 * box. The points are located once per mesh with deal.II's RemotePointEvaluation (each
 * rank evaluates the points in its cells, whoever asked for them), again after every
 * mesh change; a point outside the domain reads NaN. Evaluations are collective
 * (source/postprocess/cross_section_sampler.cc).
 */
template <int dim>
class CrossSectionSampler
{
public:
  CrossSectionSampler (const std::vector<double> &heights, unsigned int resolution);

  /** Points per height: resolution^(dim - 1). */
  unsigned int points_per_height () const { return per_height; }

  /** alpha_s at the points, height after height, each row-major (first horizontal
   * axis fastest). */
  std::vector<double> alpha_s (const SolverState<dim> &state);

  /** p' at the points, in the same order. */
  std::vector<double> pressure (const SolverState<dim> &state);

  /** The mean of the values that are not NaN (NaN if all are). */
  static double mean (const std::vector<double> &values);

private:
  void locate (const SolverState<dim> &state);

  std::vector<double>                                heights;
  unsigned int                                       resolution, per_height;
  dealii::Utilities::MPI::RemotePointEvaluation<dim> points;
  std::vector<bool>                                  found;
};
} // namespace wetbed
