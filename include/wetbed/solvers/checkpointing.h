#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/mesh/boundaries.h>
#include <wetbed/postprocess/bubble_analysis.h>
#include <wetbed/postprocess/field_output.h>
#include <wetbed/solvers/field_transfer.h>
#include <wetbed/solvers/solver_state.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <string>
#include <utility>
#include <vector>

namespace wetbed
{
/** A file of the output folder the run appends to (monitors.csv, the bubble files):
 * its length at the checkpoint and the FNV-1a hash of those bytes. */
struct AppendedFile
{
  std::string        name; // in the output folder
  unsigned long long bytes = 0, hash = 0;

  template <class Archive>
  void serialize (Archive &archive, const unsigned int)
  {
    archive &name &bytes &hash;
  }
};

/** Everything a resumed run needs besides the mesh and the fields, and the identity of
 * the run that wrote it (the file `state` of a checkpoint). */
struct CheckpointState
{
  // format 5 added solids_fed_mass; a format-4 checkpoint (no solids feed then) reads
  // with 0
  static constexpr unsigned int  current_format = 5, previous_format = 4;
  unsigned int                   format = current_format, dimension = 0;
  std::string                    mesh_file;
  double                         time = 0, time_step = 0, previous_time_step = 0;
  unsigned int                   step_number = 0, rejected_steps = 0;
  double                         next_output_time    = 0;
  unsigned int                   output_index        = 0;
  double                         initial_solids_mass = 0, solids_fed_mass = 0;
  unsigned long long             monitors_bytes = 0;
  std::vector<dealii::XDMFEntry> xdmf_entries;
  std::string                    bubble_state; // the tracker and the bubble CSV lengths
  // (name, FNV-1a hash of the contents) of every file of the saved triangulation
  std::vector<std::pair<std::string, unsigned long long>> files;
  // the identity of the run
  std::string               run_id;
  unsigned long long        mesh_file_hash = 0, coarse_mesh_hash = 0;
  std::vector<AppendedFile> appended_files; // resume cuts them back to these lengths
  std::vector<std::pair<std::string, std::string>> parameters;

  template <class Archive>
  void serialize (Archive &archive, const unsigned int)
  {
    archive &format &dimension &mesh_file &time &time_step &previous_time_step;
    archive &step_number &rejected_steps &next_output_time &output_index;
    archive &initial_solids_mass &monitors_bytes &xdmf_entries &bubble_state &files;
    archive &run_id &mesh_file_hash &coarse_mesh_hash &appended_files        &parameters;
    if (format >= 5)
      archive &solids_fed_mass;
  }
};

/**
 * Checkpoint/restart as a component (doc/theory.md, "Checkpoints"): writes the folder
 * <output folder>/checkpoint (the p4est forest with the cell-wise data of every field,
 * the time-stepping state and the identity of the run, swapped in by renames once
 * complete) and, on resume, reads it back checked against the case
 * (source/solvers/checkpointing.cc). It reads the state through SolverState; the
 * solver orchestrates the resume (the mesh, the DoFs, the fields) from its parts.
 */
template <int dim>
class Checkpointing
{
public:
  /** What a checkpoint keeps besides the state view: the next time step, the length
   * of monitors.csv, the run's id, the field output counters and the lengths of the
   * other files appended to. */
  struct RunRecord
  {
    double                              next_time_step;
    unsigned long long                  monitors_bytes;
    std::string                         run_id;
    typename FieldOutput<dim>::Counters outputs;
    // other files the run appends to (the ECT sensor's): name, bytes
    std::vector<std::pair<std::string, unsigned long long>> appended;
  };

  Checkpointing (const Parameters           &parameters,
                 MPI_Comm                    communicator,
                 dealii::ConditionalOStream &pcout,
                 dealii::TimerOutput        &timer);

  /** Saves `state` with `record` into <output folder>/checkpoint; `fields` are
   * attached for the save (their ghost values updated) and `bubbles` saves its
   * tracker; the checkpoint before is kept until the new one is complete. A full disk
   * throws (status 3) with the previous one kept; collective. */
  void write (const SolverState<dim>       &state,
              const TransferredFields<dim> &fields,
              BubbleAnalysis<dim>          &bubbles,
              const RunRecord              &record);

  /** The state of the checkpoint to resume from (the last complete one), checked
   * against the case: its files, mesh file, parameters and monitors.csv (InputError,
   * status 2, naming what differs); collective. */
  CheckpointState read ();

  /** The case's coarse mesh into `triangulation`, checked against the checkpoint's;
   * returns its boundaries. */
  Boundaries read_coarse_mesh (
      const CheckpointState                             &saved,
      dealii::parallel::distributed::Triangulation<dim> &triangulation) const;

  /** The saved refinement and partition (and the fields' cell data) onto the coarse
   * mesh of read_coarse_mesh(). */
  void load_mesh (dealii::parallel::distributed::Triangulation<dim> &triangulation) const;

  /** The folder read() took the checkpoint from. */
  const std::string &source () const { return folder; }

private:
  const Parameters           &parameters;
  MPI_Comm                    communicator;
  dealii::ConditionalOStream &pcout;
  dealii::TimerOutput        &timer;
  std::string                 folder; // of the last read()
};
} // namespace wetbed
