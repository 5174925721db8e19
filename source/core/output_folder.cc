#include <wetbed/core/input_error.h>
#include <wetbed/core/output_folder.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <regex>
#include <sys/file.h>
#include <unistd.h>

namespace wetbed
{
namespace fs = std::filesystem;

namespace
{
bool holds_results (const std::string &folder)
{
  std::error_code error;
  return fs::exists (folder + "/monitors.csv", error) ||
         fs::exists (folder + "/checkpoint", error) ||
         fs::exists (folder + "/checkpoint.previous", error);
}
} // namespace

OutputFolderLock::OutputFolderLock (const std::string &folder_,
                                    const bool         resume,
                                    const bool         overwrite,
                                    MPI_Comm           communicator)
    : folder (folder_),
      root (dealii::Utilities::MPI::this_mpi_process (communicator) == 0),
      communicator (communicator)
{
  std::string where, error;
  if (root)
  {
    const std::string lock_file = folder + "/.wetbed.lock";
    std::error_code   code;
    try
    {
      if (fs::exists (folder, code) && !fs::is_directory (folder, code))
        throw InputError ("output/folder", "'" + folder + "' exists and is not a folder");
      if (resume && !fs::is_directory (folder, code))
        throw InputError ("checkpoint/resume",
                          "no checkpoint to resume from: the output folder '" + folder +
                              "' does not exist");
      if (!fs::is_directory (folder, code))
      {
        for (fs::path p = fs::absolute (folder, code).lexically_normal ();
             !p.empty () && !fs::exists (p, code) && p != p.parent_path ();
             p = p.parent_path ())
          created_folders.push_back (p.string ());
        fs::create_directories (folder, code);
        if (code || !fs::is_directory (folder))
        {
          undo_creation ();
          throw InputError ("output/folder",
                            "cannot create '" + folder + "' (" + code.message () + ")");
        }
      }
      created_lockfile = !fs::exists (lock_file, code);
      descriptor       = open (lock_file.c_str (), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (descriptor < 0)
      {
        const std::string reason = std::strerror (errno);
        created_lockfile         = false;
        undo_creation ();
        throw InputError ("output/folder",
                          "'" + folder + "' is not writable (cannot create the lock " +
                              lock_file + ": " + reason + ")");
      }
      if (flock (descriptor, LOCK_EX | LOCK_NB) != 0)
      {
        const bool busy = errno == EWOULDBLOCK;
        close (descriptor);
        descriptor = -1;
        throw InputError (
            "output/folder",
            busy ? "'" + folder + "' is in use by another wetbed run (it holds " +
                       lock_file + "); wait for it to end or choose another folder"
                 : "cannot lock '" + lock_file + "': " + std::strerror (errno));
      }
      replacing = !resume && holds_results (folder);
      if (replacing && !overwrite)
        refusal = "'" + folder +
                  "' holds a previous run's results (monitors.csv or checkpoint/): set "
                  "output/overwrite = true or pass --overwrite to replace them, "
                  "checkpoint/resume (--resume) to continue that run, or choose another "
                  "folder";
    }
    catch (const InputError &e)
    {
      const std::string text  = e.what ();
      const auto        colon = text.find (": ");
      where                   = text.substr (0, colon);
      error                   = text.substr (colon + 2);
    }
  }
  where = dealii::Utilities::MPI::broadcast (communicator, where, 0);
  error = dealii::Utilities::MPI::broadcast (communicator, error, 0);
  if (!error.empty ())
  {
    undo_creation ();
    if (descriptor >= 0)
      close (descriptor);
    throw InputError (where, error);
  }
}

void OutputFolderLock::accept_folder ()
{
  // rank 0 looked at the folder
  const std::string why = dealii::Utilities::MPI::broadcast (communicator, refusal, 0);
  if (why.empty ())
    return;
  undo_creation ();
  throw InputError ("output/folder", why);
}

OutputFolderLock::~OutputFolderLock ()
{
  if (descriptor >= 0)
    close (descriptor); // releases the lock
}

void OutputFolderLock::undo_creation ()
{
  if (!root)
    return;
  std::error_code ignored;
  if (created_lockfile)
    fs::remove (folder + "/.wetbed.lock", ignored);
  created_lockfile = false;
  for (const auto &path : created_folders)
    if (fs::is_directory (path, ignored) && fs::is_empty (path, ignored))
      fs::remove (path, ignored);
  created_folders.clear ();
}

void OutputFolderLock::remove_previous_results ()
{
  if (!root || !replacing)
    return;
  std::error_code ignored;
  for (const char *name : {"checkpoint", "checkpoint.previous", "checkpoint.partial"})
    fs::remove_all (folder + "/" + name, ignored);
  const std::regex fields (
      "fields_[0-9]+(\\.[0-9]+)?\\.(pvtu|vtu|h5)|fields\\.(xdmf|pvd)|spectrum\\.csv|"
      "ect_spectrum\\.csv|failure_report\\.txt|parameters_resumed\\.prm");
  for (const auto &entry : fs::directory_iterator (folder, ignored))
    if (entry.is_regular_file (ignored) &&
        std::regex_match (entry.path ().filename ().string (), fields))
      fs::remove (entry.path (), ignored);
  replacing = false;
}
double free_space (const std::string &folder, const MPI_Comm communicator)
{
  double available = 0;
  if (dealii::Utilities::MPI::this_mpi_process (communicator) == 0)
  {
    std::error_code error;
    available = static_cast<double> (fs::space (folder, error).available);
    if (error)
      available = 0;
  }
  return dealii::Utilities::MPI::broadcast (communicator, available, 0);
}
} // namespace wetbed
