#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/numerics/data_out.h>

#include <vector>

namespace wetbed
{
/**
 * Time averages of the fields (`subsection statistics`): from `start time` on, after
 * every accepted step, the means of u_g, u_s, p' (one vector on the flow space), of
 * alpha_s and of Theta, and the sums of squared deviations M2 of the flow components
 * and of alpha_s, by Welford's update weighted with the step length (West 1979): with
 * W the time averaged over so far and w the part of the step after the start,
 * d = x - mean, mean += (w / (W + w)) d, M2 += w d (x - mean); the variance is M2 / W.
 * W = t - start needs no storage. The accumulators are fields of the solver's spaces
 * and layouts (ghosted), so the mesh adaptation and the checkpoints move them like the
 * solution (source/postprocess/time_averages.cc).
 */
template <int dim>
class TimeAverages
{
public:
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  explicit TimeAverages (double start_time);

  /** Zero accumulators laid out like the fields (a new run's mesh). */
  void reinit (const BlockVector &flow_like, const AlphaVector &alpha_like);

  /** After the step that ended at `time` with length `dt`. `owned` is an unghosted
   * vector of the flow layout (work space). */
  void add (double             time,
            double             dt,
            const BlockVector &flow,
            const AlphaVector &alpha,
            const AlphaVector &theta,
            BlockVector       &owned);

  /** The time averaged over by `time` (s). */
  double weight (double time) const { return time > start_time ? time - start_time : 0; }

  /** Adds the means and, once the average has begun, the variances to `data_out`
   * (`flow_names`: the names of the flow components, suffixed _mean / _variance); the
   * variances are kept here until the next call. */
  void add_fields (dealii::DataOut<dim>           &data_out,
                   const dealii::DoFHandler<dim>  &flow_dof_handler,
                   const dealii::DoFHandler<dim>  &alpha_dof_handler,
                   const std::vector<std::string> &flow_names,
                   double                          time);

  /** The accumulators, in the order FieldTransfer moves them. */
  std::vector<BlockVector *> flow_fields () { return {&flow_mean, &flow_m2}; }
  std::vector<AlphaVector *> scalar_fields ()
  {
    return {&alpha_mean, &alpha_m2, &theta_mean};
  }

  const BlockVector &flow_average () const { return flow_mean; }
  const AlphaVector &alpha_average () const { return alpha_mean; }
  const AlphaVector &theta_average () const { return theta_mean; }
  /** The sums of squared deviations M2 (variance = M2 / weight). */
  const BlockVector &flow_squared_deviations () const { return flow_m2; }
  const AlphaVector &alpha_squared_deviations () const { return alpha_m2; }

private:
  double      start_time;
  BlockVector flow_mean, flow_m2;
  AlphaVector alpha_mean, alpha_m2, theta_mean;
  // the variances of the last output (DataOut reads them when it builds the patches)
  BlockVector flow_variance;
  AlphaVector alpha_variance;
};
} // namespace wetbed
