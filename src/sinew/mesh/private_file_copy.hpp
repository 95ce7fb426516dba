#pragma once
/// @file private_file_copy.hpp
/// A private copy of an input file, for libraries that must not see what lies next to it.
///
/// Gmsh, given "mesh.msh", also runs "mesh.msh.opt" as a Gmsh script when that file exists
/// (its `System "..."` statements are shell commands), and reads the file by name after sinew
/// checked it. read_msh therefore checks and hands Gmsh a copy in a fresh directory that only
/// this user can enter (see docs/input-safety.md).

#include <string>

namespace sinew::mesh {

class PrivateFileCopy {
 public:
  /// Copies `source` to `<fresh directory>/<file_name>`, reading at most `max_bytes` bytes.
  /// Throws InputError naming `source` when it is not a regular file, is longer than
  /// `max_bytes`, or cannot be read, and sinew::Error when the copy cannot be written.
  PrivateFileCopy(const std::string& source, const std::string& file_name,
                  unsigned long long max_bytes);
  /// Removes the copy and its directory.
  ~PrivateFileCopy();
  PrivateFileCopy(const PrivateFileCopy&) = delete;
  PrivateFileCopy& operator=(const PrivateFileCopy&) = delete;

  /// Path of the copy.
  const std::string& path() const { return path_; }

 private:
  std::string directory_;
  std::string path_;
};

}  // namespace sinew::mesh
