#include <wetbed/postprocess/bubble_analysis.h>
#include <wetbed/postprocess/csv_append.h>

#include <deal.II/base/mpi.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <iomanip>
#include <map>
#include <sstream>

namespace wetbed
{
using namespace dealii;

template <int dim>
BubbleAnalysis<dim>::BubbleAnalysis (
    const BubbleAnalysisParameters                  &parameters,
    const BubbleCriteria                            &criteria,
    const parallel::distributed::Triangulation<dim> &triangulation,
    const unsigned int                               vertical,
    MPI_Comm                                         communicator)
    : parameters (parameters), criteria (criteria), triangulation (triangulation),
      vertical (vertical), communicator (communicator),
      root (Utilities::MPI::this_mpi_process (communicator) == 0)
{
}

namespace
{
const char *bubbles_header = "step,time,track,volume,equivalent_diameter,centroid_x,"
                             "centroid_y,centroid_z,lower_x,lower_y,lower_z,upper_x,"
                             "upper_y,upper_z,touches_wall,cells,rise_velocity,run\n";
const char *events_header  = "step,time,kind,tracks_before,tracks_after,run\n";
const char *summary_header = "step,time,bubbles,mean_equivalent_diameter,"
                             "bubble_volume,splittings,coalescences,run\n";
// the files, in the order of the saved lengths
const char *file_names[] = {"bubbles.csv", "bubble_events.csv", "bubble_summary.csv"};

std::string join (const std::vector<unsigned int> &tracks)
{
  std::string s;
  for (const unsigned int t : tracks)
    s += (s.empty () ? "" : " ") + std::to_string (t);
  return s;
}
} // namespace

template <int dim>
void BubbleAnalysis<dim>::open (const std::string &folder, const std::string &run_id)
{
  run           = run_id;
  output_folder = folder;
  if (!root || !parameters.enabled)
    return;
  bubbles_file.open (folder + "/" + file_names[0]);
  bubbles_file << bubbles_header;
  events_file.open (folder + "/" + file_names[1]);
  events_file << events_header;
  summary_file.open (folder + "/" + file_names[2]);
  summary_file << summary_header;
}

template <int dim>
unsigned int
BubbleAnalysis<dim>::analyse (const unsigned int     step,
                              const double           time,
                              const Mapping<dim>    &mapping,
                              const DoFHandler<dim> &dof_handler,
                              const LinearAlgebra::distributed::Vector<double> &alpha_s)
{
  const BubbleField field =
      detect_bubbles (mapping, dof_handler, alpha_s, criteria, communicator);

  // overlaps with the bubbles of the previous analysis (cell volumes shared)
  std::map<std::pair<unsigned int, unsigned int>, double> local_overlap;
  const bool have_previous = previous_label.size () == triangulation.n_active_cells ();
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned () && have_previous)
    {
      const int i = field.cell_bubble[cell->active_cell_index ()];
      const int j = static_cast<int> (previous_label[cell->active_cell_index ()]);
      if (i >= 0 && j >= 0)
        local_overlap[{i, j}] += cell->measure ();
    }
  std::vector<double> flat;
  for (const auto &[ij, v] : local_overlap)
    flat.insert (flat.end (), {double (ij.first), double (ij.second), v});
  std::map<std::pair<unsigned int, unsigned int>, double> overlap;
  for (const auto &part : Utilities::MPI::all_gather (communicator, flat))
    for (std::size_t k = 0; k + 2 < part.size (); k += 3)
      overlap[{static_cast<unsigned int> (part[k]),
               static_cast<unsigned int> (part[k + 1])}] += part[k + 2];
  std::vector<BubbleOverlap> overlaps;
  for (const auto &[ij, v] : overlap)
    overlaps.push_back ({ij.first, ij.second, v});
  const auto update = tracking.update (time, field.bubbles, overlaps, vertical);

  previous_label.reinit (triangulation.n_active_cells ());
  for (unsigned int c = 0; c < previous_label.size (); ++c)
    previous_label[c] = field.cell_bubble[c];

