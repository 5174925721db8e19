#include <wetbed/solvers/mesh_adaptation.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/error_estimator.h>

#include <algorithm>
#include <set>

/*
 * Bubble-following adaptive refinement. The indicator of a cell K is
 *   eta_K = h_K max_K |grad alpha_s| / alpha_max + w eta_Kelly,K(u_s) / max eta_Kelly
 * (the jump of alpha_s across the cell, large at gas-emulsion interfaces and zero in
 * the freeboard and a uniform emulsion, plus a Kelly term that follows the solids
 * shear); cells above `refine threshold` are refined and cells below `coarsen
 * threshold` coarsened within [minimum level, maximum level] (cells below the minimum
 * level, as on a mesh that starts coarser, are refined). Cells in the
 * distributor band (a vertex below `distributor band height`) go to the maximum level
 * whatever their indicator: bubbles are born there.
 *
 * Every field and both BDF history levels move with parallel SolutionTransfer. On Q1,
 * refinement interpolates exactly; coarsening injects the parent's vertex values and
 * loses sum(m alpha) = int alpha_h where alpha_h was not linear over the children. That
 * deficit is given back on the nodes of the coarsened cells, in proportion to each
 * node's room below alpha_max (or above 0 when mass must go), so the solids mass is
 * conserved to round-off and 0 <= alpha_s <= alpha_max still holds.
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
void MeshAdaptation<dim>::flag_cells (
    const SolverState<dim>                    &s,
    parallel::distributed::Triangulation<dim> &triangulation) const
{
  const auto   &amr = parameters.adaptive_refinement;
  Vector<float> indicator (triangulation.n_active_cells ());
  {
    const QGauss<dim> quadrature (2);
    FEValues<dim>     values (s.mapping, s.alpha_fe, quadrature, update_gradients);
    std::vector<Tensor<1, dim>> gradients (quadrature.size ());
    const double                alpha_max = parameters.physical.maximum_packing;
    for (const auto &cell : s.alpha_dof_handler.active_cell_iterators ())
      if (cell->is_locally_owned ())
      {
        values.reinit (cell);
        values.get_function_gradients (s.alpha, gradients);
        double largest = 0;
        for (const auto &g : gradients)
          largest = std::max (largest, g.norm ());
        indicator (cell->active_cell_index ()) = cell->diameter () * largest / alpha_max;
      }
  }
  if (amr.velocity_weight > 0)
  {
    Vector<float> kelly (triangulation.n_active_cells ());
    ComponentMask solids (2 * dim + 1, false);
    for (unsigned int d = 0; d < dim; ++d)
      solids.set (dim + d, true);
    KellyErrorEstimator<dim>::estimate (s.mapping,
                                        s.flow_dof_handler,
                                        QGauss<dim - 1> (3),
                                        {},
                                        s.flow_solution,
                                        kelly,
                                        solids);
    const double largest = Utilities::MPI::max (
        static_cast<double> (*std::max_element (kelly.begin (), kelly.end ())),
        s.communicator);
    if (largest > 0)
      for (unsigned int k = 0; k < kelly.size (); ++k)
        indicator (k) += amr.velocity_weight * kelly (k) / largest;
  }
  // the distributor band: cells with a vertex below its height are held at the
  // maximum level (refined whatever their indicator, never coarsened)
  const Tensor<1, dim> up      = upward_direction<dim> (parameters.physical.gravity);
  auto                 in_band = [&] (const auto &cell)
  {
    if (amr.distributor_band_height <= 0)
      return false;
    for (const unsigned int v : cell->vertex_indices ())
      if (cell->vertex (v) * up < amr.distributor_band_height)
        return true;
    return false;
  };
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      const double eta = indicator (cell->active_cell_index ());
      // below the minimum level or in the band: refined whatever the indicator
      const bool banded = in_band (cell);
      const bool forced = banded || cell->level () < static_cast<int> (amr.minimum_level);
      if ((eta > amr.refine_threshold || forced) &&
          cell->level () < static_cast<int> (amr.maximum_level))
        cell->set_refine_flag ();
      else if (eta < amr.coarsen_threshold && !banded &&
               cell->level () > static_cast<int> (amr.minimum_level))
        cell->set_coarsen_flag ();
    }
}

template <int dim>
void MeshAdaptation<dim>::restore (const SolverState<dim>          &s,
                                   const AffineConstraints<double> &alpha_constraints,
                                   AlphaVector                     &a,
                                   const double                     target,
                                   const std::vector<bool>         &candidate) const
{
  // sum_i m_i a_i is int alpha_h (condensed lumped mass, hanging nodes included)
  const auto  &m         = s.lumped_mass;
  const double alpha_max = parameters.physical.maximum_packing;
  const double deficit =
      (target - s.solids_mass (a)) / parameters.physical.particle_density; // volume
  // room: below alpha_max to add mass, above 0 to remove it; on the coarsened cells'
  // nodes, or everywhere if they cannot take it (with any room at all)
  auto room = [&] (const unsigned int i)
  {
    if (alpha_constraints.is_constrained (a.get_partitioner ()->local_to_global (i)))
      return 0.0;
    return deficit > 0 ? std::max (alpha_max - a.local_element (i), 0.0)
                       : std::max (a.local_element (i), 0.0);
  };
  for (const bool restrict_to_candidates : {true, false})
  {
    double capacity = 0;
    for (unsigned int i = 0; i < a.locally_owned_size (); ++i)
      if (!restrict_to_candidates || candidate[i])
        capacity += m.local_element (i) * room (i);
    capacity = Utilities::MPI::sum (capacity, s.communicator);
    if (capacity <= 2.0 * std::abs (deficit) && restrict_to_candidates)
      continue;
    if (capacity <= 0)
      break;
    const double share = std::min (std::abs (deficit) / capacity, 1.0);
    for (unsigned int i = 0; i < a.locally_owned_size (); ++i)
      if (!restrict_to_candidates || candidate[i])
        a.local_element (i) += (deficit > 0 ? share : -share) * room (i);
    break;
  }
  a.zero_out_ghost_values ();
  alpha_constraints.distribute (a);
  a.update_ghost_values ();
}

template <int dim>
MeshAdaptation<dim>::MeshAdaptation (const Parameters &parameters)
    : parameters (parameters)
{
}

template <int dim>
void MeshAdaptation<dim>::prepare (
    const SolverState<dim>                    &s,
    parallel::distributed::Triangulation<dim> &triangulation,
    const std::vector<const AlphaVector *>    &alpha_levels)
{
  flag_cells (s, triangulation);
  triangulation.prepare_coarsening_and_refinement ();

  // the parents of the cells to be coarsened (they will be active, maybe elsewhere)
  std::vector<std::string> coarsened_local;
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned () && cell->coarsen_flag_set () && cell->level () > 0)
      coarsened_local.push_back (cell->parent ()->id ().to_string ());
  std::sort (coarsened_local.begin (), coarsened_local.end ());
  coarsened_local.erase (std::unique (coarsened_local.begin (), coarsened_local.end ()),
                         coarsened_local.end ());
  coarsened.clear ();
  for (const auto &part : Utilities::MPI::all_gather (s.communicator, coarsened_local))
    coarsened.insert (part.begin (), part.end ());
  masses.clear ();
  for (const AlphaVector *a : alpha_levels)
    masses.push_back (s.solids_mass (*a));
}

template <int dim>
void MeshAdaptation<dim>::restore_solids_mass (
    const SolverState<dim>           &s,
    const AffineConstraints<double>  &alpha_constraints,
    const std::vector<AlphaVector *> &alpha_levels) const
{
  // the nodes of the coarsened cells, where the coarsening deficit is given back
  const AlphaVector                   &alpha = *alpha_levels[0];
  std::vector<bool>                    candidate (alpha.locally_owned_size (), false);
  std::vector<types::global_dof_index> dofs (s.alpha_fe.n_dofs_per_cell ());
  const IndexSet                       owned = alpha.locally_owned_elements ();
  for (const auto &cell : s.alpha_dof_handler.active_cell_iterators ())
    if (!cell->is_artificial () && coarsened.count (cell->id ().to_string ()))
    {
      cell->get_dof_indices (dofs);
      for (const auto dof : dofs)
        if (owned.is_element (dof))
          candidate[alpha.get_partitioner ()->global_to_local (dof)] = true;
    }
  for (unsigned int k = 0; k < alpha_levels.size (); ++k)
    restore (s, alpha_constraints, *alpha_levels[k], masses[k], candidate);
}

template class MeshAdaptation<2>;
template class MeshAdaptation<3>;
} // namespace wetbed
