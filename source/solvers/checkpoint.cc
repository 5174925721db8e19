#include <wetbed/core/input_error.h>
#include <wetbed/postprocess/bed_monitors.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/mpi.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

/*
 * Checkpoint/restart. A checkpoint is the folder <output folder>/checkpoint:
 *   triangulation*  p4est forest + the cell-wise data of every field (deal.II's
 *                   parallel SolutionTransfer: u_g, u_s, p' and alpha_s, Theta with
 *                   their two BDF history levels), independent of the rank count;
 *   state           the time-stepping state (t, dt, previous dt, step, rejections),
 *                   the output counters and XDMF index, the initial solids mass and
 *                   the length of monitors.csv at that step.
 * It is written into checkpoint.partial and swapped in by renames only once complete,
 * so that a crash during the write never loses the previous checkpoint (at worst it
 * is left as checkpoint.previous, which a resume falls back on).
 */
namespace wetbed
{
using namespace dealii;

namespace
{
constexpr unsigned int checkpoint_format = 2;

/** Everything a resumed run needs besides the mesh and the fields. */
struct CheckpointState
{
  unsigned int                   format = checkpoint_format, dimension = 0;
  std::string                    mesh_file;
  double                         time = 0, time_step = 0, previous_time_step = 0;
  unsigned int                   step_number = 0, rejected_steps = 0;
  double                         next_output_time    = 0;
  unsigned int                   output_index        = 0;
  double                         initial_solids_mass = 0;
  unsigned long long             monitors_bytes      = 0;
  std::vector<dealii::XDMFEntry> xdmf_entries;
  std::string                    bubble_state; // the tracker and the bubble CSV lengths
  // (name, FNV-1a hash of the contents) of every file of the saved triangulation
  std::vector<std::pair<std::string, unsigned long long>> files;

