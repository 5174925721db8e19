#pragma once

#include <wetbed/solvers/solver_state.h>

#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <vector>

namespace wetbed
{
/** The vertical axis of the domain (the coordinate axis gravity points along), the
 * horizontal axes and the domain's bounding box over all ranks. */
template <int dim>
struct HorizontalFrame
{
  unsigned int              vertical;
  std::vector<unsigned int> across; // the horizontal axes, in ascending order
  dealii::Point<dim>        lower, upper;
  double                    up; // +1 or -1: the sign of the upward axis direction

  /** The point at `height` along -g from the coordinate origin with the horizontal
   * coordinates `horizontal` (dim - 1 of them). */
  dealii::Point<dim> at (double height, const std::vector<double> &horizontal) const;
};

/** Collective. */
template <int dim>
HorizontalFrame<dim> horizontal_frame (const SolverState<dim> &state);

/**
 * Fields evaluated at a set of points, distributed: the points come from `where` (which
 * may read the mesh), are located once per mesh with deal.II's RemotePointEvaluation
 * (each rank evaluates the points in its cells, whoever asked for them) and again after
 * every mesh change. A point outside the domain reads NaN. Refinement does not move the
 * domain, so after a mesh change only the points found at the first location are
 * looked for again: deal.II's search for a point outside every cell falls back to a
 * scan of all vertices, with an exception per cell tried (for the 8,192 points of an
 * ECT slab in a cylinder, whose corners lie outside, ~10 s on 2 ranks). Evaluations are
 * collective (source/postprocess/field_sampler.cc).
 */
template <int dim>
class FieldSampler
{
public:
  using Locator =
      std::function<std::vector<dealii::Point<dim>> (const SolverState<dim> &)>;
  using AlphaVector = typename SolverState<dim>::AlphaVector;
  using BlockVector = typename SolverState<dim>::BlockVector;
  using FlowValue   = dealii::Tensor<1, 2 * dim + 1>; // u_g, u_s, p'

  explicit FieldSampler (Locator where);

  /** The points of the current mesh. */
  const std::vector<dealii::Point<dim>> &points (const SolverState<dim> &state);

  /** A field of the alpha_s space (ghosted) at the points. */
  std::vector<double> scalar (const SolverState<dim> &state, const AlphaVector &field);

  /** A field of the flow space (ghosted) at the points. */
  std::vector<FlowValue> flow (const SolverState<dim> &state, const BlockVector &field);

private:
  void locate (const SolverState<dim> &state);

  Locator                                            where;
  std::vector<dealii::Point<dim>>                    located;
  dealii::Utilities::MPI::RemotePointEvaluation<dim> evaluation;
  std::vector<bool>                                  found;
  // the indices of the points `evaluation` holds, and of those found the first time
  std::vector<unsigned int> evaluated, inside;
  bool                      located_before = false;

  /** values of the evaluated points at their places among all, NaN elsewhere */
  template <typename Value>
  std::vector<Value> expand (const std::vector<Value> &values, const Value &nan) const;
};
} // namespace wetbed
