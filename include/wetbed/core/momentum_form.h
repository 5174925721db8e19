#pragma once

namespace wetbed
{
/** `momentum equations/form` (doc/theory.md, "Momentum equations"). */
enum class MomentumForm
{
  conservative,
  advective,
  skew_symmetric
};
} // namespace wetbed
