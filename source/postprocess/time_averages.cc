#include <wetbed/postprocess/time_averages.h>

#include <algorithm>

namespace wetbed
{
using namespace dealii;

template <int dim>
TimeAverages<dim>::TimeAverages (const double start_time) : start_time (start_time)
{
}

template <int dim>
void TimeAverages<dim>::reinit (const BlockVector &flow_like,
                                const AlphaVector &alpha_like)
{
  for (BlockVector *v : flow_fields ())
  {
    v->reinit (flow_like);
    *v = 0;
  }
  for (AlphaVector *v : scalar_fields ())
  {
    v->reinit (alpha_like);
    *v = 0;
  }
}

template <int dim>
void TimeAverages<dim>::add (const double       time,
                             const double       dt,
                             const BlockVector &flow,
                             const AlphaVector &alpha,
                             const AlphaVector &theta,
                             BlockVector       &owned)
{
  const double total = weight (time);
  const double w     = std::min (dt, total);
  if (w <= 0)
    return;
  const double share = w / total;
  // the flow components, on unghosted copies (the ghosted accumulators are written
  // whole at the end)
  owned = flow;
  BlockVector mean (owned), m2 (owned), delta (owned);
  mean  = flow_mean;
  m2    = flow_m2;
  delta = owned;
  delta -= mean;           // d = x - mean
  mean.add (share, delta); // mean += (w / W) d
  owned -= mean;           // x - mean (new)
  owned.scale (delta);     // d (x - mean)
  m2.add (w, owned);
  flow_mean = mean;
  flow_m2   = m2;
  // alpha_s (mean and M2) and Theta (mean), node by node
  for (unsigned int i = 0; i < alpha.locally_owned_size (); ++i)
  {
    const double a = alpha.local_element (i), d = a - alpha_mean.local_element (i);
    alpha_mean.local_element (i) += share * d;
    alpha_m2.local_element (i) += w * d * (a - alpha_mean.local_element (i));
    theta_mean.local_element (i) +=
        share * (theta.local_element (i) - theta_mean.local_element (i));
  }
  for (AlphaVector *v : scalar_fields ())
    v->update_ghost_values ();
}

template <int dim>
void TimeAverages<dim>::add_fields (DataOut<dim>                   &data_out,
                                    const DoFHandler<dim>          &flow_dof_handler,
                                    const DoFHandler<dim>          &alpha_dof_handler,
                                    const std::vector<std::string> &flow_names,
                                    const double                    time)
{
  std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds (
      2 * dim, DataComponentInterpretation::component_is_part_of_vector);
  kinds.push_back (DataComponentInterpretation::component_is_scalar);
  const auto suffixed = [&] (const std::string &suffix)
  {
    std::vector<std::string> names;
    for (const auto &name : flow_names)
      names.push_back (name + suffix);
    return names;
  };
  data_out.add_data_vector (flow_dof_handler, flow_mean, suffixed ("_mean"), kinds);
  data_out.add_data_vector (alpha_dof_handler, alpha_mean, "alpha_s_mean");
  data_out.add_data_vector (alpha_dof_handler, theta_mean, "granular_temperature_mean");
  // variance = M2 / W (zero before the start)
  const double total = weight (time);
  const double scale = total > 0 ? 1.0 / total : 0.0;
  flow_variance.reinit (flow_m2);
  {
    BlockVector           unghosted;
    std::vector<IndexSet> partitioning;
    for (unsigned int b = 0; b < flow_m2.n_blocks (); ++b)
      partitioning.push_back (flow_m2.block (b).locally_owned_elements ());
    unghosted.reinit (partitioning, flow_m2.block (0).get_mpi_communicator ());
    unghosted = flow_m2;
    unghosted *= scale;
    flow_variance = unghosted;
  }
  alpha_variance.reinit (alpha_m2);
  alpha_variance = alpha_m2;
  alpha_variance *= scale;
  alpha_variance.update_ghost_values ();
  data_out.add_data_vector (
      flow_dof_handler, flow_variance, suffixed ("_variance"), kinds);
  data_out.add_data_vector (alpha_dof_handler, alpha_variance, "alpha_s_variance");
}

template class TimeAverages<2>;
template class TimeAverages<3>;
} // namespace wetbed
