#pragma once

#include <wetbed/boundary_conditions/free_slip_condition.h>
#include <wetbed/boundary_conditions/johnson_jackson_condition.h>
#include <wetbed/boundary_conditions/no_slip_condition.h>
#include <wetbed/boundary_conditions/partial_slip_condition.h>
#include <wetbed/closures/law_registry.h>

namespace wetbed
{
/** The registered wall conditions (`boundary conditions/<phase> wall condition`):
 * adding one is its class and its name here. */
using WallConditionList = closures::LawList<NoSlipCondition,
                                            FreeSlipCondition,
                                            PartialSlipCondition,
                                            JohnsonJacksonCondition>;
} // namespace wetbed
