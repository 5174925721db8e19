#include <wetbed/assembly/flow/flow_terms.h>
#include <wetbed/assembly/flow/manufactured_source_term.h>
#include <wetbed/solvers/two_fluid_solver.h>

namespace wetbed
{
using namespace dealii;

template <int dim>
void TwoFluidSolver<dim>::setup_flow_assembler ()
{
  const auto       &pp = parameters.physical;
  FlowMaterial<dim> material{pp.gas_density,
                             pp.particle_density,
                             pp.gas_viscosity,
                             pp.residual_solids_fraction,
                             {}};
  for (unsigned int d = 0; d < dim; ++d)
    material.gravity[d] = pp.gravity[d];
  flow_assembler = std::make_unique<FlowAssembler<dim>> (
      mapping, flow_dof_handler, alpha_dof_handler, closure_evaluator, material);
  FlowTermContext<dim> context{&parameters,
                               boundaries,
                               &closure_evaluator,
                               material,
                               moving_wall_velocity (),
                               flow_fe.degree,
                               !manufactured || manufactured->slip_walls ()};
  add_flow_terms (*flow_assembler, context);
  // verification runs only: the manufactured solution's sources
  if (manufactured)
    flow_assembler->add_term (std::make_unique<ManufacturedSourceTerm<dim>> (
        manufactured,
        boundaries.ids (BoundaryType::outlet),
        boundaries.ids (BoundaryType::wall)));
}

/**
 * The Oseen-linearised two-fluid system at t_{n+1} about the latest iterate
 * (doc/theory.md, "Discrete flow system"), by the flow terms of this case.
 */
template <int dim>
void TwoFluidSolver<dim>::assemble_flow_system (const BDFCoefficients &bdf,
                                                const double           dt)
{
  TimerOutput::Scope scope (timer, "flow assembly");
  if (!flow_assembler)
    setup_flow_assembler ();
  // the volume fraction and flow state of this linearisation, for the momentum budget
  // (copies of ghosted vectors: the ghost values come with them)
  assembled_alpha = alpha;
  assembled_flow  = flow_solution;
  const FlowAssemblyState<dim>                          state{bdf,
                                     dt,
                                     &flow_solution,
                                     &flow_old,
                                     &flow_old2,
                                     &alpha,
                                     &alpha_old,
                                     &alpha_old2,
                                     &theta};
  const typename FlowAssembler<dim>::BoundaryRowCapture capture{
      &boundary_velocity_dofs,
      upward_direction<dim> (parameters.physical.gravity),
      &boundary_cell_systems};
  flow_assembler->assemble (
      state, flow_constraints, schur_constraints, flow_operator, flow_rhs, capture);
}

template void TwoFluidSolver<2>::setup_flow_assembler ();
template void TwoFluidSolver<3>::setup_flow_assembler ();
template void TwoFluidSolver<2>::assemble_flow_system (const BDFCoefficients &, double);
template void TwoFluidSolver<3>::assemble_flow_system (const BDFCoefficients &, double);
} // namespace wetbed
