#include <wetbed/command_line/application.h>

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <iostream>

int main (int argc, char **argv)
{
  unsigned int threads = 1;
  try
  {
    threads = wetbed::take_threads_option (argc, argv);
  }
  catch (const std::exception &e)
  {
    std::cerr << "wetbed: error: " << e.what () << std::endl;
    return 2;
  }
  // A run started without mpirun is an Open MPI singleton: unless told otherwise it
  // starts a helper daemon (orted) it never uses (wetbed spawns no processes), a third
  // of a serial start-up (1.0 -> 0.65 s). A user's own setting of the variable wins;
  // under mpirun it is not read.
  setenv ("OMPI_MCA_ess_singleton_isolated", "1", 0);
  // Checkpoints write with explicit offsets and need no shared file pointer; Open MPI's
  // shared-memory one ("sm") creates a file beside each file opened and now and then
  // fails doing so (MPI_ERR_OTHER in the triangulation's save, a checkpoint lost and the
  // run stopped, seen under ctest -j2). The others remain; a user's setting wins.
  setenv ("OMPI_MCA_sharedfp", "^sm", 0);
  dealii::Utilities::MPI::MPI_InitFinalize mpi (argc, argv, threads);
  return wetbed::run_application (argc, argv);
}
