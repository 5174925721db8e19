#pragma once

#include <wetbed/closures/law_registry.h>
#include <wetbed/closures/solids_stress/constant_viscosity.h>
#include <wetbed/closures/solids_stress/kinetic_theory_rheology.h>

namespace wetbed::closures
{
/** The registered rheologies (`solids stress/model`): adding one is its class (with
 * `model_name` and `create (const SolidsStressSettings &)`) and its name here. */
using SolidsStressModels = LawList<ConstantViscosityRheology, KineticTheoryRheology>;
} // namespace wetbed::closures
