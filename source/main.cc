#include <wetbed/core/application.h>

#include <deal.II/base/mpi.h>

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
  dealii::Utilities::MPI::MPI_InitFinalize mpi (argc, argv, threads);
  return wetbed::run_application (argc, argv);
}
