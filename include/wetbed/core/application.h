#pragma once

namespace wetbed
{
/**
 * The command line: `wetbed case.prm`, `wetbed --help`, `wetbed --print-parameters`.
 * Returns the exit status: 0 on success, 1 on a usage error, 2 on bad input, 3 when
 * the run failed.
 */
int run_application (int argc, char **argv);
} // namespace wetbed
