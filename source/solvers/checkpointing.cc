#include <wetbed/core/input_error.h>
#include <wetbed/core/output_folder.h>
#include <wetbed/mesh/mesh_input.h>
#include <wetbed/solvers/checkpointing.h>

#include <deal.II/base/mpi.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

/*
 * Checkpoint/restart. A checkpoint is the folder <output folder>/checkpoint:
 *   triangulation*  p4est forest + the cell-wise data of every field (deal.II's
 *                   parallel SolutionTransfer: u_g, u_s, p' and alpha_s, Theta with
 *                   their two BDF history levels), independent of the rank count;
 *   state           the time-stepping state (t, dt, previous dt, step, rejections),
 *                   the output counters and XDMF index, the initial solids mass, the
 *                   length of monitors.csv at that step and a hash of those bytes; the
 *                   identity of the run: its id, a hash of the mesh file and of the
 *                   coarse mesh made from it, every parameter, and a hash of each file
 *                   of the triangulation;
 *   state.checksum  the hash of `state` itself.
 * A resume refuses (status 2, naming what differs) a checkpoint whose files do not
 * match their hashes, whose mesh or parameters differ from the case's (but for those
 * that may change on resume, resume_may_change), or whose monitors.csv or bubble files
 * are not the ones its run wrote.
 * It is written into checkpoint.partial and swapped in by renames only once complete,
 * so that a crash during the write never loses the previous checkpoint (at worst it
 * is left as checkpoint.previous, which a resume falls back on).
 */
