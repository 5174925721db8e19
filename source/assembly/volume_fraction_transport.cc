#include <wetbed/assembly/scalar_sparsity.h>
#include <wetbed/assembly/volume_fraction_transport.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>

namespace wetbed
{
template <int dim>
void VolumeFractionTransport<dim>::setup (
    const dealii::DoFHandler<dim>           &dof_handler,
    const dealii::Mapping<dim>              &mapping,
    const dealii::AffineConstraints<double> &hanging_node_constraints,
    const Vector                            &layout)
{
  using namespace dealii;
  const MPI_Comm  comm     = dof_handler.get_triangulation ().get_communicator ();
  const IndexSet &owned    = dof_handler.locally_owned_dofs ();
  const IndexSet  relevant = DoFTools::extract_locally_relevant_dofs (dof_handler);
  const DynamicSparsityPattern dsp =
      distributed_scalar_sparsity (dof_handler, hanging_node_constraints);

  this->dof_handler = &dof_handler;
  this->mapping     = &mapping;
  constraints       = &hanging_node_constraints;
  convection.reinit (owned, owned, dsp, comm);
  convection_transpose.reinit (owned, owned, dsp, comm);
  IndexSet columns (dof_handler.n_dofs ());
  for (const auto row : owned)
  {
    std::vector<types::global_dof_index> row_columns;
    for (auto it = dsp.begin (row); it != dsp.end (row); ++it)
      row_columns.push_back (it->column ());
    columns.add_indices (row_columns.begin (), row_columns.end ());
  }
  columns.add_indices (relevant);
  work.reinit (owned, columns, comm);
  work_x.reinit (work);
  mass.reinit (work);
  scratch_low.reinit (work);
  scratch_plus.reinit (work);
  scratch_minus.reinit (work);
  Vector condensed_mass;
  condensed_mass.reinit (layout); // the layout only: zero entries, whatever layout holds

  const QGauss<dim> quadrature (dof_handler.get_fe ().degree + 1);
  FEValues<dim>     fe_values (
      mapping, dof_handler.get_fe (), quadrature, update_values | update_JxW_values);
  const unsigned int                   n = dof_handler.get_fe ().n_dofs_per_cell ();
  std::vector<types::global_dof_index> dofs (n);
  dealii::Vector<double>               cell_mass (n);
  for (const auto &cell : dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      fe_values.reinit (cell);
      cell->get_dof_indices (dofs);
      cell_mass = 0;
      for (unsigned int q = 0; q < quadrature.size (); ++q)
        for (unsigned int i = 0; i < n; ++i)
          cell_mass (i) += fe_values.shape_value (i, q) * fe_values.JxW (q);
      hanging_node_constraints.distribute_local_to_global (
          cell_mass, dofs, condensed_mass);
    }
  condensed_mass.compress (VectorOperation::add);
  mass.copy_locally_owned_data_from (condensed_mass);
  mass.update_ghost_values ();

  const auto &partitioner = *work.get_partitioner ();
  rows.assign (owned.n_elements (), Row ());
  constrained.assign (owned.n_elements (), false);
  unsigned int local_row = 0;
  for (const auto global_row : owned)
  {
    constrained[local_row] = hanging_node_constraints.is_constrained (global_row);
    Row &row               = rows[local_row++];
    if (constrained[local_row - 1])
      continue; // a hanging node: no equation, its value follows its parents
    for (auto it = convection.begin (global_row); it != convection.end (global_row); ++it)
      row.columns.push_back (partitioner.global_to_local (it->column ()));
    row.k.assign (row.columns.size (), 0.0);
    row.kt.assign (row.columns.size (), 0.0);
  }
}

template <int dim>
void VolumeFractionTransport<dim>::set_velocity (const VelocityAtQuadrature &velocity)
{
  using namespace dealii;
  convection           = 0;
  convection_transpose = 0;
  // phi_j (Q1) u (Q2) grad phi_i (Q1) is of degree 3 per direction: 3 Gauss points
  const QGauss<dim>                    quadrature (dof_handler->get_fe ().degree + 2);
  FEValues<dim>                        fe_values (*mapping,
                           dof_handler->get_fe (),
                           quadrature,
                           update_values | update_gradients | update_JxW_values |
                               update_quadrature_points);
  const unsigned int                   n = dof_handler->get_fe ().n_dofs_per_cell ();
  std::vector<types::global_dof_index> dofs (n);
  std::vector<Tensor<1, dim>>          u (quadrature.size ());
  FullMatrix<double>                   cell_k (n, n), cell_kt (n, n);
  for (const auto &cell : dof_handler->active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      fe_values.reinit (cell);
      cell->get_dof_indices (dofs);
      velocity (cell, fe_values, u);
      cell_k = 0;
      for (unsigned int q = 0; q < quadrature.size (); ++q)
        for (unsigned int i = 0; i < n; ++i)
        {
          const double advective_derivative =
              (u[q] * fe_values.shape_grad (i, q)) * fe_values.JxW (q);
          for (unsigned int j = 0; j < n; ++j)
            cell_k (i, j) += fe_values.shape_value (j, q) * advective_derivative;
        }
      cell_kt.copy_transposed (cell_k);
      constraints->distribute_local_to_global (cell_k, dofs, convection);
      constraints->distribute_local_to_global (cell_kt, dofs, convection_transpose);
    }
  convection.compress (VectorOperation::add);
  convection_transpose.compress (VectorOperation::add);
  // the rows in Epetra's storage order, the order setup() recorded the columns in (both
  // matrices share one sparsity pattern); Epetra's local rows are the owned DoFs in order
  const Epetra_CrsMatrix &k  = convection.trilinos_matrix ();
  const Epetra_CrsMatrix &kt = convection_transpose.trilinos_matrix ();
  for (unsigned int i = 0; i < rows.size (); ++i)
  {
    Row &row = rows[i];
    if (row.columns.empty ())
      continue;
    int     n = 0, n_t = 0;
    double *values = nullptr, *values_t = nullptr;
    int    *columns = nullptr, *columns_t = nullptr;
    k.ExtractMyRowView (i, n, values, columns);
    kt.ExtractMyRowView (i, n_t, values_t, columns_t);
    AssertThrow (static_cast<std::size_t> (n) == row.columns.size () && n_t == n,
                 dealii::ExcInternalError ());
    std::copy (values, values + n, row.k.begin ());
    std::copy (values_t, values_t + n, row.kt.begin ());
  }
}

template <int dim>
void VolumeFractionTransport<dim>::load (const Vector &alpha_out)
{
  work.copy_locally_owned_data_from (alpha_out);
  work.update_ghost_values ();
}

template <int dim>
void VolumeFractionTransport<dim>::store (Vector &alpha_out) const
{
  alpha_out.zero_out_ghost_values ();
  alpha_out.copy_locally_owned_data_from (work);
  constraints->distribute (alpha_out); // hanging nodes: convex combinations of parents
  alpha_out.update_ghost_values ();
}

template <int dim>
double VolumeFractionTransport<dim>::artificial_diffusion (EdgeValues &diffusion) const
{
  const unsigned int n_owned   = rows.size ();
  double             stable_dt = std::numeric_limits<double>::max ();
  for (unsigned int i = 0; i < n_owned; ++i)
  {
    const Row &row = rows[i];
    const auto m   = row.columns.size ();
    diffusion[i].resize (m);
    if (constrained[i])
      continue;
    double diagonal = 0, off_diagonal_sum = 0;
    for (unsigned int e = 0; e < m; ++e)
    {
      const unsigned int j   = row.columns[e];
      const double       kij = row.k[e], kji = row.kt[e];
      if (j == i)
        diagonal = kij;
      else
      {
        diffusion[i][e] = std::max ({-kij, 0.0, -kji});
        off_diagonal_sum += diffusion[i][e];
      }
    }
    const double rate = off_diagonal_sum - diagonal;
    if (rate > 0)
      stable_dt = std::min (stable_dt, mass.local_element (i) / rate);
  }
  return stable_dt;
}

template <int dim>
void VolumeFractionTransport<dim>::low_order_step (const Vector     &alpha,
                                                   const EdgeValues &diffusion,
                                                   const double      tau,
                                                   EdgeValues       &low_flux,
                                                   Vector           &low) const
{
  // low-order update written as antisymmetric edge fluxes
  //   F^L_ij = k_ij a_j - k_ji a_i + d_ij (a_j - a_i)   (sum_j k_ji = 0)
  for (unsigned int i = 0; i < rows.size (); ++i)
  {
    const Row   &row = rows[i];
    const double a_i = alpha.local_element (i);
    low_flux[i].assign (row.columns.size (), 0.0);
    if (constrained[i])
    {
      low.local_element (i) = a_i;
      continue;
    }
    double change = 0;
    for (unsigned int e = 0; e < row.columns.size (); ++e)
    {
      const unsigned int j = row.columns[e];
      if (j == i)
        continue;
      const double a_j = alpha.local_element (j);
      const double f =
          tau * (row.k[e] * a_j - row.kt[e] * a_i + diffusion[i][e] * (a_j - a_i));
      low_flux[i][e] = f;
      change += f;
    }
    low.local_element (i) = a_i + change / mass.local_element (i);
  }
}

template <int dim>
void VolumeFractionTransport<dim>::antidiffusive_fluxes (const Vector     &alpha,
                                                         const Vector     &low,
                                                         const EdgeValues &diffusion,
                                                         const double      tau,
                                                         const double      alpha_max,
                                                         EdgeValues       &flux,
                                                         Vector           &r_plus,
                                                         Vector           &r_minus) const
{
  // antidiffusive fluxes (mass-lumping part neglected), prelimited, and Zalesak sums
  for (unsigned int i = 0; i < rows.size (); ++i)
  {
    const Row &row = rows[i];
    flux[i].assign (row.columns.size (), 0.0);
    double p_plus = 0, p_minus = 0;
    double upper = std::max (low.local_element (i), alpha.local_element (i));
    double lower = std::min (low.local_element (i), alpha.local_element (i));
    for (unsigned int e = 0; e < row.columns.size (); ++e)
    {
      const unsigned int j = row.columns[e];
      upper = std::max ({upper, low.local_element (j), alpha.local_element (j)});
      lower = std::min ({lower, low.local_element (j), alpha.local_element (j)});
      if (j == i)
        continue;
      double f =
          tau * diffusion[i][e] * (alpha.local_element (i) - alpha.local_element (j));
      if (f * (low.local_element (i) - low.local_element (j)) < 0)
        f = 0; // prelimiting: no flux against the low-order gradient
      flux[i][e] = f;
      p_plus += std::max (f, 0.0);
      p_minus += std::min (f, 0.0);
    }
    upper                = std::max (std::min (upper, alpha_max), low.local_element (i));
    lower                = std::min (std::max (lower, 0.0), low.local_element (i));
    const double m       = constrained[i] ? 1.0 : mass.local_element (i);
    const double q_plus  = m * (upper - low.local_element (i));
    const double q_minus = m * (lower - low.local_element (i));
    r_plus.local_element (i)  = p_plus > 0 ? std::min (1.0, q_plus / p_plus) : 1.0;
    r_minus.local_element (i) = p_minus < 0 ? std::min (1.0, q_minus / p_minus) : 1.0;
  }
}

template <int dim>
void VolumeFractionTransport<dim>::limit_antidiffusive_fluxes (const EdgeValues &low_flux,
                                                               const Vector     &r_plus,
                                                               const Vector     &r_minus,
                                                               EdgeValues       &flux,
                                                               double           &removed,
                                                               double &total) const
{
  // total edge flux G_ij = F^L_ij + l_ij f_ij
  for (unsigned int i = 0; i < rows.size (); ++i)
  {
    const Row &row = rows[i];
    for (unsigned int e = 0; e < row.columns.size (); ++e)
    {
      const unsigned int j       = row.columns[e];
      const double       f       = flux[i][e];
      double             limited = 0;
      if (f != 0)
      {
        const double l =
            f > 0 ? std::min (r_plus.local_element (i), r_minus.local_element (j))
                  : std::min (r_minus.local_element (i), r_plus.local_element (j));
        limited = l * f;
        removed += (1 - l) * std::abs (f);
        total += std::abs (f);
      }
      flux[i][e] = low_flux[i][e] + limited;
    }
  }
}

template <int dim>
unsigned int VolumeFractionTransport<dim>::advance (Vector      &alpha_out,
                                                    const double dt,
                                                    const double cfl,
                                                    const double alpha_max)
{
  load (alpha_out);
  Vector            &alpha   = work;
  const unsigned int n_owned = rows.size ();
  EdgeValues         diffusion (n_owned);
  const double stable_dt = dealii::Utilities::MPI::min (artificial_diffusion (diffusion),
                                                        alpha.get_mpi_communicator ());
  // NaN or a vanishing stable sub-step: infinitely many sub-steps (the cast of a count
  // beyond unsigned int would be undefined, hence the test in double first)
  last_required_sub_steps =
      stable_dt > 0 ? dt / (cfl * stable_dt) : std::numeric_limits<double>::infinity ();
  if (!(last_required_sub_steps <= max_sub_steps))
    return dealii::numbers::invalid_unsigned_int;
  const unsigned int n_sub =
      std::max (1u, static_cast<unsigned int> (std::ceil (last_required_sub_steps)));
  const double tau = dt / n_sub;

  Vector &low = scratch_low, &r_plus = scratch_plus, &r_minus = scratch_minus;
  // per edge: low-order flux F^L_ij (into i), antidiffusive flux f_ij, then their sum
  EdgeValues low_flux (n_owned), flux (n_owned);
  double     removed = 0, total = 0;
  bound_activity = 0;
  inflow_volume  = 0;
  for (unsigned int sub = 0; sub < n_sub; ++sub)
  {
    alpha.update_ghost_values ();
    low_order_step (alpha, diffusion, tau, low_flux, low);
    low.update_ghost_values ();
    antidiffusive_fluxes (alpha, low, diffusion, tau, alpha_max, flux, r_plus, r_minus);
    r_plus.update_ghost_values ();
    r_minus.update_ghost_values ();
    limit_antidiffusive_fluxes (low_flux, r_plus, r_minus, flux, removed, total);
    // global bounds [0, alpha_max]: low-order compression into a packed node is
    // blocked here, the discrete counterpart of the packing limit
    bound_activity += limit_to_bounds (alpha, flux, alpha_max);
    if (inflow_rates.size () > 0)
      inflow_volume += add_inflow (alpha, tau, alpha_max);
  }
  alpha.update_ghost_values ();
  const MPI_Comm comm = alpha.get_mpi_communicator ();
  removed             = dealii::Utilities::MPI::sum (removed, comm);
  total               = dealii::Utilities::MPI::sum (total, comm);
  limiter_activity    = total > 0 ? removed / total : 0.0;
  bound_activity      = dealii::Utilities::MPI::sum (bound_activity, comm);
  inflow_volume       = dealii::Utilities::MPI::sum (inflow_volume, comm);
  store (alpha_out);
  return n_sub;
}

template <int dim>
double VolumeFractionTransport<dim>::limit_to_bounds (
    Vector &alpha, const std::vector<std::vector<double>> &flux, const double alpha_max)
{
  // Zalesak's limiter with Q from the current state and the global bounds only:
  // total fluxes into a node never lift it above alpha_max, out of it never below 0.
  // l_ij = l_ji, so the update stays exactly conservative.
  const unsigned int n_owned = rows.size ();
  Vector            &r_plus = scratch_plus, &r_minus = scratch_minus;
  for (unsigned int i = 0; i < n_owned; ++i)
  {
    double p_plus = 0, p_minus = 0;
    for (const double g : flux[i])
    {
      p_plus += std::max (g, 0.0);
      p_minus += std::min (g, 0.0);
    }
    const double m            = constrained[i] ? 1.0 : mass.local_element (i);
    const double q_plus       = m * std::max (alpha_max - alpha.local_element (i), 0.0);
    const double q_minus      = m * std::min (-alpha.local_element (i), 0.0);
    r_plus.local_element (i)  = p_plus > q_plus ? q_plus / p_plus : 1.0;
    r_minus.local_element (i) = p_minus < q_minus ? q_minus / p_minus : 1.0;
  }
  r_plus.update_ghost_values ();
  r_minus.update_ghost_values ();
  double              held_back = 0;
  std::vector<double> updated (n_owned);
  for (unsigned int i = 0; i < n_owned; ++i)
  {
    const Row &row = rows[i];
    double     sum = 0;
    for (unsigned int e = 0; e < row.columns.size (); ++e)
    {
      const unsigned int j = row.columns[e];
      const double       g = flux[i][e];
      if (g == 0 || j == i)
        continue;
      const double l =
          g > 0 ? std::min (r_plus.local_element (i), r_minus.local_element (j))
                : std::min (r_minus.local_element (i), r_plus.local_element (j));
      sum += l * g;
      held_back += (1 - l) * std::abs (g);
    }
    updated[i] =
        alpha.local_element (i) + (constrained[i] ? 0.0 : sum / mass.local_element (i));
  }
  for (unsigned int i = 0; i < n_owned; ++i)
    alpha.local_element (i) = updated[i];
  alpha.update_ghost_values ();
  return held_back;
}

template <int dim>
double VolumeFractionTransport<dim>::add_inflow (Vector      &alpha,
                                                 const double tau,
                                                 const double alpha_max) const
{
  // the feed's boundary flux int phi_i alpha_in u_in.(-n) ds, the term the conservative
  // operator leaves out (it has no boundary flux): a source at the inlet nodes
  double added = 0;
  for (unsigned int i = 0; i < rows.size (); ++i)
  {
    const double rate = inflow_rates.local_element (i);
    if (rate <= 0 || constrained[i])
      continue;
    const double m          = mass.local_element (i);
    const double a          = alpha.local_element (i);
    const double after      = std::min (a + tau * rate / m, std::max (alpha_max, a));
    alpha.local_element (i) = after;
    added += m * (after - a);
  }
  return added;
}

template <int dim>
double VolumeFractionTransport<dim>::apply_diffusive_fluxes (
    Vector                                       &alpha_out,
    const dealii::TrilinosWrappers::SparseMatrix &A,
    const Vector                                 &x_in,
    const double                                  alpha_max)
{
  load (alpha_out);
  Vector &alpha = work, &x = work_x;
  x.copy_locally_owned_data_from (x_in);
  x.update_ghost_values ();
  const auto                      &partitioner = *alpha.get_partitioner ();
  const unsigned int               n_owned     = rows.size ();
  std::vector<std::vector<double>> flux (n_owned);
  const Epetra_CrsMatrix          &a = A.trilinos_matrix ();
  for (unsigned int i = 0; i < n_owned; ++i)
  {
    const Row &row = rows[i];
    flux[i].assign (row.columns.size (), 0.0);
    if (constrained[i])
      continue;
    // Epetra's local row i is the i-th owned DoF; its columns are local to A's column map
    int     n       = 0;
    double *values  = nullptr;
    int    *columns = nullptr;
    a.ExtractMyRowView (i, n, values, columns);
    for (int e = 0; e < n; ++e)
    {
      const unsigned int j = partitioner.global_to_local (
          dealii::TrilinosWrappers::global_index (a.ColMap (), columns[e]));
      if (j == i)
        continue;
      const auto position = std::find (row.columns.begin (), row.columns.end (), j);
      Assert (position != row.columns.end (), dealii::ExcInternalError ());
      flux[i][position - row.columns.begin ()] =
          -values[e] * (x.local_element (j) - x.local_element (i));
    }
  }
  const double held_back = limit_to_bounds (alpha, flux, alpha_max);
  store (alpha_out);
  return dealii::Utilities::MPI::sum (held_back, alpha.get_mpi_communicator ());
}

template class VolumeFractionTransport<2>;
template class VolumeFractionTransport<3>;
} // namespace wetbed
