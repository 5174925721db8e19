#include <wetbed/core/application.h>

#include <deal.II/base/mpi.h>

int main (int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi (argc, argv, 1);
  return wetbed::run_application (argc, argv);
}
