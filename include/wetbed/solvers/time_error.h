#pragma once

#include <deal.II/lac/la_parallel_vector.h>

#include <mpi.h>

namespace wetbed
{
/**
 * The local time-error estimate of a step of alpha_s (doc/theory.md "Time step"): with
 * the predictor alpha^P = alpha^n + (dt/dt_old)(alpha^n - alpha^{n-1}), the linear
 * extrapolation of the last two steps, e_i = dt/(2 dt + dt_old) |alpha^{n+1}_i -
 * alpha^P_i| is the local error of a first-order step, (dt^2/2)|alpha''|, to leading
 * order; the estimate is its RMS weighted with the lumped mass over the nodes that hold
 * solids (alpha_s > 1e-3 before or after the step), 0 when none does. Collective.
 */
double
alpha_time_error (const dealii::LinearAlgebra::distributed::Vector<double> &alpha,
                  const dealii::LinearAlgebra::distributed::Vector<double> &alpha_n,
                  const dealii::LinearAlgebra::distributed::Vector<double> &alpha_nm1,
                  const dealii::LinearAlgebra::distributed::Vector<double> &lumped_mass,
                  double                                                    dt,
                  double                                                    dt_old,
                  MPI_Comm                                                  communicator);
} // namespace wetbed
