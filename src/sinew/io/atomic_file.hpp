#pragma once
/// @file atomic_file.hpp
/// Writing files so that a reader (or a crash) never sees a half-written file: the content
/// goes to a temporary file in the same directory, is flushed, then renamed over the target.

#include <string>
#include <string_view>

namespace sinew::io {

/// Writes `content` to `path` atomically; creates missing parent directories. Throws
/// sinew::OutputError naming the path on any failure (the target is then left as it was).
void write_file_atomically(const std::string& path, std::string_view content);

/// Whether this process writes files (default true). A run on several MPI ranks writes from
/// rank 0 only: the other ranks switch writing off, and then write_file_atomically,
/// check_output_directory and OutputDirectoryLock do nothing (docs/mpi.md).
void set_files_written(bool written);
bool files_written();

/// While it lives, this process writes files even where set_files_written(false) switched that
/// off: an MPI rank writing its own piece of a parallel VTU set (io/pvtu.hpp). Main thread only.
class WritingOnThisRank {
 public:
  WritingOnThisRank() : before_(files_written()) { set_files_written(true); }
  ~WritingOnThisRank() { set_files_written(before_); }
  WritingOnThisRank(const WritingOnThisRank&) = delete;
  WritingOnThisRank& operator=(const WritingOnThisRank&) = delete;

 private:
  bool before_;
};

}  // namespace sinew::io
