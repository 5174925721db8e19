#pragma once

#include <wetbed/assembly/flow/flow_assembler.h>
#include <wetbed/boundary_conditions/wall_conditions.h>
#include <wetbed/core/parameters.h>
#include <wetbed/core/verification_hook.h>
#include <wetbed/mesh/mesh_input.h>

#include <memory>

namespace wetbed
{
/** What the choice of the flow terms depends on besides the parameters. */
template <int dim>
struct FlowTermContext
{
  const Parameters                 *parameters;
  Boundaries                        boundaries;
  WallConditions                    walls;
  const closures::ClosureEvaluator *closures;
  FlowMaterial<dim>                 material;
  dealii::Tensor<1, dim>            moving_wall_velocity;
  unsigned int                      velocity_degree;
  // false: a verification run imposes exact velocities on the walls instead of their
  // conditions (VerificationHook::walls_keep_conditions)
  bool wall_conditions = true;
};

/**
 * Adds the terms of the flow system this case needs, chosen from the parameters (as
 * Lethe's setup_assemblers): inertia, drag coupling, viscous stress, convection (with
 * streamline diffusion where stabilized), the pressure couplings, the body force and
 * the Schur mobility in the volume; on the walls the friction of their conditions
 * (partial slip, Johnson-Jackson, ...), Nitsche no-penetration and the outlet backflow
 * where they apply. A new term: one class deriving from FlowTerm and one line here.
 */
template <int dim>
void add_flow_terms (FlowAssembler<dim> &assembler, const FlowTermContext<dim> &context);

/**
 * The flow assembler of a case: the material of `physical`, the terms of add_flow_terms
 * and the sources `verification` imposes (none in a production run).
 */
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
                     std::shared_ptr<const VerificationHook<dim>> verification);
} // namespace wetbed
