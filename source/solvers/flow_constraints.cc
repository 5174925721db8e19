#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

namespace wetbed
{
using namespace dealii;

namespace
{
/** `function` on every boundary id of `ids` (nothing if `ids` is empty). */
template <int dim>
void interpolate_on (const Mapping<dim>                 &mapping,
                     const DoFHandler<dim>              &dof_handler,
                     const std::set<types::boundary_id> &ids,
                     const Function<dim>                &function,
                     AffineConstraints<double>          &constraints,
                     const ComponentMask                &mask)
{
  if (ids.empty ())
    return;
  std::map<types::boundary_id, const Function<dim> *> functions;
  for (const auto id : ids)
    functions[id] = &function;
  VectorTools::interpolate_boundary_values (
      mapping, dof_handler, functions, constraints, mask);
}
} // namespace

/**
 * Constraints of the flow system at time `at_time`: hanging nodes; slip walls (strong
 * no-normal-flux unless Nitsche imposes it in the assembly) or no-slip walls; a held
 * solids velocity; the inlet gas velocity U(t)/alpha_g against gravity with solids held
 * at the distributor and retained at the outlet; in a verification run the exact
 * velocities of its hook. And the Schur preconditioner's pressure pinned on the outlet.
 */
template <int dim>
void TwoFluidSolver<dim>::make_flow_constraints (const double at_time)
{
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs (flow_dof_handler);
  const auto    &ids      = boundaries;
  const auto    &bc       = parameters.boundary;
  const ComponentMask solids_mask =
      flow_fe.component_mask (FEValuesExtractors::Vector (dim));

  verification->set_time (at_time); // the step's exact boundary values and sources
  flow_constraints.clear ();
  flow_constraints.reinit (relevant);
  make_mesh_constraints (flow_dof_handler, flow_constraints);

  const Function<dim> *exact_flow = verification->exact_flow ();
  if (exact_flow && verification->walls_keep_conditions ())
    constrain_walls ();
  if (exact_flow)
  {
    // verification: exact velocities on the inlet and (unless the walls keep their
    // conditions) the walls, traction on the outlet
    const Function<dim> &exact = *exact_flow;
    ComponentMask        velocities (2 * dim + 1, true);
    velocities.set (2 * dim, false);
    if (!verification->walls_keep_conditions ())
      interpolate_on (mapping,
                      flow_dof_handler,
                      ids.ids (BoundaryType::wall),
                      exact,
                      flow_constraints,
                      velocities);
    interpolate_on (mapping,
                    flow_dof_handler,
                    ids.ids (BoundaryType::inlet),
                    exact,
                    flow_constraints,
                    velocities);
  }
  else
  {
    if (bc.hold_solids)
      constrain_held_solids (at_time);
    // walls first: their constraints take precedence at the corners
    constrain_walls ();
    constrain_inlet_gas (at_time);
    // solids are held at the distributor (or enter at a feed's velocity) and retained
    // at the outlet (a grid)
    std::set<types::boundary_id> held = ids.ids (BoundaryType::outlet);
    for (const auto id : ids.ids (BoundaryType::inlet))
      if (!inlets.feeds_solids (id))
        held.insert (id);
      else
      {
        Vector<double>       feed (2 * dim + 1);
        const Tensor<1, dim> u = inlets.solids_velocity (id);
        for (unsigned int d = 0; d < dim; ++d)
          feed[dim + d] = u[d];
        interpolate_on (mapping,
                        flow_dof_handler,
                        {id},
                        Functions::ConstantFunction<dim> (feed),
                        flow_constraints,
                        solids_mask);
      }
    interpolate_on (mapping,
                    flow_dof_handler,
                    held,
                    Functions::ZeroFunction<dim> (2 * dim + 1),
                    flow_constraints,
                    solids_mask);
  }
  const types::global_dof_index pinned = pin_pressure (relevant);
  flow_constraints.close ();
  make_schur_constraints (relevant, pinned);
}

template <int dim>
void TwoFluidSolver<dim>::constrain_walls ()
{
  const auto         &ids      = boundaries;
  const auto         &bc       = parameters.boundary;
  const ComponentMask gas_mask = flow_fe.component_mask (FEValuesExtractors::Vector (0));
  const ComponentMask solids_mask =
      flow_fe.component_mask (FEValuesExtractors::Vector (dim));
  // the moving wall's velocity for both phases, (u_w, u_w, 0)
  Vector<double>       wall_motion (2 * dim + 1);
  const Tensor<1, dim> wall_velocity = moving_wall_velocity ();
  for (unsigned int d = 0; d < dim; ++d)
    wall_motion[d] = wall_motion[dim + d] = wall_velocity[d];
  // per phase: the walls of a prescribed velocity (no slip) as constraints, on the
  // others no penetration as constraints unless Nitsche imposes it in the assembly
  auto wall = [&] (const Phase phase, const ComponentMask &mask)
  {
    const auto prescribed = wall_conditions.walls (
        phase, [] (const WallCondition &c) { return c.prescribes_velocity (); });
    const auto slipping = wall_conditions.walls (
        phase, [] (const WallCondition &c) { return !c.prescribes_velocity (); });
    std::set<types::boundary_id> fixed, moving;
    for (const auto id : prescribed)
      (ids.is (id, BoundaryType::moving_wall) ? moving : fixed).insert (id);
    interpolate_on (mapping,
                    flow_dof_handler,
                    fixed,
                    Functions::ZeroFunction<dim> (2 * dim + 1),
                    flow_constraints,
                    mask);
    interpolate_on (mapping,
                    flow_dof_handler,
                    moving,
                    Functions::ConstantFunction<dim> (wall_motion),
                    flow_constraints,
                    mask);
    if (!bc.nitsche && !slipping.empty ())
      VectorTools::compute_no_normal_flux_constraints (flow_dof_handler,
                                                       phase == Phase::gas ? 0 : dim,
                                                       slipping,
                                                       flow_constraints,
                                                       mapping);
  };
  wall (Phase::solids, solids_mask);
  wall (Phase::gas, gas_mask);
}

template <int dim>
void TwoFluidSolver<dim>::constrain_held_solids (const double at_time)
{
  // every solids dof on owned and ghost cells, at the held velocity u_s(x, t)
  held_velocity_function.set_time (at_time);
  const Quadrature<dim> nodes (flow_fe.get_unit_support_points ());
  FEValues<dim>         node_values (mapping, flow_fe, nodes, update_quadrature_points);
  std::vector<types::global_dof_index> dofs (flow_fe.n_dofs_per_cell ());
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned () || cell->is_ghost ())
    {
      cell->get_dof_indices (dofs);
      node_values.reinit (cell);
      for (unsigned int i = 0; i < dofs.size (); ++i)
      {
        const unsigned int c = flow_fe.system_to_component_index (i).first;
        if (c < dim || c >= 2 * dim || flow_constraints.is_constrained (dofs[i]))
          continue;
        Point<3> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = node_values.quadrature_point (i)[d];
        flow_constraints.add_line (dofs[i]);
        flow_constraints.set_inhomogeneity (dofs[i],
                                            held_velocity_function.value (x, c - dim));
      }
    }
}

