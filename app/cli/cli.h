// The `ispm` command line: render, export, info, compare (and more as the product grows).
#pragma once

namespace ispm {

// Returns the process exit code: 0 success, 1 a failed check (compare), 2 bad input.
int runCli(int argc, char** argv);

} // namespace ispm
