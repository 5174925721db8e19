#pragma once

#include <fstream>
#include <string>

namespace wetbed
{
/** Cuts `filename` back to its first `bytes` (its length at a checkpoint) and opens it
 * in `file` for appending; throws std::runtime_error if it is shorter than that. */
void continue_csv (std::ofstream     &file,
                   const std::string &filename,
                   unsigned long long bytes);
} // namespace wetbed
