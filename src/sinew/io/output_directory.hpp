#pragma once
/// @file output_directory.hpp
/// A run's output directory is its own: it is checked before any work, locked for the run's
/// lifetime so a second run into it is refused, and it starts empty so no file of an earlier run
/// can pass for a result of this one (docs/output-directory.md).

#include <string>

namespace sinew::io {

struct OutputDirectoryOptions {
  /// Empty a non-empty directory that an earlier sinew run wrote (it holds `.sinew.lock`,
  /// summary.json or sinew.pvd) before writing. A directory sinew did not write is never emptied.
  bool overwrite = false;
  /// Continue the earlier sinew run in the directory (its checkpoint): the directory must exist
  /// and hold that run's outputs, which stay.
  bool resume = false;
};

/// The lock file sinew keeps in every output directory it writes (pid, start time, command).
inline constexpr const char* kOutputLockFile = ".sinew.lock";

/// Checks `path` as an output directory without writing anything: not empty, not an existing
/// non-directory, not held by another running sinew, empty or `overwrite` of an earlier run's
/// outputs, and creatable and writable (checked on its nearest existing ancestor).
/// Throws InputError with the reason and what to do.
void check_output_directory(const std::string& path, const OutputDirectoryOptions& options);

/// The lock on an output directory, held while the object lives (an advisory flock on
/// `<directory>/.sinew.lock`, released by the kernel even when the process is killed).
class OutputDirectoryLock {
 public:
  /// Creates `path` if needed, takes its lock, records `command` and this process in the lock
  /// file, and (with `overwrite`) removes everything else in it. Throws InputError when the
  /// directory fails check_output_directory or another run holds the lock, OutputError when it
  /// cannot be created or written.
  OutputDirectoryLock(const std::string& path, const OutputDirectoryOptions& options, const std::string& command);
  ~OutputDirectoryLock();
  OutputDirectoryLock(const OutputDirectoryLock&) = delete;
  OutputDirectoryLock& operator=(const OutputDirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace sinew::io
