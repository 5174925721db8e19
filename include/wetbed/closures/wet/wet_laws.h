#pragma once

#include <wetbed/closures/law_registry.h>
#include <wetbed/closures/wet/bridge_gated_restitution.h>
#include <wetbed/closures/wet/gollwitzer_restitution.h>
#include <wetbed/closures/wet/lian_rupture_distance.h>
#include <wetbed/closures/wet/literal_restitution.h>
#include <wetbed/closures/wet/mikami_rupture_distance.h>
#include <wetbed/closures/wet/pitois_rupture_distance.h>

namespace wetbed::closures
{
/** The registered wet laws (source/closures/wet/wet_registry.cc): adding one is its
 * header and its name here. Each must compile for double, ADNumber and VectorizedArray
 * (tests/closures_vectorized.cc). */
using RuptureDistanceLaws =
    LawList<LianRuptureDistance, PitoisRuptureDistance, MikamiRuptureDistance>;
using WetRestitutionLaws =
    LawList<BridgeGatedRestitution, LiteralRestitution, GollwitzerRestitution>;
} // namespace wetbed::closures
