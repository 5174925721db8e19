#include <wetbed/assembly/flow/body_force_term.h>
#include <wetbed/assembly/flow/convection_term.h>
#include <wetbed/assembly/flow/drag_coupling_term.h>
#include <wetbed/assembly/flow/flow_terms.h>
#include <wetbed/assembly/flow/imposed_source_term.h>
#include <wetbed/assembly/flow/inertia_term.h>
#include <wetbed/assembly/flow/nitsche_wall_term.h>
#include <wetbed/assembly/flow/outlet_backflow_term.h>
#include <wetbed/assembly/flow/pressure_coupling_term.h>
#include <wetbed/assembly/flow/schur_mobility_term.h>
#include <wetbed/assembly/flow/viscous_term.h>
#include <wetbed/assembly/flow/wall_friction_term.h>

#include <cmath>

namespace wetbed
{
template <int dim>
void add_flow_terms (FlowAssembler<dim> &assembler, const FlowTermContext<dim> &context)
{
  const Parameters &p  = *context.parameters;
  const auto       &bc = p.boundary;
  const Boundaries &id = context.boundaries;
  const auto       &m  = context.material;

  assembler.add_term (std::make_unique<InertiaTerm<dim>> (m, p.momentum_form));
  assembler.add_term (std::make_unique<DragCouplingTerm<dim>> ());
  assembler.add_term (std::make_unique<ViscousTerm<dim>> ());
  assembler.add_term (std::make_unique<ConvectionTerm<dim>> (p.stabilization));
  assembler.add_term (std::make_unique<PressureCouplingTerm<dim>> ());
  assembler.add_term (std::make_unique<BodyForceTerm<dim>> (m));
  assembler.add_term (std::make_unique<SchurMobilityTerm<dim>> (m));

  // the walls: each phase's friction, and no penetration by Nitsche where it slips
  const WallConditions &walls = context.walls;
  const auto friction         = [] (const WallCondition &c) { return c.has_friction (); };
  if (context.wall_conditions &&
      (walls.any (Phase::gas, friction) || walls.any (Phase::solids, friction)))
    assembler.add_term (std::make_unique<WallFrictionTerm<dim>> (
        walls, id.ids (BoundaryType::moving_wall), context.moving_wall_velocity));
  std::map<dealii::types::boundary_id, std::array<bool, 2>> weak;
  if (context.wall_conditions && bc.nitsche)
    for (const auto wall : id.walls ())
    {
      const std::array<bool, 2> slips = {
          {!walls.at (wall, Phase::gas).prescribes_velocity (),
           !walls.at (wall, Phase::solids).prescribes_velocity ()}};
      if (slips[0] || slips[1])
        weak[wall] = slips;
    }
  if (!weak.empty ())
    assembler.add_term (std::make_unique<NitscheWallTerm<dim>> (
        weak,
        bc.nitsche_penalty * std::pow (context.velocity_degree + 1.0, 2),
        m,
        *context.closures));
  if (p.stabilization)
    assembler.add_term (std::make_unique<OutletBackflowTerm<dim>> (
        id.ids (BoundaryType::outlet), m.gas_density));
}

template <int dim>
std::unique_ptr<FlowAssembler<dim>>
make_flow_assembler (const Parameters                            &parameters,
                     const dealii::Mapping<dim>                  &mapping,
                     const dealii::DoFHandler<dim>               &flow_dof_handler,
                     const dealii::DoFHandler<dim>               &alpha_dof_handler,
                     const closures::ClosureEvaluator            &closures,
                     const Boundaries                            &boundaries,
                     const WallConditions                        &walls,
                     const dealii::Tensor<1, dim>                &moving_wall_velocity,
                     std::shared_ptr<const VerificationHook<dim>> verification)
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
      mapping, flow_dof_handler, alpha_dof_handler, closures, material);
  const FlowTermContext<dim> context{&parameters,
                                     boundaries,
                                     walls,
                                     &closures,
                                     material,
                                     moving_wall_velocity,
                                     flow_dof_handler.get_fe ().degree,
                                     verification->walls_keep_conditions ()};
  add_flow_terms (*assembler, context);
  if (verification->has_flow_sources ())
    assembler->add_term (
        std::make_unique<ImposedSourceTerm<dim>> (verification,
                                                  boundaries.ids (BoundaryType::outlet),
                                                  boundaries.ids (BoundaryType::wall)));
  return assembler;
}

template void add_flow_terms (FlowAssembler<2> &, const FlowTermContext<2> &);
template void add_flow_terms (FlowAssembler<3> &, const FlowTermContext<3> &);
template std::unique_ptr<FlowAssembler<2>>
make_flow_assembler (const Parameters &,
                     const dealii::Mapping<2> &,
                     const dealii::DoFHandler<2> &,
                     const dealii::DoFHandler<2> &,
                     const closures::ClosureEvaluator &,
                     const Boundaries &,
                     const WallConditions &,
                     const dealii::Tensor<1, 2> &,
                     std::shared_ptr<const VerificationHook<2>>);
template std::unique_ptr<FlowAssembler<3>>
make_flow_assembler (const Parameters &,
                     const dealii::Mapping<3> &,
                     const dealii::DoFHandler<3> &,
                     const dealii::DoFHandler<3> &,
                     const closures::ClosureEvaluator &,
                     const Boundaries &,
                     const WallConditions &,
                     const dealii::Tensor<1, 3> &,
                     std::shared_ptr<const VerificationHook<3>>);
} // namespace wetbed
