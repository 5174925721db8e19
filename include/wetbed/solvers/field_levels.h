#pragma once

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

namespace wetbed
{
/**
 * The unknowns of the two-fluid model (ghosted) at the current iterate and at the two
 * previous time levels t_n and t_{n-1} (BDF2): the flow (u_g, u_s, p') on the Q2/Q1
 * space, alpha_s and the granular temperature Theta (m^2/s^2; zero without kinetic
 * theory) on the Q1 space.
 */
struct FieldLevels
{
  using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  BlockVector flow, flow_old, flow_old2;
  AlphaVector alpha, alpha_old, alpha_old2;
  AlphaVector theta, theta_old, theta_old2;
};
} // namespace wetbed