  template <class Archive>
  void serialize (Archive &archive, const unsigned int)
  {
    archive &format &dimension &mesh_file &time &time_step &previous_time_step;
    archive &step_number &rejected_steps &next_output_time &output_index;
    archive &initial_solids_mass &monitors_bytes &xdmf_entries &bubble_state &files;
  }
};

/** 64-bit FNV-1a hash of a file's bytes (detects truncated or damaged checkpoints). */
unsigned long long file_hash (const std::string &path)
{
  std::ifstream      in (path, std::ios::binary);
  unsigned long long hash = 1469598103934665603ull;
  std::vector<char>  buffer (1 << 16);
  while (in)
  {
    in.read (buffer.data (), buffer.size ());
    for (std::streamsize i = 0; i < in.gcount (); ++i)
    {
      hash ^= static_cast<unsigned char> (buffer[i]);
      hash *= 1099511628211ull;
    }
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

std::string checkpoint_folder (const std::string &output_folder, const char *which = "")
{
  return output_folder + "/checkpoint" + which;
}
} // namespace

template <int dim>
void TwoFluidSolver<dim>::write_checkpoint ()
{
  TimerOutput::Scope scope (timer, "checkpoint");
  const bool         root     = Utilities::MPI::this_mpi_process (communicator) == 0;
  const std::string  target   = checkpoint_folder (parameters.output.folder);
  const std::string  partial  = checkpoint_folder (parameters.output.folder, ".partial");
  const std::string  previous = checkpoint_folder (parameters.output.folder, ".previous");
  if (root)
  {
    std::filesystem::remove_all (partial);
    std::filesystem::create_directories (partial);
  }
  MPI_Barrier (communicator);

  // the order of the transfers is the order in which resume() reads them back
  for (AlphaVector *v :
       {&alpha, &alpha_old, &alpha_old2, &theta, &theta_old, &theta_old2})
    v->update_ghost_values ();
  parallel::distributed::SolutionTransfer<dim, BlockVector> flow_transfer (
      flow_dof_handler);
  flow_transfer.prepare_for_serialization (
      std::vector<const BlockVector *>{&flow_solution, &flow_old, &flow_old2});
  parallel::distributed::SolutionTransfer<dim, AlphaVector> scalar_transfer (
      alpha_dof_handler);
  scalar_transfer.prepare_for_serialization (std::vector<const AlphaVector *>{
      &alpha, &alpha_old, &alpha_old2, &theta, &theta_old, &theta_old2});
  bubble_analysis->prepare_for_serialization ();
  triangulation.save (partial + "/triangulation");

  CheckpointState state;
  state.dimension           = dim;
  state.mesh_file           = parameters.mesh.file;
  state.time                = time;
  state.time_step           = time_step;
  state.previous_time_step  = previous_time_step;
  state.step_number         = step_number;
  state.rejected_steps      = rejected_steps;
  state.next_output_time    = next_output_time;
  state.output_index        = output_index;
  state.initial_solids_mass = initial_solids_mass;
  state.monitors_bytes      = monitors.bytes_written ();
  state.xdmf_entries        = xdmf_entries;
  state.bubble_state        = bubble_analysis->saved_state ();
  MPI_Barrier (communicator);
  if (root)
  {
    for (const std::string &name : triangulation_files (partial))
      state.files.emplace_back (name, file_hash (partial + "/" + name));
    {
      std::ofstream                 out (partial + "/state");
      boost::archive::text_oarchive archive (out);
      archive << state;
      out.flush ();
      if (!out)
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
  pcout << "  checkpoint written at t = " << time << " (step " << step_number << ")"
        << std::endl;
}

template <int dim>
void TwoFluidSolver<dim>::resume_from_checkpoint ()
{
  const std::string output = parameters.output.folder;
  std::string       folder = checkpoint_folder (output);
  // a crash between the two renames of write_checkpoint() leaves only the previous one
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
    std::ifstream                 in (folder + "/state");
    boost::archive::text_iarchive archive (in);
    archive >> state;
  }
  catch (const std::exception &)
  {
    throw InputError ("checkpoint/resume",
                      "'" + folder + "/state' is not a readable wetbed checkpoint");
  }
  require (state.format == checkpoint_format,
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

  for (const auto &[name, hash] : state.files)
    require (std::filesystem::is_regular_file (folder + "/" + name) &&
                 file_hash (folder + "/" + name) == hash,
             "checkpoint/resume",
             "'" + folder + "/" + name + "' is missing or damaged (checksum)");
  require (!state.files.empty (),
           "checkpoint/resume",
           "'" + folder + "/state' lists no mesh files");

  // the coarse mesh of the case, then the saved refinement and partition
  MeshParameters coarse     = parameters.mesh;
  coarse.initial_refinement = 0;
  boundaries                = read_mesh<dim> (coarse,
                               parameters.boundary.moving_wall_name,
                               parameters.parameter_file_directory,
                               output,
                               parameters.physical.gravity,
                               triangulation);
  make_wall_conditions ();
  make_bubble_analysis ();
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
  connect_load_balancing ();
  setup_dofs ();

  {
    FieldTransfers transfers{std::make_unique<FlowTransfer> (flow_dof_handler),
                             std::make_unique<ScalarTransfer> (alpha_dof_handler)};
    receive_fields (transfers, true);
  }
  bubble_analysis->deserialize ();

  time                = state.time;
  time_step           = state.time_step;
  previous_time_step  = state.previous_time_step;
  step_number         = state.step_number;
  rejected_steps      = state.rejected_steps;
  next_output_time    = state.next_output_time;
  output_index        = state.output_index;
  initial_solids_mass = state.initial_solids_mass;
  xdmf_entries        = state.xdmf_entries;
  make_flow_constraints (time);

  monitors.reopen (output + "/monitors.csv",
                   Utilities::MPI::this_mpi_process (communicator) == 0,
                   state.monitors_bytes,
                   monitor_columns ());
  monitors.restore (evaluate_monitors (this->state ()));
  bubble_analysis->restore_state (state.bubble_state, output);
  resumed = true;
  pcout << "Resumed from " << folder << " at t = " << time << " (step " << step_number
        << ")" << std::endl;
}

template void TwoFluidSolver<2>::write_checkpoint ();
template void TwoFluidSolver<3>::write_checkpoint ();
template void TwoFluidSolver<2>::resume_from_checkpoint ();
template void TwoFluidSolver<3>::resume_from_checkpoint ();
} // namespace wetbed
