#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

namespace wetbed
{
using namespace dealii;

/** Writes u_g, u_s, p', alpha_s, alpha_g as VTU pieces with a PVTU record. */
template <int dim>
void TwoFluidSolver<dim>::write_fields () const
{
  TimerOutput::Scope scope (timer, "output");
  DataOut<dim>       data_out;
  data_out.attach_triangulation (triangulation);
  std::vector<std::string> names;
  for (unsigned int d = 0; d < dim; ++d)
    names.push_back ("gas_velocity");
  for (unsigned int d = 0; d < dim; ++d)
    names.push_back ("solids_velocity");
  names.push_back ("pressure");
  std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds (
      2 * dim, DataComponentInterpretation::component_is_part_of_vector);
  kinds.push_back (DataComponentInterpretation::component_is_scalar);
  data_out.add_data_vector (flow_dof_handler, flow_solution, names, kinds);
  data_out.add_data_vector (alpha_dof_handler, alpha, "alpha_s");
  AlphaVector alpha_g (alpha);
  for (unsigned int i = 0; i < alpha_g.locally_owned_size (); ++i)
    alpha_g.local_element (i) = 1.0 - alpha.local_element (i);
  alpha_g.update_ghost_values ();
  data_out.add_data_vector (alpha_dof_handler, alpha_g, "alpha_g");
  Vector<float> subdomain (triangulation.n_active_cells ());
  subdomain = triangulation.locally_owned_subdomain ();
  data_out.add_data_vector (subdomain, "rank");
  data_out.build_patches (mapping, 2, DataOut<dim>::curved_inner_cells);
  data_out.write_vtu_with_pvtu_record (
      parameters.output.folder + "/", "fields", output_index, communicator, 5);
  const_cast<TwoFluidSolver<dim> *> (this)->output_index++;
  const_cast<TwoFluidSolver<dim> *> (this)->next_output_time +=
      parameters.output.field_interval;
}

template <int dim>
typename TwoFluidSolver<dim>::Errors TwoFluidSolver<dim>::compute_errors () const
{
  Assert (manufactured, ExcMessage ("no manufactured solution attached"));
  const ManufacturedFlowFunction<dim> exact (*manufactured);
  const QGauss<dim>                   quadrature (5);
  Vector<float>                       cellwise (triangulation.n_active_cells ());
  auto                                norm = [&] (const unsigned int          first,
                   const unsigned int          count,
                   const VectorTools::NormType type)
  {
    ComponentSelectFunction<dim> mask (std::make_pair (first, first + count),
                                       2 * dim + 1);
    VectorTools::integrate_difference (mapping,
                                       flow_dof_handler,
                                       flow_solution,
                                       exact,
                                       cellwise,
                                       quadrature,
                                       type,
                                       &mask);
    return VectorTools::compute_global_error (triangulation, cellwise, type);
  };
  return {norm (0, dim, VectorTools::L2_norm),
          norm (0, dim, VectorTools::H1_seminorm),
          norm (dim, dim, VectorTools::L2_norm),
          norm (dim, dim, VectorTools::H1_seminorm),
          norm (2 * dim, 1, VectorTools::L2_norm)};
}

template void                      TwoFluidSolver<2>::write_fields () const;
template void                      TwoFluidSolver<3>::write_fields () const;
template TwoFluidSolver<2>::Errors TwoFluidSolver<2>::compute_errors () const;
template TwoFluidSolver<3>::Errors TwoFluidSolver<3>::compute_errors () const;
} // namespace wetbed
