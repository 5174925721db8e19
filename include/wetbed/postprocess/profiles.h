#pragma once

#include <wetbed/core/statistics_parameters.h>
#include <wetbed/postprocess/field_sampler.h>
#include <wetbed/solvers/solver_state.h>

#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace wetbed
{
/**
 * Profiles and cross-section maps (`subsection statistics`): radial profiles (3D,
 * azimuthal means), lateral profiles (in 3D means over the depth), plane maps and
 * lines, each sampled by a FieldSampler at every field output and at the end of the
 * run and appended to its own CSV file in statistics/ (one block of rows per time).
 * With `time averages` on they sample the time averages (means and standard
 * deviations; nothing before the averages start), otherwise the fields themselves.
 * Rank 0 writes; a resumed run cuts the files back to their lengths at the checkpoint
 * (source/postprocess/profiles.cc).
 */
template <int dim>
class Profiles
{
public:
  explicit Profiles (const StatisticsParameters &parameters);
  ~Profiles ();

  /** A new run: creates statistics/ and each file with its header. */
  void open (const std::string &folder);

  /** A resumed run: continues each file from its length in `appended` (name relative
   * to the output folder, bytes: the checkpoint's); a file the checkpoint does not
   * list starts anew. Throws std::runtime_error if a file is shorter than that. */
  void reopen (const std::string                                             &folder,
               const std::vector<std::pair<std::string, unsigned long long>> &appended);

  /** Samples `state` and appends a block of rows to each file, unless this time was
   * written already or the averages have not started; collective. */
  void write (const SolverState<dim> &state);

  /** (file name relative to the output folder, bytes written) of every file (rank 0;
   * 0 elsewhere). */
  std::vector<std::pair<std::string, unsigned long long>> file_lengths ();

  /** Whether a write failed (a full disk). */
  bool writing_failed () const;

private:
  enum class Kind
  {
    radial,
    lateral,
    plane,
    line
  };
  struct Profile;

  /** The header of a profile's file. */
  std::string header (const Profile &profile) const;
  /** The rows of `profile` for `state` (rank 0; empty elsewhere); collective. */
  std::string rows (Profile &profile, const SolverState<dim> &state) const;
  static void write_position (std::ostream               &out,
                              Kind                        kind,
                              const dealii::Point<dim>   &first,
                              const dealii::Point<dim>   &start,
                              const HorizontalFrame<dim> &frame);

  StatisticsParameters                  parameters;
  std::vector<std::unique_ptr<Profile>> profiles;
  bool                                  root;
  double                                last_time;
};
} // namespace wetbed
