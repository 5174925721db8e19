#include <wetbed/solvers/time_error.h>

#include <deal.II/base/mpi.h>

#include <cmath>

namespace wetbed
{
double
alpha_time_error (const dealii::LinearAlgebra::distributed::Vector<double> &alpha,
                  const dealii::LinearAlgebra::distributed::Vector<double> &alpha_n,
                  const dealii::LinearAlgebra::distributed::Vector<double> &alpha_nm1,
                  const dealii::LinearAlgebra::distributed::Vector<double> &lumped_mass,
                  const double                                              dt,
                  const double                                              dt_old,
                  const MPI_Comm                                            communicator)
{
  const double ratio = dt / dt_old, scale = dt / (2 * dt + dt_old);
  double       sums[2] = {0, 0}; // the mass-weighted squared error, the mass
  for (unsigned int i = 0; i < alpha.locally_owned_size (); ++i)
  {
    const double now = alpha.local_element (i), old = alpha_n.local_element (i);
    if (std::max (now, old) <= 1e-3)
      continue;
    const double predicted = old + ratio * (old - alpha_nm1.local_element (i));
    const double error     = scale * (now - predicted);
    sums[0] += lumped_mass.local_element (i) * error * error;
    sums[1] += lumped_mass.local_element (i);
  }
  dealii::Utilities::MPI::sum (dealii::ArrayView<const double> (sums, 2),
                               communicator,
                               dealii::ArrayView<double> (sums, 2));
  return sums[1] > 0 ? std::sqrt (sums[0] / sums[1]) : 0.0;
}
} // namespace wetbed
