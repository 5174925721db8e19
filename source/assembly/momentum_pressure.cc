#include <wetbed/assembly/flow/flow_terms.h>
#include <wetbed/assembly/flow/manufactured_source_term.h>
#include <wetbed/solvers/two_fluid_solver.h>

namespace wetbed
{
using namespace dealii;

template <int dim>
std::unique_ptr<FlowAssembler<dim>> TwoFluidSolver<dim>::make_flow_assembler () const
{
  const auto       &pp = parameters.physical;
  FlowMaterial<dim> material{pp.gas_density,
                             pp.particle_density,
                             pp.gas_viscosity,
                             pp.residual_solids_fraction,
                             {}};
  for (unsigned int d = 0; d < dim; ++d)
    material.gravity[d] = pp.gravity[d];
  auto assembler = std::make_unique<FlowAssembler<dim>> (
      mapping, flow_dof_handler, alpha_dof_handler, closure_evaluator, material);
  FlowTermContext<dim> context{&parameters,
                               boundaries,
                               wall_conditions,
                               &closure_evaluator,
                               material,
                               moving_wall_velocity (),
                               flow_fe.degree,
                               !manufactured || manufactured->slip_walls ()};
  add_flow_terms (*assembler, context);
  // verification runs only: the manufactured solution's sources
  if (manufactured)
    assembler->add_term (std::make_unique<ManufacturedSourceTerm<dim>> (
        manufactured,
        boundaries.ids (BoundaryType::outlet),
        boundaries.ids (BoundaryType::wall)));
  return assembler;
}

/**
 * The Oseen-linearised two-fluid system at t_{n+1} about the latest iterate
 * (doc/theory.md, "Discrete flow system"), by the flow terms of this case.
 */
template <int dim>
void TwoFluidSolver<dim>::assemble_flow_system (const BDFCoefficients &bdf,
                                                const double           dt)
{
  if (!flow_system.has_assembler ())
    flow_system.set_assembler (make_flow_assembler ());
  const FlowAssemblyState<dim> state{bdf,
                                     dt,
                                     &flow_solution,
                                     &flow_old,
                                     &flow_old2,
                                     &alpha,
                                     &alpha_old,
                                     &alpha_old2,
                                     &theta};
  flow_system.assemble (state, flow_constraints, schur_constraints);
}

template std::unique_ptr<FlowAssembler<2>>
TwoFluidSolver<2>::make_flow_assembler () const;
template std::unique_ptr<FlowAssembler<3>>
              TwoFluidSolver<3>::make_flow_assembler () const;
template void TwoFluidSolver<2>::assemble_flow_system (const BDFCoefficients &, double);
template void TwoFluidSolver<3>::assemble_flow_system (const BDFCoefficients &, double);
} // namespace wetbed