  if (root)
  {
    double total = 0, diameters = 0;
    for (unsigned int i = 0; i < field.bubbles.size (); ++i)
    {
      const Bubble &b = field.bubbles[i];
      total += b.volume;
      diameters += b.equivalent_diameter;
      bubbles_file << step << ',' << std::setprecision (10) << time << ','
                   << update.track[i] << ',' << b.volume << ',' << b.equivalent_diameter;
      for (const auto *v : {&b.centroid, &b.lower, &b.upper})
        for (unsigned int d = 0; d < 3; ++d)
          bubbles_file << ',' << (*v)[d];
      bubbles_file << ',' << b.touches_wall << ',' << b.cells << ',';
      if (!std::isnan (update.rise_velocity[i]))
        bubbles_file << update.rise_velocity[i];
      bubbles_file << ',' << run << '\n';
    }
    for (const auto &e : update.events)
      events_file << step << ',' << std::setprecision (10) << time << ','
                  << (e.kind == BubbleEvent::Kind::splitting ? "splitting"
                                                             : "coalescence")
                  << ',' << join (e.before) << ',' << join (e.after) << ',' << run
                  << '\n';
    summary_file << step << ',' << std::setprecision (10) << time << ','
                 << field.bubbles.size () << ','
                 << (field.bubbles.empty () ? 0.0 : diameters / field.bubbles.size ())
                 << ',' << total << ',' << tracking.splittings () << ','
                 << tracking.coalescences () << ',' << run << '\n';
    for (auto *f : {&bubbles_file, &events_file, &summary_file})
      f->flush ();
  }
  // rank 0 writes: all stop together when a file lost a row
  const bool failed = root && (!bubbles_file || !events_file || !summary_file);
  if (Utilities::MPI::broadcast (communicator, failed, 0))
    throw std::runtime_error (
        "output/folder: cannot append to the bubble files in '" + output_folder +
        "' at t = " + std::to_string (time) +
        " (disk full or not writable); the last checkpoint is kept");
  return field.bubbles.size ();
}

template <int dim>
std::unique_ptr<typename BubbleAnalysis<dim>::LabelTransfer>
BubbleAnalysis<dim>::make_transfer () const
{
  // a coarsened cell keeps the label of any child that had one
  return std::make_unique<LabelTransfer> (
      triangulation,
      false,
      &AdaptationStrategies::Refinement::preserve<dim, dim, float>,
      [] (const typename Triangulation<dim>::cell_iterator &,
          const std::vector<float> &children)
      { return *std::max_element (children.begin (), children.end ()); });
}

template <int dim>
typename BubbleAnalysis<dim>::LabelTransfer &BubbleAnalysis<dim>::attach_labels ()
{
  // no analysis on this mesh yet: no labels
  if (previous_label.size () != triangulation.n_active_cells ())
  {
    previous_label.reinit (triangulation.n_active_cells ());
    previous_label = -1.0f;
  }
  transfer = make_transfer ();
  return *transfer;
}

template <int dim>
void BubbleAnalysis<dim>::prepare_for_mesh_change ()
{
  attach_labels ().prepare_for_coarsening_and_refinement (previous_label);
}

template <int dim>
void BubbleAnalysis<dim>::after_mesh_change ()
{
  previous_label.reinit (triangulation.n_active_cells ());
  transfer->unpack (previous_label);
  transfer.reset ();
}

template <int dim>
void BubbleAnalysis<dim>::prepare_for_serialization ()
{
  attach_labels ().prepare_for_serialization (previous_label);
}

template <int dim>
void BubbleAnalysis<dim>::deserialize ()
{
  previous_label.reinit (triangulation.n_active_cells ());
  make_transfer ()->deserialize (previous_label);
  transfer.reset (); // the one of a save() in this run, if any
}

template <int dim>
std::string BubbleAnalysis<dim>::saved_state ()
{
  transfer.reset (); // the labels are in the saved triangulation by now
  std::vector<unsigned long long> bytes;
  for (auto *f : {&bubbles_file, &events_file, &summary_file})
    bytes.push_back (f->is_open () ? static_cast<unsigned long long> (f->tellp ()) : 0);
  bytes = Utilities::MPI::broadcast (communicator, bytes, 0);
  std::ostringstream            out;
  boost::archive::text_oarchive archive (out);
  archive << tracking << bytes;
  return out.str ();
}

template <int dim>
std::vector<std::pair<std::string, unsigned long long>>
BubbleAnalysis<dim>::file_lengths ()
{
  std::vector<std::pair<std::string, unsigned long long>> lengths;
  std::ofstream *files[] = {&bubbles_file, &events_file, &summary_file};
  for (unsigned int f = 0; f < 3; ++f)
    if (files[f]->is_open ())
      lengths.emplace_back (file_names[f],
                            static_cast<unsigned long long> (files[f]->tellp ()));
  return lengths;
}

template <int dim>
void BubbleAnalysis<dim>::restore_state (const std::string &state,
                                         const std::string &folder,
                                         const std::string &run_id)
{
  run           = run_id;
  output_folder = folder;
  std::vector<unsigned long long> bytes;
  std::istringstream              in (state);
  boost::archive::text_iarchive   archive (in);
  archive >> tracking >> bytes;
  if (!root || !parameters.enabled)
    return;
  if (bytes[2] == 0) // the checkpointed run did not analyse bubbles
  {
    open (folder, run_id);
    return;
  }
  continue_csv (bubbles_file, folder + "/" + file_names[0], bytes[0]);
  continue_csv (events_file, folder + "/" + file_names[1], bytes[1]);
  continue_csv (summary_file, folder + "/" + file_names[2], bytes[2]);
}

template class BubbleAnalysis<2>;
template class BubbleAnalysis<3>;
} // namespace wetbed
