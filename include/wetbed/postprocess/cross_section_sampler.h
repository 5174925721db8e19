#pragma once

#include <wetbed/postprocess/field_sampler.h>

#include <vector>

namespace wetbed
{
/** The pixel centres of the horizontal bounding box of `frame` at each height, height
 * after height, each row-major (first horizontal axis fastest): resolution^(dim - 1)
 * points per height. */
template <int dim>
std::vector<dealii::Point<dim>> cross_section_points (const HorizontalFrame<dim> &frame,
                                                      const std::vector<double>  &heights,
                                                      unsigned int resolution);

/**
 * Horizontal cross-sections of the domain sampled on a grid of points: at each height
 * (along -g from the coordinate origin) `resolution` x `resolution` points (3D;
 * `resolution` in 2D) at the centres of the pixels of the domain's horizontal bounding
 * box, evaluated by a FieldSampler (a point outside the domain reads NaN); collective
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
  std::vector<double> heights;
  unsigned int        resolution, per_height;
  FieldSampler<dim>   sampler;
};
} // namespace wetbed
