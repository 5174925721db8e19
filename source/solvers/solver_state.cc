#include <wetbed/solvers/solver_state.h>

#include <deal.II/base/mpi.h>

namespace wetbed
{
template <int dim>
double SolverState<dim>::solids_mass (const AlphaVector &a) const
{
  double sum = 0;
  for (unsigned int i = 0; i < a.locally_owned_size (); ++i)
    sum += lumped_mass.local_element (i) * a.local_element (i);
  return dealii::Utilities::MPI::sum (sum, communicator) *
         parameters.physical.particle_density;
}

template struct SolverState<2>;
template struct SolverState<3>;
} // namespace wetbed
