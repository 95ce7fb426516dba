#pragma once
/// @file temp_dir.hpp
/// The tests' scratch directory: a fresh, empty directory under the system temporary directory
/// (mkdtemp, so unique across processes, tests and instances), removed with everything in it
/// when the object goes out of scope.

#include <stdlib.h>  // mkdtemp

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace sinew::testing {

class TempDir {
 public:
  /// A new directory `<temp>/<stem>-XXXXXX`.
  explicit TempDir(const std::string& stem = "sinew-test") {
    std::string pattern = (std::filesystem::temp_directory_path() / (stem + "-XXXXXX")).string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (::mkdtemp(buffer.data()) == nullptr) {
      throw std::system_error(errno, std::generic_category(), "mkdtemp " + pattern);
    }
    path_ = buffer.data();
  }
  /// Removes the directory and its contents, giving the owner every permission first (a test
  /// may have made something in it read-only); errors are ignored.
  ~TempDir() {
    namespace fs = std::filesystem;
    std::error_code ignored;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ignored);
    std::error_code walk;
    for (auto it = fs::recursive_directory_iterator(path_, fs::directory_options::skip_permission_denied, walk);
         !walk && it != fs::recursive_directory_iterator(); it.increment(walk)) {
      if (!it->is_symlink(ignored) && it->is_directory(ignored)) {
        fs::permissions(it->path(), fs::perms::owner_all, fs::perm_options::add, ignored);
      }
    }
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// `name` inside the directory, as a string (the file need not exist).
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  /// `name` inside the directory.
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  /// Writes `text` (bytes as given) to `name` inside the directory and returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::string target = file(name);
    std::ofstream out(target, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + target);
    return target;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace sinew::testing
