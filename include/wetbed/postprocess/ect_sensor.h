#pragma once

#include <wetbed/core/ect_sensor_parameters.h>
#include <wetbed/postprocess/cross_section_sampler.h>
#include <wetbed/solvers/solver_state.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace wetbed
{
/**
 * An ECT-like sensor (`subsection ECT sensor`): the solids fraction of a horizontal
 * slab, recorded at a fixed frame rate whatever the time step. After every accepted
 * step the slab is sampled (`levels` cross-sections of `resolution` x `resolution`
 * points, CrossSectionSampler); each frame time k/f that the step passed is written,
 * interpolated linearly between the samples before and after it: to ect.csv the mean
 * over the slab (alpha_s_slab), to ect_images.csv the image (each pixel averaged
 * across the slab; nan outside the domain). Rank 0 writes; a resumed run cuts both
 * files back to their lengths at the checkpoint (source/postprocess/ect_sensor.cc).
 */
template <int dim>
class EctSensor
{
public:
  explicit EctSensor (const EctSensorParameters &parameters);

  /** A new run: opens both files with their headers and writes the frame at t = 0. */
  void open (const std::string &folder, const SolverState<dim> &state);

  /** A resumed run: continues both files from their lengths in `appended` (name,
   * bytes: the checkpoint's) and samples the restored state, whose frames are
   * written. Throws std::runtime_error if a file is shorter than that. */
  void reopen (const std::string                                             &folder,
               const std::vector<std::pair<std::string, unsigned long long>> &appended,
               const SolverState<dim>                                        &state);

  /** After an accepted step: the frames since the last call; collective. The fields
   * are sampled only at a step that passes a frame time and at the step before one the
   * next step (at most `next_step` long) may pass: a frame interpolates between these two
   * (on an adapted mesh each sample after a mesh change locates the pixels anew). */
  void record (const SolverState<dim> &state, double next_step);

  /** (file name, bytes written) of both files (rank 0; 0 elsewhere). */
  std::vector<std::pair<std::string, unsigned long long>> file_lengths ();

  /** Whether a write failed (a full disk). */
  bool writing_failed () const;

  static constexpr const char *signal_file = "ect.csv";
  static constexpr const char *images_file = "ect_images.csv";

private:
  /** The image (pixels averaged over the levels) and the slab mean of `state`. */
  std::vector<double> sample (const SolverState<dim> &state);
  void                write_frame (double time, const std::vector<double> &image);

  EctSensorParameters      parameters;
  CrossSectionSampler<dim> sampler;
  bool                     root;
  std::ofstream            signal, images;
  double                   previous_time = 0;
  std::vector<double>      previous; // image pixels, then the slab mean
  unsigned long long       next_frame = 0;
};
} // namespace wetbed
