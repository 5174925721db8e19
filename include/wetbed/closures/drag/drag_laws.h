#pragma once

#include <wetbed/closures/drag/gidaspow.h>
#include <wetbed/closures/drag/no_drag.h>
#include <wetbed/closures/drag/syamlal_obrien.h>
#include <wetbed/closures/drag/wen_yu.h>
#include <wetbed/closures/law_registry.h>

namespace wetbed::closures
{
/** The registered drag laws (source/closures/drag/drag_registry.cc): adding one is its
 * header and its name here. Each must compile for double, ADNumber and VectorizedArray
 * (tests/closures_vectorized.cc). */
using DragLaws = LawList<SyamlalOBrien, Gidaspow, WenYu, NoDrag>;
} // namespace wetbed::closures
