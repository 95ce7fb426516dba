#pragma once
/// @file interrupt.hpp
/// Graceful interrupt of a run (docs/checkpoints.md): while an InterruptGuard lives, SIGINT and
/// SIGTERM only raise a flag that the run looks at between Newton iterations; the run then
/// writes a checkpoint of its last converged state and stops with ExitCode::Interrupted. A
/// second signal ends the process at once (the default action is back after the first).

#include <string>

#include "sinew/core/error.hpp"

namespace sinew::app {

/// The run stopped for a signal; what() says where and how to resume.
class RunInterrupted : public Error {
 public:
  using Error::Error;
};

class InterruptGuard {
 public:
  /// Installs the handlers (the flag starts cleared).
  InterruptGuard();
  /// Restores the handlers that were there before.
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The signal received since the guard was made, or 0.
  static int pending();
  /// "SIGINT", "SIGTERM".
  static std::string name(int signal);
};

}  // namespace sinew::app
