#include <wetbed/command_line/application.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/output_folder.h>
#include <wetbed/core/parameters.h>
#include <wetbed/core/stall_watchdog.h>
#include <wetbed/mesh/mesh_input.h>
#include <wetbed/postprocess/closure_table.h>
#include <wetbed/postprocess/spectrum.h>
#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace wetbed
{
namespace
{
void print_usage (std::ostream &out)
{
  out << "wetbed: two-fluid (Euler-Euler) simulation of gas-solid fluidized beds\n\n"
         "usage:\n"
         "  wetbed CASE.prm                run the case (mpirun -np N wetbed CASE.prm)\n"
         "  wetbed CASE.prm --resume       continue it from <output folder>/checkpoint\n"
         "  wetbed CASE.prm --overwrite    replace a previous run's results in the "
         "output folder\n"
         "  wetbed CASE.prm --threads N    N threads per rank for the flow assembly "
         "(default 1)\n"
         "  wetbed --print-parameters [json]\n"
         "                                 every parameter with default and "
         "documentation\n"
         "                                 (json: with its pattern, for "
         "scripts/make_parameter_doc.py)\n"
         "  wetbed closures CASE.prm [--alpha-s A,..] [--theta T,..] [--shear-rate "
         "G,..]\n"
         "                 [--points FILE]  every dry and wet closure of the case at "
         "the\n"
         "                                 points (CSV on stdout; FILE rows: alpha_s "
         "theta shear_rate)\n"
         "  wetbed spectrum MONITORS.csv [--start T] [--segments K] [--columns A,B]\n"
         "                                 Welch spectra of monitors.csv columns (CSV "
         "on\n"
         "                                 stdout; default: pressure_drop and the "
         "planes)\n"
         "  wetbed --help                  this text\n\n"
         "Results go to `output/folder` of the case: parameters.prm, monitors.csv,\n"
         "fields_*.pvtu. Exit status: 0 done, 1 usage, 2 bad input, 3 run failed,\n"
         "4 stopped by SIGTERM/SIGINT/SIGUSR2 after writing a checkpoint,\n"
         "5 ended by checkpoint/stall timeout (a rank stopped or lost).\n";
}

/** The text of an exception on one line (deal.II's messages span several). */
std::string one_line (const std::string &text)
{
  std::string line;
  bool        blank = false;
  for (const char c : text)
    if (c == '\n' || c == '\r' || c == '\t' || c == ' ')
      blank = !line.empty ();
    else
    {
      if (blank)
        line += ' ';
      line += c;
      blank = false;
    }
  return line;
}

/** `wetbed spectrum MONITORS.csv [--start T] [--segments K] [--columns A,B]`. */
int spectrum_command (const std::vector<std::string> &arguments)
{
  double                   start    = 0;
  unsigned int             segments = 4;
  std::vector<std::string> columns;
  for (std::size_t i = 1; i < arguments.size (); i += 2)
  {
    const std::string &option = arguments[i];
    if (option != "--start" && option != "--segments" && option != "--columns")
      throw InputError ("spectrum " + option,
                        "unknown option (--start, --segments, --columns)");
    if (i + 1 >= arguments.size ())
      throw InputError ("spectrum " + option, "needs a value");
    const std::string &value = arguments[i + 1];
    std::size_t        used  = 0;
    if (option == "--start")
    {
      try
      {
        start = std::stod (value, &used);
      }
      catch (const std::logic_error &)
      {
        used = 0;
      }
      require (used == value.size () && used > 0,
               "spectrum --start",
               "'" + value + "' is not a number");
      require (std::isfinite (start) && start >= 0,
               "spectrum --start",
               "'" + value + "' is not a finite time >= 0 (s)");
    }
    else if (option == "--segments")
    {
      long n = 0;
      try
      {
        n = std::stol (value, &used);
      }
      catch (const std::logic_error &)
      {
        used = 0;
      }
      require (used == value.size () && used > 0,
               "spectrum --segments",
               "'" + value + "' is not a number");
      require (n >= 1 && n <= 1024,
               "spectrum --segments",
               "'" + value + "' is not a segment count in [1, 1024]");
      segments = static_cast<unsigned int> (n);
    }
    else
    {
      columns = dealii::Utilities::split_string_list (value);
      require (!columns.empty (), "spectrum --columns", "names no column");
      for (const auto &name : columns)
        require (!name.empty (),
                 "spectrum --columns",
                 "has an empty column name in '" + value + "'");
    }
  }
  try
  {
    write_monitor_spectra (arguments[0], columns, start, segments, std::cout);
  }
  catch (const std::invalid_argument &e)
  {
    throw InputError ("spectrum " + arguments[0], e.what ());
  }
  return 0;
}

/**
 * Runs the case; returns the exit status (0 finished, 4 stopped by a signal). Nothing
 * is created before the parameters and the mesh file have been checked; the output
 * folder is then locked for the whole run; a run refused on its input or mesh removes
 * what it created and changes nothing that was there.
 */
template <int dim>
int run_case (const Parameters &parameters, const dealii::ParameterHandler &prm)
{
  const bool resume = parameters.checkpoint.resume;
  if (!resume)
    check_mesh_file (parameters.mesh, parameters.parameter_file_directory);
  OutputFolderLock folder (
      parameters.output.folder, resume, parameters.output.overwrite, MPI_COMM_WORLD);
  // ends the run if a rank stops making progress (checkpoint/stall timeout)
  const StallWatchdog watchdog (parameters.checkpoint.stall_timeout,
                                parameters.output.folder);
  DeferredMeshCommit  mesh; // mesh.msh only once the whole case is accepted
  TwoFluidSolver<dim> solver (parameters, MPI_COMM_WORLD);
  try
  {
    solver.initialize ([&folder] () { folder.accept_folder (); });
  }
  catch (const InputError &)
  {
    mesh.discard ();
    folder.undo_creation ();
    throw;
  }
  catch (const std::exception &e)
  {
    mesh.discard ();
    folder.undo_creation ();
    // whatever stops a resume before the run continues is a problem of the checkpoint
    // (the input), not a failed run
    if (resume)
    {
      std::string reason = one_line (e.what ());
      if (reason.rfind ("checkpoint/resume: ", 0) == 0)
        reason = reason.substr (19);
      throw InputError ("checkpoint/resume",
                        "cannot resume from '" + parameters.output.folder +
                            "/checkpoint': " + reason);
    }
    throw;
  }
  mesh.commit ();
  folder.remove_previous_results ();
  if (dealii::Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0)
    prm.print_parameters (parameters.output.folder +
                              (resume ? "/parameters_resumed.prm" : "/parameters.prm"),
                          dealii::ParameterHandler::PRM);
  return solver.run () == TwoFluidSolver<dim>::RunEnd::finished ? 0 : 4;
}

/** Takes every `flag` out of the arguments; whether there was one. */
bool take_flag (int &argc, char **argv, const std::string &flag)
{
  bool found = false;
  for (int i = 1; i < argc; ++i)
    if (argv[i] == flag)
    {
      for (int j = i; j + 1 < argc; ++j)
        argv[j] = argv[j + 1];
      --argc;
      --i;
      found = true;
    }
  return found;
}
} // namespace

unsigned int take_threads_option (int &argc, char **argv)
{
  unsigned int threads = 1;
  for (int i = 1; i < argc; ++i)
  {
    if (std::string (argv[i]) != "--threads")
      continue;
    require (i + 1 < argc, "--threads", "needs a value");
    const std::string value = argv[i + 1];
    std::size_t       end   = 0;
    long              n     = 0;
    try
    {
      n = std::stol (value, &end);
    }
    catch (const std::logic_error &)
    {
      end = 0;
    }
    require (end == value.size () && n >= 1 && n <= 1024,
             "--threads",
             "'" + value + "' is not a thread count (an integer >= 1)");
    threads = static_cast<unsigned int> (n);
    for (int j = i; j + 2 <= argc; ++j)
      argv[j] = argv[j + 2];
    argc -= 2;
    --i;
  }
  return threads;
}

int run_application (int argc, char **argv)
{
  const bool root = dealii::Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0;
  if (argc >= 3 && std::string (argv[1]) == "closures")
  {
    try
    {
      dealii::ParameterHandler prm;
      const Parameters         parameters = Parameters::read (argv[2], prm);
      const auto               points =
          closure_points (std::vector<std::string> (argv + 3, argv + argc), parameters);
      if (root)
        write_closure_table (parameters, points, std::cout);
      return 0;
    }
    catch (const InputError &e)
    {
      if (root)
        std::cerr << "wetbed: error: " << e.what () << std::endl;
      return 2;
    }
  }
  if (argc >= 3 && std::string (argv[1]) == "spectrum")
  {
    try
    {
      return spectrum_command (std::vector<std::string> (argv + 2, argv + argc));
    }
    catch (const InputError &e)
    {
      if (root)
        std::cerr << "wetbed: error: " << e.what () << std::endl;
      return 2;
    }
  }
  if (argc >= 2 && std::string (argv[1]) == "--print-parameters")
  {
    dealii::ParameterHandler prm;
    Parameters::declare_parameters (prm);
    const bool json = argc == 3 && std::string (argv[2]) == "json";
    if (argc > 2 && !json)
    {
      if (root)
        std::cerr << "wetbed: error: --print-parameters takes no argument or `json`, "
                     "not `"
                  << argv[2] << "`" << std::endl;
      return 2;
    }
    if (root)
      prm.print_parameters (std::cout,
                            json ? dealii::ParameterHandler::JSON
                                 : dealii::ParameterHandler::PRM);
    return 0;
  }
  const bool overwrite = take_flag (argc, argv, "--overwrite");
  const bool resume    = argc == 3 && std::string (argv[2]) == "--resume";
  if (argc != 2 && !resume)
  {
    if (root)
      print_usage (std::cerr);
    return 1;
  }
  const std::string argument = argv[1];
  if (argument == "--help" || argument == "-h")
  {
    if (root)
      print_usage (std::cout);
    return 0;
  }
  try
  {
    dealii::ParameterHandler prm;
    Parameters               parameters = Parameters::read (argument, prm);
    if (resume)
      parameters.checkpoint.resume = true;
    if (overwrite)
      parameters.output.overwrite = true;
    return parameters.dimension == 2 ? run_case<2> (parameters, prm)
                                     : run_case<3> (parameters, prm);
  }
  catch (const InputError &e)
  {
    if (root)
      std::cerr << "wetbed: error: " << e.what () << std::endl;
    return 2;
  }
  catch (const std::exception &e)
  {
    if (root)
      std::cerr << "wetbed: run failed: " << one_line (e.what ()) << std::endl;
    return 3;
  }
  return 0;
}
} // namespace wetbed
