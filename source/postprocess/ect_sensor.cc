#include <wetbed/postprocess/csv_append.h>
#include <wetbed/postprocess/ect_sensor.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <limits>

namespace wetbed
{
namespace
{
/** The heights of the levels: the centres of equal parts of the slab. */
std::vector<double> level_heights (const EctSensorParameters &p)
{
  std::vector<double> heights;
  for (unsigned int k = 0; k < p.levels; ++k)
    heights.push_back (p.centre_height - p.thickness / 2 +
                       (k + 0.5) * p.thickness / p.levels);
  return heights;
}

/** Frames at times k/f: the first one after `time` (one at `time` itself counts as
 * written, up to a relative 1e-9 of a frame). */
unsigned long long first_frame_after (const double time, const double rate)
{
  return static_cast<unsigned long long> (std::floor (time * rate + 1e-9)) + 1;
}
} // namespace

template <int dim>
EctSensor<dim>::EctSensor (const EctSensorParameters &parameters)
    : parameters (parameters),
      sampler (level_heights (parameters), parameters.resolution),
      root (dealii::Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0)
{
}

template <int dim>
std::vector<double> EctSensor<dim>::sample (const SolverState<dim> &s)
{
  const std::vector<double> values = sampler.alpha_s (s);
  const unsigned int        pixels = sampler.points_per_height ();
  std::vector<double>       image (pixels + 1, 0.0);
  double                    sum   = 0;
  unsigned int              count = 0;
  for (unsigned int i = 0; i < pixels; ++i)
  {
    double       pixel_sum = 0;
    unsigned int found     = 0;
    for (unsigned int level = 0; level < parameters.levels; ++level)
    {
      const double v = values[level * pixels + i];
      if (!std::isnan (v))
      {
        pixel_sum += v;
        ++found;
      }
    }
    image[i] = found > 0 ? pixel_sum / found : std::numeric_limits<double>::quiet_NaN ();
    sum += pixel_sum;
    count += found;
  }
  image[pixels] = count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN ();
  return image;
}

template <int dim>
void EctSensor<dim>::write_frame (const double time, const std::vector<double> &image)
{
  if (!root)
    return;
  signal << std::setprecision (10) << time << ',' << std::setprecision (8)
         << image.back () << '\n';
  images << std::setprecision (10) << time << std::setprecision (5);
  for (std::size_t i = 0; i + 1 < image.size (); ++i)
    images << ',' << image[i];
  images << '\n';
  signal.flush ();
  images.flush ();
}

template <int dim>
void EctSensor<dim>::open (const std::string &folder, const SolverState<dim> &s)
{
  if (root)
  {
    signal.open (folder + "/" + signal_file, std::ios::trunc);
    images.open (folder + "/" + images_file, std::ios::trunc);
    signal << "time,alpha_s_slab\n";
    images << "time";
    for (unsigned int i = 0; i < sampler.points_per_height (); ++i)
      images << ",pixel_" << i % parameters.resolution << '_'
             << i / parameters.resolution;
    images << '\n';
  }
  previous      = sample (s);
  previous_time = s.time;
  next_frame    = first_frame_after (s.time, parameters.frame_rate);
  write_frame (s.time, previous); // t = 0 is frame 0
}

template <int dim>
void EctSensor<dim>::reopen (
    const std::string                                             &folder,
    const std::vector<std::pair<std::string, unsigned long long>> &appended,
    const SolverState<dim>                                        &s)
{
  if (root)
    for (const auto &[name, bytes] : appended)
    {
      if (name == signal_file)
        continue_csv (signal, folder + "/" + name, bytes);
      if (name == images_file)
        continue_csv (images, folder + "/" + name, bytes);
    }
  previous      = sample (s);
  previous_time = s.time;
  next_frame    = first_frame_after (s.time, parameters.frame_rate);
}

template <int dim>
void EctSensor<dim>::record (const SolverState<dim> &s, const double next_step)
{
  const double rate = parameters.frame_rate;
  // a step shorter than planned (rejected, or the last) ends earlier: if even the
  // planned one ends before the next frame, this step's image is not needed
  const bool passed = next_frame <= s.time * rate + 1e-9;
  if (!passed && next_frame > (s.time + next_step) * rate + 2e-9)
    return;
  const std::vector<double> current = sample (s);
  for (; next_frame <= s.time * rate + 1e-9; ++next_frame)
  {
    const double        frame_time = next_frame / rate;
    const double        w          = s.time > previous_time
                                         ? (frame_time - previous_time) / (s.time - previous_time)
                                         : 1;
    std::vector<double> frame (current.size ());
    for (std::size_t i = 0; i < frame.size (); ++i)
      frame[i] = (1 - w) * previous[i] + w * current[i];
    write_frame (frame_time, frame);
  }
  previous      = current;
  previous_time = s.time;
}

template <int dim>
std::vector<std::pair<std::string, unsigned long long>> EctSensor<dim>::file_lengths ()
{
  const auto length = [&] (std::ofstream &file)
  {
    return root && file.is_open () ? static_cast<unsigned long long> (file.tellp ())
                                   : 0ull;
  };
  return {{signal_file, length (signal)}, {images_file, length (images)}};
}

template <int dim>
bool EctSensor<dim>::writing_failed () const
{
  return root && ((signal.is_open () && !signal) || (images.is_open () && !images));
}

template class EctSensor<2>;
template class EctSensor<3>;
} // namespace wetbed
