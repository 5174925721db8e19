#pragma once

#include <set>
#include <string>

namespace wetbed
{
/**
 * The names a gmsh .geo text defines with `DefineConstant[ name = {value, ...}, name =
 * value, ... ];`: the constants that `gmsh -setnumber name value` overrides (a plain
 * assignment `name = value;` ignores -setnumber). Line and block comments and strings
 * are skipped.
 */
std::set<std::string> geo_defined_constants (const std::string &geo_text);
} // namespace wetbed
