#pragma once
/// @file cli.hpp
/// The `sinew` command line: run, validate, schema.

namespace sinew::app {

/// Parses arguments, runs the command, returns the process exit code:
/// 0 success, 1 bad input or usage, 2 the solve stopped (last converged state written).
int run_cli(int argc, char** argv);

}  // namespace sinew::app
