#pragma once

#include <wetbed/closures/kinetic_theory/granular_conductivity.h>
#include <wetbed/closures/kinetic_theory/kinetic_viscosity.h>
#include <wetbed/closures/kinetic_theory/radial_distribution.h>
#include <wetbed/closures/law_registry.h>

namespace wetbed::closures
{
/** The registered kinetic-theory laws
 * (source/closures/kinetic_theory/kinetic_theory_registry.cc): adding one is its header
 * and its name here. Each must compile for double, ADNumber and VectorizedArray
 * (tests/closures_vectorized.cc). */
using RadialDistributionLaws = LawList<OgawaRadialDistribution,
                                       CarnahanStarlingRadialDistribution,
                                       LunSavageRadialDistribution>;
using KineticViscosityLaws   = LawList<GidaspowKineticViscosity, SyamlalKineticViscosity>;
using GranularConductivityLaws = LawList<GidaspowConductivity, SyamlalConductivity>;
} // namespace wetbed::closures
