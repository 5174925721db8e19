#include <wetbed/core/input_error.h>
#include <wetbed/mesh/cell_weights.h>
#include <wetbed/solvers/owned_first_layout.h>
#include <wetbed/solvers/two_fluid_solver.h>
#include <wetbed/solvers/velocity_near_null_space.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <limits>

/*
 * The degrees of freedom of a mesh: the flow (u_g, u_s | p') in two blocks, the alpha_s
 * and Theta space, their constraints (hanging nodes, periodicity) and sparsity, the
 * transport operator, the flow system for this mesh, the checks that need the mesh, and
 * the partition's cost model.
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
void TwoFluidSolver<dim>::setup_dofs ()
{
  TimerOutput::Scope scope (timer, "setup");
  // the mapping's support points on this mesh (a mesh change invalidates them)
  mapping.initialize (MappingQ<dim> (parameters.mesh.mapping_degree), triangulation);
  inlets.reinit (triangulation, mapping, boundaries, communicator);
  flow_dof_handler.distribute_dofs (flow_fe);
  std::vector<unsigned int> block_of_component (2 * dim + 1, 0);
  block_of_component[2 * dim] = 1;
  DoFRenumbering::component_wise (flow_dof_handler, block_of_component);
  const std::vector<types::global_dof_index> dofs_per_block =
      DoFTools::count_dofs_per_fe_block (flow_dof_handler, block_of_component);
  const IndexSet owned    = flow_dof_handler.locally_owned_dofs ();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs (flow_dof_handler);
  flow_owned              = {
                   owned.get_view (0, dofs_per_block[0]),
                   owned.get_view (dofs_per_block[0], dofs_per_block[0] + dofs_per_block[1])};
  flow_relevant = {
      relevant.get_view (0, dofs_per_block[0]),
      relevant.get_view (dofs_per_block[0], dofs_per_block[0] + dofs_per_block[1])};

  alpha_dof_handler.distribute_dofs (alpha_fe);

  // the solids fraction first: the inlet constraints read it
  const IndexSet alpha_relevant =
      DoFTools::extract_locally_relevant_dofs (alpha_dof_handler);
  alpha_constraints.clear ();
  alpha_constraints.reinit (alpha_relevant);
  make_mesh_constraints (alpha_dof_handler, alpha_constraints);
  alpha_constraints.close ();
  fields.alpha.reinit (
      alpha_dof_handler.locally_owned_dofs (), alpha_relevant, communicator);
  fields.alpha_old.reinit (fields.alpha);
  fields.alpha_old2.reinit (fields.alpha);
  // the granular temperature lives on the alpha_s space (Q1, same DoFs)
  fields.theta.reinit (fields.alpha);
  fields.theta_old.reinit (fields.alpha);
  fields.theta_old2.reinit (fields.alpha);
  make_flow_constraints (0.0);

  fields.flow.reinit (flow_owned, flow_relevant, communicator);
  list_owned_entries_first (fields.flow, flow_owned); // their copies share the layout
  fields.flow_old.reinit (fields.flow);
  fields.flow_old2.reinit (fields.flow);
  if (time_averages) // a mesh change or a resume transfers them afterwards
    time_averages->reinit (fields.flow, fields.alpha);
  // the operator's sparsity, the reaction rows, a fresh preconditioner
  flow_system.reinit (mapping,
                      flow_dof_handler,
                      flow_owned,
                      flow_relevant,
                      flow_constraints,
                      schur_constraints,
                      boundaries,
                      fields.alpha);

  // the transport operator and the correction matrices
  solids_transport.reinit (mapping, alpha_dof_handler, alpha_constraints, fields.alpha);
  if (parameters.boundary.feeds_solids ())
  {
    LinearAlgebra::distributed::Vector<double> rates;
    inlets.solids_inflow_rates (
        alpha_dof_handler, mapping, alpha_constraints, fields.alpha, rates);
    solids_transport.set_inflow (rates);
  }
  if (kinetic_theory)
    granular_energy.reinit (alpha_dof_handler, alpha_constraints); // PDE: its sparsity

  measure_mesh ();
  report_mesh (dofs_per_block);
}

template <int dim>
void TwoFluidSolver<dim>::measure_mesh ()
{
  double               h = std::numeric_limits<double>::max (), normal_motion = 0;
  const Tensor<1, dim> wall_motion = moving_wall_velocity ();
  FEFaceValues<dim>    face_values (
      mapping, alpha_fe, QGauss<dim - 1> (2), update_normal_vectors);
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned ())
    {
      h = std::min (h, cell->minimum_vertex_distance ());
      for (const auto f : cell->face_indices ())
        if (cell->face (f)->at_boundary () &&
            boundaries.is (cell->face (f)->boundary_id (), BoundaryType::moving_wall))
        {
          face_values.reinit (cell, f);
          for (const auto &n : face_values.get_normal_vectors ())
            normal_motion = std::max (normal_motion, std::abs (wall_motion * n));
        }
    }
  require (Utilities::MPI::max (normal_motion, communicator) <=
               1e-8 * std::max (wall_motion.norm (), 1e-300),
           "boundary conditions/moving wall velocity",
           "must be tangential to the moving wall (it has a normal component of " +
               std::to_string (Utilities::MPI::max (normal_motion, communicator)) +
               " m/s)");
  min_node_spacing = Utilities::MPI::min (h, communicator) / 2.0;
}

template <int dim>
void TwoFluidSolver<dim>::report_mesh (
    const std::vector<types::global_dof_index> &dofs_per_block) const
{
  if (!initialized) // adaptations: the cell count is in monitors.csv
    pcout << "Mesh: " << triangulation.n_global_active_cells () << " cells; flow DoFs "
          << dofs_per_block[0] << " (u_g, u_s) + " << dofs_per_block[1]
          << " (p'), alpha_s DoFs " << alpha_dof_handler.n_dofs () << std::endl;
  if (!initialized)
  {
    unsigned int                                   cells = 0, wall_faces = 0;
    const auto                                     ids = boundaries;
    const std::function<bool (types::boundary_id)> is_wall =
        [ids] (const types::boundary_id id) { return ids.is_wall (id); };
    for (const auto &cell : triangulation.active_cell_iterators ())
      if (cell->is_locally_owned ())
      {
        ++cells;
        wall_faces += weighted_boundary_faces<dim> (cell, is_wall);
      }
    const auto c =
        Utilities::MPI::min_max_avg (static_cast<double> (cells), communicator);
    const auto w =
        Utilities::MPI::min_max_avg (static_cast<double> (wall_faces), communicator);
    // what each product of the flow operator exchanges: the values of the DoFs on a
    // rank's cells that another rank owns (imported before, sent back after the loop)
    const double owned = flow_dof_handler.locally_owned_dofs ().n_elements ();
    const double active =
        DoFTools::extract_locally_active_dofs (flow_dof_handler).n_elements ();
    const auto g = Utilities::MPI::min_max_avg (active - owned, communicator);
    const auto o = Utilities::MPI::min_max_avg (owned, communicator);
    pcout << "Partition: owned cells per rank " << c.min << "-" << c.max
          << ", wall faces per rank " << w.min << "-" << w.max
          << " (mesh/wall face weight " << parameters.mesh.wall_face_weight
          << "); flow DoFs per rank " << o.min << "-" << o.max << ", ghost flow DoFs "
          << g.min << "-" << g.max << " (" << g.sum << " in all)" << std::endl;
  }
}

template <int dim>
void TwoFluidSolver<dim>::make_mesh_constraints (
    const DoFHandler<dim> &dof_handler, AffineConstraints<double> &constraints) const
{
  DoFTools::make_hanging_node_constraints (dof_handler, constraints);
  if (boundaries.has (BoundaryType::periodic_low))
    DoFTools::make_periodicity_constraints (
        dof_handler,
        boundaries.id_of (BoundaryType::periodic_low),
        boundaries.id_of (BoundaryType::periodic_high),
        parameters.mesh.periodic_direction,
        constraints);
}

template <int dim>
Tensor<1, dim> TwoFluidSolver<dim>::moving_wall_velocity () const
{
  Tensor<1, dim> velocity;
  if (boundaries.has (BoundaryType::moving_wall))
    for (unsigned int d = 0; d < dim; ++d)
      velocity[d] = parameters.boundary.moving_wall_velocity[d];
  return velocity;
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
template void TwoFluidSolver<2>::setup_dofs ();
template void TwoFluidSolver<3>::setup_dofs ();
template void TwoFluidSolver<2>::measure_mesh ();
template void TwoFluidSolver<3>::measure_mesh ();
template void
TwoFluidSolver<2>::report_mesh (const std::vector<types::global_dof_index> &) const;
template void
TwoFluidSolver<3>::report_mesh (const std::vector<types::global_dof_index> &) const;
template void
TwoFluidSolver<2>::make_mesh_constraints (const DoFHandler<2> &,
                                          AffineConstraints<double> &) const;
template void
                      TwoFluidSolver<3>::make_mesh_constraints (const DoFHandler<3> &,
                                          AffineConstraints<double> &) const;
template Tensor<1, 2> TwoFluidSolver<2>::moving_wall_velocity () const;
template Tensor<1, 3> TwoFluidSolver<3>::moving_wall_velocity () const;
} // namespace wetbed
