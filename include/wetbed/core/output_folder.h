#pragma once

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

namespace wetbed
{
/** The bytes free on the file system of `folder` as rank 0 sees it (0 if it cannot
 * tell), on every rank; collective. What a write checks for room before it starts. */
double free_space (const std::string &folder, MPI_Comm communicator);

/**
 * The output folder of a run, held for the whole run: rank 0 creates it if missing
 * (the input has been read and checked by then), takes an exclusive lock (flock on
 * `<folder>/.wetbed.lock`) and refuses a new run into a folder that holds a previous
 * run's results (monitors.csv, checkpoint/) unless `overwrite`; the decision is
 * broadcast, every rank throws the same InputError naming `output/folder` (or
 * `checkpoint/resume`). The lock is released when the object is destroyed (or the
 * process ends).
 */
class OutputFolderLock
{
public:
  OutputFolderLock (const std::string &folder,
                    bool               resume,
                    bool               overwrite,
                    MPI_Comm           communicator);
  ~OutputFolderLock ();
  OutputFolderLock (const OutputFolderLock &)            = delete;
  OutputFolderLock &operator= (const OutputFolderLock &) = delete;

  /**
   * The run was refused (bad input or mesh): removes what this object created, the
   * lock file and the folders that did not exist before (if they are empty), so that
   * a refused run leaves the file system as it found it.
   */
  void undo_creation ();

  /**
   * The whole input has been checked (the mesh read, the initial state made): throws
   * the InputError naming output/folder that the folder deserves (it holds a previous
   * run's results and neither overwrite nor resume was asked for), after
   * undo_creation(); nothing otherwise. Until then the refusal waits, so that a case
   * with a bad input is refused for its input, not for its folder.
   */
  void accept_folder ();

  /**
   * The new run's input and mesh are accepted and it replaces a previous run: removes
   * that run's checkpoint (checkpoint, checkpoint.previous, checkpoint.partial) and
   * its field files (with fields.xdmf and fields.pvd), spectrum.csv, ect_spectrum.csv,
   * failure_report.txt and parameters_resumed.prm, which the new run would otherwise
   * leave mixed with its own.
   */
  void remove_previous_results ();

private:
  std::string              folder;
  bool                     root;
  bool                     replacing        = false; // a previous run's results are here
  bool                     created_lockfile = false;
  int                      descriptor       = -1;
  std::string              refusal; // the folder's, until accept_folder()
  MPI_Comm                 communicator;
  std::vector<std::string> created_folders; // deepest first
};
} // namespace wetbed
