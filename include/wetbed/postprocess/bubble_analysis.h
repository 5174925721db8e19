#pragma once

#include <wetbed/core/bubble_analysis_parameters.h>
#include <wetbed/postprocess/bubble_tracking.h>

#include <deal.II/distributed/cell_data_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/vector.h>

#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace wetbed
{
/**
 * Bubble analysis during a run: detection (detect_bubbles), tracking between analyses
 * by overlap (BubbleTracker) and the files bubbles.csv (one row per bubble per
 * analysis), bubble_events.csv (splittings and coalescences) and bubble_summary.csv
 * (one row per analysis). The bubble of every cell at the last analysis is cell data
 * that follows mesh changes and goes into checkpoints.
 */
template <int dim>
class BubbleAnalysis
{
public:
  BubbleAnalysis (const BubbleAnalysisParameters                          &parameters,
                  const BubbleCriteria                                    &criteria,
                  const dealii::parallel::distributed::Triangulation<dim> &triangulation,
                  unsigned int                                             vertical,
                  MPI_Comm                                                 communicator);

  /** Creates the CSV files in `folder` (rank 0 writes); the last column of each, run,
   * holds `run_id` on every row. */
  void open (const std::string &folder, const std::string &run_id);

  /** Detects and tracks the bubbles of alpha_s (ghosted), appends the rows. Returns the
   * number of bubbles. Collective. */
  unsigned int
  analyse (unsigned int                                              step,
           double                                                    time,
           const dealii::Mapping<dim>                               &mapping,
           const dealii::DoFHandler<dim>                            &dof_handler,
           const dealii::LinearAlgebra::distributed::Vector<double> &alpha_s);

  /** Around a mesh change: the last analysis's cell labels move with the cells. */
  void prepare_for_mesh_change ();
  void after_mesh_change ();

  /** Around Triangulation::save()/load(): the cell labels, in the order of the other
   * attached data. */
  void prepare_for_serialization ();
  void deserialize ();
  /** The tracker state and the CSV lengths; restore_state() cuts the CSV files of
   * `folder` back to the saved lengths and appends from there, rows of run `run_id`. */
  std::string saved_state ();
  void        restore_state (const std::string &state,
                             const std::string &folder,
                             const std::string &run_id);
  /** (name, bytes written) of the open CSV files (rank 0; none elsewhere). */
  std::vector<std::pair<std::string, unsigned long long>> file_lengths ();

  const BubbleTracker &tracker () const { return tracking; }

private:
  using LabelTransfer =
      dealii::parallel::distributed::CellDataTransfer<dim, dim, dealii::Vector<float>>;
  std::unique_ptr<LabelTransfer> make_transfer () const;
  /** A new transfer of previous_label (sized to the mesh, -1 if not analysed on it). */
  LabelTransfer &attach_labels ();

  const BubbleAnalysisParameters                           parameters;
  const BubbleCriteria                                     criteria;
  const dealii::parallel::distributed::Triangulation<dim> &triangulation;
  const unsigned int                                       vertical; // the upward axis
  MPI_Comm                                                 communicator;
  const bool                                               root;

  BubbleTracker                  tracking;
  dealii::Vector<float>          previous_label; // by active cell index; -1: none
  std::unique_ptr<LabelTransfer> transfer;
  std::ofstream                  bubbles_file, events_file, summary_file;
  std::string                    run; // the run's id, the last column of every row
  std::string                    output_folder;
};
} // namespace wetbed