namespace wetbed
{
using namespace dealii;

namespace
{
/** The parameters that may differ on resume: when the run ends, how it steps and
 * solves, what and how often it writes, how the mesh is partitioned and adapted (a run
 * spun up on a fixed mesh may go on with adaptive refinement from its state, and the
 * reverse), and the checkpoints themselves; everything else defines the problem or the
 * files being continued. */
bool resume_may_change (const std::string &name)
{
  static const std::vector<std::string> names = {
      "time stepping/end time",
      "time stepping/maximum time step",
      "time stepping/minimum time step",
      "time stepping/cfl target",
      "time stepping/courant measure",
      "time stepping/time error tolerance",
      "time stepping/growth factor",
      "time stepping/outer iterations",
      "time stepping/outer tolerance",
      "time stepping/outer alpha tolerance",
      "time stepping/outer forcing",
      "time stepping/extrapolate initial guess",
      "output/folder",
      "output/field format",
      "output/field interval",
      "output/monitor interval",
      "output/overwrite",
      "output/progress interval",
      "mesh/wall face weight"};
  static const std::vector<std::string> subsections = {"checkpoint/",
                                                       "linear solver/",
                                                       "spectrum/",
                                                       "divergence checks/",
                                                       "adaptive refinement/"};
  if (std::find (names.begin (), names.end (), name) != names.end ())
    return true;
  for (const std::string &s : subsections)
    if (name.rfind (s, 0) == 0)
      return true;
  return false;
}

constexpr unsigned long long fnv_offset = 1469598103934665603ull;

void fnv_add (unsigned long long &hash, const char *bytes, const std::size_t n)
{
  for (std::size_t i = 0; i < n; ++i)
  {
    hash ^= static_cast<unsigned char> (bytes[i]);
    hash *= 1099511628211ull;
  }
}

/** A 64-bit FNV-1a hash of a string's bytes. */
unsigned long long text_hash (const std::string &text)
{
  unsigned long long hash = fnv_offset;
  fnv_add (hash, text.data (), text.size ());
  return hash;
}

/** The hash of the vertices of the coarse cells, in their order. */
template <int dim>
unsigned long long coarse_mesh_hash (const Triangulation<dim> &triangulation)
{
  unsigned long long hash = fnv_offset;
  for (auto cell = triangulation.begin (0); cell != triangulation.end (0); ++cell)
    for (const unsigned int v : cell->vertex_indices ())
      for (unsigned int d = 0; d < dim; ++d)
      {
        const double x = cell->vertex (v)[d];
        fnv_add (hash, reinterpret_cast<const char *> (&x), sizeof x);
      }
  return hash;
}

/** 64-bit FNV-1a hash of a file's first `length` bytes (all by default; detects
 * truncated or damaged files). */
unsigned long long
file_hash (const std::string &path,
           unsigned long long length = std::numeric_limits<unsigned long long>::max ())
{
  std::ifstream      in (path, std::ios::binary);
  unsigned long long hash = fnv_offset;
  std::vector<char>  buffer (1 << 16);
  while (in && length > 0)
  {
    in.read (buffer.data (), std::min<unsigned long long> (buffer.size (), length));
    fnv_add (hash, buffer.data (), in.gcount ());
    length -= in.gcount ();
  }
  return hash;
}

/** The files triangulation.save() wrote into `folder`, sorted. */
std::vector<std::string> triangulation_files (const std::string &folder)
{
  std::vector<std::string> names;
  for (const auto &entry : std::filesystem::directory_iterator (folder))
    if (entry.path ().filename ().string ().rfind ("triangulation", 0) == 0)
      names.push_back (entry.path ().filename ().string ());
  std::sort (names.begin (), names.end ());
  return names;
}

/** A parameter's text as words (the runs between separators and blanks) and the
 * separators ',', ';', ':' themselves. */
std::vector<std::string> parameter_tokens (const std::string &text)
{
  std::vector<std::string> tokens;
  std::string              word;
  for (const char c : text + ' ')
    if (c == ',' || c == ';' || c == ':' || std::isspace (static_cast<unsigned char> (c)))
    {
      if (!word.empty ())
        tokens.push_back (word);
      word.clear ();
      if (!std::isspace (static_cast<unsigned char> (c)))
        tokens.emplace_back (1, c);
    }
    else
      word += c;
  return tokens;
}

/** Two texts of one parameter that mean the same: the same separators and words, a
 * number equal to a number however written ("1" and "1.0", "0.05" and "5e-2", "0,
 * -9.81" and "0,-9.81"). */
bool same_parameter_value (const std::string &a, const std::string &b)
{
  if (a == b)
    return true;
  const std::vector<std::string> ta = parameter_tokens (a), tb = parameter_tokens (b);
  if (ta.size () != tb.size ())
    return false;
  const auto number = [] (const std::string &word, double &value)
  {
    char *end = nullptr;
    value     = std::strtod (word.c_str (), &end);
    return !word.empty () && end == word.c_str () + word.size ();
  };
  for (std::size_t i = 0; i < ta.size (); ++i)
  {
    double x = 0, y = 0;
    if (ta[i] != tb[i] && !(number (ta[i], x) && number (tb[i], y) && x == y))
      return false;
  }
  return true;
}

/**
 * The checkpoint is this case's: the same mesh file (its bytes), the same parameters
 * but for those that may change on resume, and the run's own monitors.csv and bubble
 * files (their first bytes as saved); InputError (status 2) naming what differs.
 */
void check_identity (const CheckpointState &state,
                     const Parameters      &parameters,
                     const std::string     &folder)
{
  const std::string mesh =
      check_mesh_file (parameters.mesh, parameters.parameter_file_directory);
  require (file_hash (mesh) == state.mesh_file_hash,
           "checkpoint/resume",
           "mesh/file '" + mesh + "' has changed since the checkpoint in '" + folder +
               "' was written");
  const std::map<std::string, std::string> saved (state.parameters.begin (),
                                                  state.parameters.end ());
  for (const auto &[name, value] : parameters.values)
  {
    if (resume_may_change (name))
      continue;
    const auto it = saved.find (name);
    // a parameter newer than the checkpoint: its default is what that run did
    const auto declared = parameters.defaults.find (name);
    if (it == saved.end () && declared != parameters.defaults.end () &&
        same_parameter_value (declared->second, value))
      continue;
    require (
        it != saved.end () && same_parameter_value (it->second, value),
        "checkpoint/resume",
        name + " = '" + value + "', the checkpoint's run had '" +
            (it == saved.end () ? std::string ("no such parameter") : it->second) +
            "' (on resume only the end time, time-step limits, outer iterations, output, "
            "checkpoint, linear solver, spectrum and divergence check settings "
            "may change)");
  }
  // monitors.csv and the bubble files: resume cuts them back, so each must still begin
  // with what the checkpoint's run had written
  for (const AppendedFile &appended : state.appended_files)
  {
    const std::string file = parameters.output.folder + "/" + appended.name;
    require (std::filesystem::is_regular_file (file) &&
                 std::filesystem::file_size (file) >= appended.bytes &&
                 file_hash (file, appended.bytes) == appended.hash,
             "checkpoint/resume",
             "'" + file + "' is not the one the checkpoint's run wrote (run " +
                 state.run_id + "); resuming would cut or rewrite it");
  }
}

std::string checkpoint_folder (const std::string &output_folder, const char *which = "")
{
  return output_folder + "/checkpoint" + which;
}
} // namespace

template <int dim>
Checkpointing<dim>::Checkpointing (const Parameters   &parameters,
                                   MPI_Comm            communicator,
                                   ConditionalOStream &pcout,
                                   TimerOutput        &timer)
    : parameters (parameters), communicator (communicator), pcout (pcout), timer (timer)
{
}

template <int dim>
void Checkpointing<dim>::write (const SolverState<dim>       &s,
                                const TransferredFields<dim> &fields,
                                BubbleAnalysis<dim>          &bubbles,
                                const RunRecord              &record)
{
  TimerOutput::Scope scope (timer, "checkpoint");
  const bool         root     = Utilities::MPI::this_mpi_process (communicator) == 0;
  const std::string  target   = checkpoint_folder (parameters.output.folder);
  const std::string  partial  = checkpoint_folder (parameters.output.folder, ".partial");
  const std::string  previous = checkpoint_folder (parameters.output.folder, ".previous");
  // room for the new one beside the last (p4est aborts the run on a full disk): the
  // cell-wise field data SolutionTransfer writes (3 flow and 6 scalar vectors), 10%
  // more and 64 kB for the forest and the state; refused on every rank together
  // (status 3), the previous checkpoint kept
  const double needed =
      1.1 * 8.0 * s.triangulation.n_global_active_cells () *
          (3.0 * s.flow_fe.n_dofs_per_cell () + 6.0 * s.alpha_fe.n_dofs_per_cell ()) +
      65536.0;
  const double available = free_space (parameters.output.folder, communicator);
  if (available < needed)
    throw std::runtime_error ("output/folder: no room for a checkpoint in '" +
                              parameters.output.folder +
                              "' at t = " + std::to_string (s.time) + " (needs ~" +
                              std::to_string (needed / 1048576.0) + " MB, " +
                              std::to_string (available / 1048576.0) +
                              " MB free); the previous checkpoint is kept");
  if (root)
  {
    std::filesystem::remove_all (partial);
    std::filesystem::create_directories (partial);
  }
  MPI_Barrier (communicator);

  // the order of the transfers is the order in which a resume reads them back
  FieldTransfer<dim> transfer (s.flow_dof_handler, s.alpha_dof_handler);
  transfer.attach (fields, true);
  bubbles.prepare_for_serialization ();
  s.triangulation.save (partial + "/triangulation");

  CheckpointState state;
  state.dimension           = dim;
  state.mesh_file           = parameters.mesh.file;
  state.time                = s.time;
  state.time_step           = record.next_time_step;
  state.previous_time_step  = s.time_step;
  state.step_number         = s.step_number;
  state.rejected_steps      = s.rejected_steps;
  state.next_output_time    = record.outputs.next_output_time;
  state.output_index        = record.outputs.output_index;
  state.initial_solids_mass = s.initial_solids_mass;
  state.solids_fed_mass     = s.solids_fed_mass;
  state.monitors_bytes      = record.monitors_bytes;
  state.xdmf_entries        = record.outputs.xdmf_entries;
  state.bubble_state        = bubbles.saved_state ();
  state.run_id              = record.run_id;
  state.mesh_file_hash =
      file_hash (check_mesh_file (parameters.mesh, parameters.parameter_file_directory));
  state.coarse_mesh_hash = coarse_mesh_hash<dim> (s.triangulation);
  state.parameters       = parameters.values;
  MPI_Barrier (communicator);
  if (root)
  {
    std::vector<std::pair<std::string, unsigned long long>> appended =
        bubbles.file_lengths ();
    appended.emplace_back ("monitors.csv", state.monitors_bytes);
    appended.insert (appended.end (), record.appended.begin (), record.appended.end ());
    for (const auto &[name, bytes] : appended)
      if (bytes > 0)
        state.appended_files.push_back (
            {name, bytes, file_hash (parameters.output.folder + "/" + name, bytes)});
    for (const std::string &name : triangulation_files (partial))
      state.files.emplace_back (name, file_hash (partial + "/" + name));
    {
      std::ostringstream text;
      {
        boost::archive::text_oarchive archive (text);
        archive << state;
      }
      std::ofstream out (partial + "/state");
      out << text.str ();
      std::ofstream sum (partial + "/state.checksum");
      sum << text_hash (text.str ()) << "\n";
      out.flush ();
      sum.flush ();
      if (!out || !sum)
        throw std::runtime_error ("could not write the checkpoint state in " + partial);
    }
    // swap: the old checkpoint is removed only once the new one is in place
    std::filesystem::remove_all (previous);
    if (std::filesystem::exists (target))
      std::filesystem::rename (target, previous);
    std::filesystem::rename (partial, target);
    std::filesystem::remove_all (previous);
  }
  MPI_Barrier (communicator);
  pcout << "  checkpoint written at t = " << s.time << " (step " << s.step_number << ")"
        << std::endl;
}

template <int dim>
CheckpointState Checkpointing<dim>::read ()
{
  const std::string output = parameters.output.folder;
  folder                   = checkpoint_folder (output);
  // a crash between the two renames of write() leaves only the previous one
  if (!std::filesystem::is_regular_file (folder + "/state") &&
      std::filesystem::is_regular_file (checkpoint_folder (output, ".previous") +
                                        "/state"))
    folder = checkpoint_folder (output, ".previous");
  require (std::filesystem::is_regular_file (folder + "/state"),
           "checkpoint/resume",
           "no checkpoint to resume from in '" + output + "' (expected " + folder +
               "/state)");

  CheckpointState state;
  try
  {
    std::ifstream      in (folder + "/state");
    std::ostringstream text;
    text << in.rdbuf ();
    unsigned long long saved_sum = 0;
    std::ifstream (folder + "/state.checksum") >> saved_sum;
    require (saved_sum == text_hash (text.str ()),
             "checkpoint/resume",
             "'" + folder + "/state' is damaged or was edited (its checksum differs)");
    std::istringstream            saved (text.str ());
    boost::archive::text_iarchive archive (saved);
    archive >> state;
  }
  catch (const InputError &)
  {
    throw;
  }
  catch (const std::exception &)
  {
    throw InputError ("checkpoint/resume",
                      "'" + folder + "/state' is not a readable wetbed checkpoint");
  }
  require (state.format == CheckpointState::current_format ||
               state.format == CheckpointState::previous_format,
           "checkpoint/resume",
           "'" + folder + "' was written by another checkpoint format version");
  require (state.dimension == dim,
           "checkpoint/resume",
           "'" + folder + "' holds a " + std::to_string (state.dimension) +
               "D run, the case is " + std::to_string (dim) + "D");
  require (state.mesh_file == parameters.mesh.file,
           "checkpoint/resume",
           "'" + folder + "' was written with mesh/file = " + state.mesh_file +
               ", the case has " + parameters.mesh.file);

  check_identity (state, parameters, folder);
  for (const auto &[name, hash] : state.files)
    require (std::filesystem::is_regular_file (folder + "/" + name) &&
                 file_hash (folder + "/" + name) == hash,
             "checkpoint/resume",
             "'" + folder + "/" + name + "' is missing or damaged (checksum)");
  require (!state.files.empty (),
           "checkpoint/resume",
           "'" + folder + "/state' lists no mesh files");
  return state;
}

template <int dim>
Boundaries Checkpointing<dim>::read_coarse_mesh (
    const CheckpointState                     &saved,
    parallel::distributed::Triangulation<dim> &triangulation) const
{
  // the coarse mesh of the case, then the saved refinement and partition
  MeshParameters coarse       = parameters.mesh;
  coarse.initial_refinement   = 0;
  const Boundaries boundaries = read_mesh<dim> (coarse,
                                                parameters.boundary.moving_wall_name,
                                                parameters.parameter_file_directory,
                                                parameters.output.folder,
                                                parameters.physical.gravity,
                                                triangulation);
  require (coarse_mesh_hash<dim> (triangulation) == saved.coarse_mesh_hash,
           "checkpoint/resume",
           "the mesh made from mesh/file differs from the one of the checkpoint's run");
  return boundaries;
}

template <int dim>
void Checkpointing<dim>::load_mesh (
    parallel::distributed::Triangulation<dim> &triangulation) const
{
  try
  {
    triangulation.load (folder + "/triangulation");
  }
  catch (const std::exception &e)
  {
    throw InputError ("checkpoint/resume",
                      "the mesh in '" + folder +
                          "' cannot be loaded (corrupt, or not "
                          "made from mesh/file)");
  }
}

template class Checkpointing<2>;
template class Checkpointing<3>;
} // namespace wetbed
