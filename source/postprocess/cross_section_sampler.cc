#include <wetbed/postprocess/cross_section_sampler.h>

#include <cmath>
#include <limits>

namespace wetbed
{
using namespace dealii;

template <int dim>
std::vector<Point<dim>> cross_section_points (const HorizontalFrame<dim> &frame,
                                              const std::vector<double>  &heights,
                                              const unsigned int          resolution)
{
  const unsigned int      per_height = dim == 3 ? resolution * resolution : resolution;
  std::vector<Point<dim>> where;
  where.reserve (heights.size () * per_height);
  std::vector<double> horizontal (dim - 1);
  for (const double height : heights)
    for (unsigned int k = 0; k < per_height; ++k)
    {
      const unsigned int index[2] = {k % resolution, k / resolution};
      for (unsigned int a = 0; a < dim - 1; ++a)
      {
        const unsigned int axis = frame.across[a];
        horizontal[a]           = frame.lower[axis] + (index[a] + 0.5) *
                                                (frame.upper[axis] - frame.lower[axis]) /
                                                resolution;
      }
      where.push_back (frame.at (height, horizontal));
    }
  return where;
}

template <int dim>
CrossSectionSampler<dim>::CrossSectionSampler (const std::vector<double> &heights,
                                               const unsigned int         resolution)
    : heights (heights), resolution (resolution),
      per_height (dim == 3 ? resolution * resolution : resolution),
      sampler (
          [heights, resolution] (const SolverState<dim> &s)
          { return cross_section_points (horizontal_frame (s), heights, resolution); })
{
}

template <int dim>
std::vector<double> CrossSectionSampler<dim>::alpha_s (const SolverState<dim> &s)
{
  return sampler.scalar (s, s.alpha);
}

template <int dim>
std::vector<double> CrossSectionSampler<dim>::pressure (const SolverState<dim> &s)
{
  const auto          flow = sampler.flow (s, s.flow_solution);
  std::vector<double> values (flow.size ());
  for (unsigned int i = 0; i < values.size (); ++i)
    values[i] = flow[i][2 * dim];
  return values;
}

template <int dim>
double CrossSectionSampler<dim>::mean (const std::vector<double> &values)
{
  double       sum   = 0;
  unsigned int count = 0;
  for (const double v : values)
    if (!std::isnan (v))
    {
      sum += v;
      ++count;
    }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN ();
}

template std::vector<Point<2>> cross_section_points (const HorizontalFrame<2> &,
                                                     const std::vector<double> &,
                                                     unsigned int);
template std::vector<Point<3>> cross_section_points (const HorizontalFrame<3> &,
                                                     const std::vector<double> &,
                                                     unsigned int);
template class CrossSectionSampler<2>;
template class CrossSectionSampler<3>;
} // namespace wetbed
