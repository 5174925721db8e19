#include <wetbed/solvers/solids_transport.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <iomanip>
#include <sstream>

namespace wetbed
{
using namespace dealii;

template <int dim>
SolidsTransport<dim>::SolidsTransport (const Parameters &parameters,
                                       MPI_Comm          communicator,
                                       TimerOutput      &timer)
    : parameters (parameters), timer (timer), correction (parameters, communicator, timer)
{
}

template <int dim>
void SolidsTransport<dim>::reinit (const Mapping<dim>              &mapping,
                                   const DoFHandler<dim>           &alpha_dof_handler,
                                   const AffineConstraints<double> &alpha_constraints,
                                   const AlphaVector               &layout)
{
  transport.setup (alpha_dof_handler, mapping, alpha_constraints, layout);
  correction.reinit (alpha_dof_handler, alpha_constraints, layout);
}

template <int dim>
bool SolidsTransport<dim>::advance (const SolidsTransportInputs<dim> &inputs,
                                    AlphaVector                      &alpha,
                                    BlockVector                      &flow_solution,
                                    SolveHistory                     &history,
                                    std::string                      &reason)
{
  // explicit bounded transport from t_n with the midpoint of u_s^n and u_s*
  // (doc/theory.md, "One time step", step 2)
  {
    TimerOutput::Scope scope (timer, "alpha transport");
    correction.begin (alpha);
    const FEValuesExtractors::Vector solids (dim);
    // the transport integrates with QGauss(3) on the alpha cell; the same points on
    // the flow cell of the same triangulation cell give u_s there
    FEValues<dim> flow_values (
        inputs.mapping, inputs.flow_fe, QGauss<dim> (3), update_values);
    std::vector<Tensor<1, dim>> u_now, u_before;
    transport.set_velocity (
        [&] (const typename DoFHandler<dim>::active_cell_iterator &alpha_cell,
             const FEValues<dim> & /*alpha_values: QGauss(3) as flow_values*/,
             std::vector<Tensor<1, dim>> &u)
        {
          flow_values.reinit (typename DoFHandler<dim>::active_cell_iterator (
              &inputs.flow_dof_handler.get_triangulation (),
              alpha_cell->level (),
              alpha_cell->index (),
              &inputs.flow_dof_handler));
          u_now.resize (u.size ());
          u_before.resize (u.size ());
          flow_values[solids].get_function_values (flow_solution, u_now);
          flow_values[solids].get_function_values (inputs.flow_old, u_before);
          for (unsigned int i = 0; i < u.size (); ++i)
            u[i] = 0.5 * (u_now[i] + u_before[i]);
        });
    AlphaVector transported (inputs.alpha_old);
    if (transport.advance (transported,
                           inputs.dt,
                           parameters.time.transport_cfl,
                           parameters.physical.maximum_packing) ==
        numbers::invalid_unsigned_int)
    {
      std::ostringstream text;
      text << "the alpha_s transport would need " << std::setprecision (3)
           << transport.required_sub_steps () << " sub-steps (at most "
           << VolumeFractionTransport<dim>::max_sub_steps
           << "): the solids would cross that many cells in one step";
      reason = text.str ();
      return false;
    }
    alpha = transported;
  }
  // implicit solids-pressure correction of alpha_s, then of u_s with the same
  // compaction response, so that velocity and packing stay consistent (steps 3-4)
  const SolveRecord record = [&] (const std::string           &solver,
                                  const dealii::SolverControl &control,
                                  const bool                   converged)
  { history.record (solver, control, converged); };
  if (correction.correct_solids_fraction (
          inputs, flow_solution, alpha, transport, record))
    correction.correct_solids_velocity (inputs, alpha, flow_solution);
  return true;
}

template class SolidsTransport<2>;
template class SolidsTransport<3>;
} // namespace wetbed