template <int dim>
void TwoFluidSolver<dim>::constrain_inlet_gas (const double at_time)
{
  // the gas enters with the superficial velocity U of its group, i.e. at U/alpha_g with
  // the local gas fraction at each node, so the volume flux is U whatever bed sits on
  // the distributor
  const Quadrature<dim> nodes (flow_fe.get_unit_support_points ());
  FEValues<dim>         alpha_at_nodes (
      mapping, alpha_fe, nodes, update_values | update_quadrature_points);
  std::vector<double>                  alpha_values (nodes.size ());
  std::vector<types::global_dof_index> dofs (flow_fe.n_dofs_per_cell ());
  auto                                 alpha_cell = alpha_dof_handler.begin_active ();
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
  {
    if ((cell->is_locally_owned () || cell->is_ghost ()) && cell->at_boundary ())
      for (const unsigned int f : cell->face_indices ())
        if (cell->face (f)->at_boundary () &&
            boundaries.is (cell->face (f)->boundary_id (), BoundaryType::inlet))
        {
          alpha_at_nodes.reinit (alpha_cell);
          alpha_at_nodes.get_function_values (fields.alpha, alpha_values);
          cell->get_dof_indices (dofs);
          for (unsigned int i = 0; i < dofs.size (); ++i)
          {
            const unsigned int c = flow_fe.system_to_component_index (i).first;
            if (c >= dim || !flow_fe.has_support_on_face (i, f) ||
                flow_constraints.is_constrained (dofs[i]))
              continue;
            const Tensor<1, dim> U =
                inlets.superficial_velocity (cell->face (f)->boundary_id (),
                                             alpha_at_nodes.quadrature_point (i),
                                             at_time);
            flow_constraints.add_line (dofs[i]);
            flow_constraints.set_inhomogeneity (dofs[i], U[c] / (1.0 - alpha_values[i]));
          }
        }
    ++alpha_cell;
  }
}

