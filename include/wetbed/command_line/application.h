#pragma once

namespace wetbed
{
/**
 * The command line: `wetbed case.prm`, `wetbed --help`, `wetbed --print-parameters`.
 * Returns the exit status: 0 on success, 1 on a usage error, 2 on bad input, 3 when
 * the run failed.
 */
int run_application (int argc, char **argv);

/**
 * Removes `--threads N` from the arguments and returns N (1 without it): the threads
 * of each MPI rank for the thread-parallel parts (the flow assembly). Throws an
 * InputError naming `--threads` unless N is an integer >= 1.
 */
unsigned int take_threads_option (int &argc, char **argv);
} // namespace wetbed
