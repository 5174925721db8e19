#include <wetbed/solvers/two_fluid_solver.h>

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
void TwoFluidSolver<dim>::flag_cells_for_adaptation ()
{
  const auto   &amr = parameters.adaptive_refinement;
  Vector<float> indicator (triangulation.n_active_cells ());
  {
    const QGauss<dim>           quadrature (2);
    FEValues<dim>               values (mapping, alpha_fe, quadrature, update_gradients);
    std::vector<Tensor<1, dim>> gradients (quadrature.size ());
    const double                alpha_max = parameters.physical.maximum_packing;
    for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
      if (cell->is_locally_owned ())
      {
        values.reinit (cell);
        values.get_function_gradients (alpha, gradients);
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
    KellyErrorEstimator<dim>::estimate (
        mapping, flow_dof_handler, QGauss<dim - 1> (3), {}, flow_solution, kelly, solids);
    const double largest = Utilities::MPI::max (
        static_cast<double> (*std::max_element (kelly.begin (), kelly.end ())),
        communicator);
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
void TwoFluidSolver<dim>::restore_solids_mass (AlphaVector             &a,
                                               const double             target,
                                               const std::vector<bool> &candidate) const
{
  // sum_i m_i a_i is int alpha_h (condensed lumped mass, hanging nodes included)
  const auto  &m         = solids_transport.lumped_mass ();
  const double alpha_max = parameters.physical.maximum_packing;
  const double deficit =
      (target - solids_mass (a)) / parameters.physical.particle_density; // volume
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
    capacity = Utilities::MPI::sum (capacity, communicator);
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
void TwoFluidSolver<dim>::adapt_mesh ()
{
  TimerOutput::Scope scope (timer, "adaptive refinement");
  flag_cells_for_adaptation ();
  triangulation.prepare_coarsening_and_refinement ();

  // the parents of the cells to be coarsened (they will be active, maybe elsewhere)
  std::vector<std::string> coarsened_local;
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned () && cell->coarsen_flag_set () && cell->level () > 0)
      coarsened_local.push_back (cell->parent ()->id ().to_string ());
  std::sort (coarsened_local.begin (), coarsened_local.end ());
  coarsened_local.erase (std::unique (coarsened_local.begin (), coarsened_local.end ()),
                         coarsened_local.end ());
  std::set<std::string> coarsened;
  for (const auto &part : Utilities::MPI::all_gather (communicator, coarsened_local))
    coarsened.insert (part.begin (), part.end ());

  FieldTransfers transfers = attach_fields (false);
  const auto     scalars   = scalar_fields (); // alpha_s^{n+1}, ^n, ^{n-1} first
  double         masses[3];
  for (unsigned int k = 0; k < 3; ++k)
    masses[k] = solids_mass (*scalars[k]);

  bubble_analysis->prepare_for_mesh_change ();
  triangulation.execute_coarsening_and_refinement ();
  setup_dofs ();
  receive_fields (transfers, false);
  bubble_analysis->after_mesh_change ();

  // the nodes of the coarsened cells, where the coarsening deficit is given back
  std::vector<bool>                    candidate (alpha.locally_owned_size (), false);
  std::vector<types::global_dof_index> dofs (alpha_fe.n_dofs_per_cell ());
  const IndexSet                       owned = alpha.locally_owned_elements ();
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
    if (!cell->is_artificial () && coarsened.count (cell->id ().to_string ()))
    {
      cell->get_dof_indices (dofs);
      for (const auto dof : dofs)
        if (owned.is_element (dof))
          candidate[alpha.get_partitioner ()->global_to_local (dof)] = true;
    }
  for (unsigned int k = 0; k < 3; ++k)
    restore_solids_mass (*scalars[k], masses[k], candidate);
}

template <int dim>
void TwoFluidSolver<dim>::connect_load_balancing ()
{
  const Boundaries ids = boundaries;
  cell_weights         = connect_cell_weights<dim> (triangulation,
                                            parameters.mesh.wall_face_weight,
                                            [ids] (const types::boundary_id id)
                                            { return ids.is_wall (id); });
  // a fresh mesh is repartitioned by the weights at once; a mesh loaded from a
  // checkpoint keeps its partition until the next adaptation (repartitioning the loaded
  // forest crashed in deal.II 9.4's p4est transfer)
  if (cell_weights.connected () && Utilities::MPI::n_mpi_processes (communicator) > 1 &&
      !parameters.checkpoint.resume)
    triangulation.repartition ();
}

template void TwoFluidSolver<2>::connect_load_balancing ();
template void TwoFluidSolver<3>::connect_load_balancing ();
template void TwoFluidSolver<2>::adapt_mesh ();
template void TwoFluidSolver<3>::adapt_mesh ();
template void TwoFluidSolver<2>::flag_cells_for_adaptation ();
template void TwoFluidSolver<3>::flag_cells_for_adaptation ();
template void TwoFluidSolver<2>::restore_solids_mass (AlphaVector &,
                                                      double,
                                                      const std::vector<bool> &) const;
template void TwoFluidSolver<3>::restore_solids_mass (AlphaVector &,
                                                      double,
                                                      const std::vector<bool> &) const;
} // namespace wetbed