template <int dim>
types::global_dof_index TwoFluidSolver<dim>::pin_pressure (const IndexSet &relevant)
{
  // without an outlet (a closed or periodic domain) p' is fixed to 0 at one node: the
  // first pressure dof that is not a periodic or hanging copy of another
  types::global_dof_index pinned = numbers::invalid_dof_index;
  if (boundaries.has (BoundaryType::outlet))
    return pinned;
  const IndexSet &pressure_owned = flow_owned[1];
  const auto      offset         = flow_owned[0].size ();
  for (const auto i : pressure_owned)
    if (!flow_constraints.is_constrained (offset + i))
    {
      pinned = offset + i;
      break;
    }
  pinned = Utilities::MPI::min (pinned, communicator);
  if (relevant.is_element (pinned))
    flow_constraints.add_line (pinned);
  return pinned;
}

template <int dim>
void TwoFluidSolver<dim>::make_schur_constraints (const IndexSet               &relevant,
                                                  const types::global_dof_index pinned)
{
  // the Schur preconditioner's pressure is fixed where the outlet is traction-free (or
  // at the pinned node)
  schur_constraints.clear ();
  schur_constraints.reinit (relevant);
  make_mesh_constraints (flow_dof_handler, schur_constraints);
  ComponentMask pressure_mask (2 * dim + 1, false);
  pressure_mask.set (2 * dim, true);
  if (boundaries.has (BoundaryType::outlet))
    interpolate_on (mapping,
                    flow_dof_handler,
                    boundaries.ids (BoundaryType::outlet),
                    Functions::ZeroFunction<dim> (2 * dim + 1),
                    schur_constraints,
                    pressure_mask);
  else if (relevant.is_element (pinned))
    schur_constraints.add_line (pinned);
  schur_constraints.close ();
}

#define WETBED_INSTANTIATE(dim)                                                          \
  template void                    TwoFluidSolver<dim>::make_flow_constraints (double);  \
  template void                    TwoFluidSolver<dim>::constrain_walls ();              \
  template void                    TwoFluidSolver<dim>::constrain_held_solids (double);  \
  template void                    TwoFluidSolver<dim>::constrain_inlet_gas (double);    \
  template types::global_dof_index TwoFluidSolver<dim>::pin_pressure (const IndexSet &); \
  template void TwoFluidSolver<dim>::make_schur_constraints (const IndexSet &,           \
                                                             types::global_dof_index);
WETBED_INSTANTIATE (2)
WETBED_INSTANTIATE (3)
#undef WETBED_INSTANTIATE
} // namespace wetbed
