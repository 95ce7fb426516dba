#include "sinew/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "sinew/core/error.hpp"

namespace sinew::io {

namespace fs = std::filesystem;

namespace {

/// Distinguishes temporary files of concurrent writes within one process.
std::atomic<unsigned long long> g_temp_counter{0};

[[noreturn]] void fail(const std::string& path, const std::string& what, const std::string& reason) {
  throw OutputError("cannot write file '" + path + "': " + what + ": " + reason);
}

/// Flushes the directory entry of a rename to disk. Best effort: some file systems refuse
/// fsync on directories, and the content itself is already durable.
void sync_directory(const fs::path& directory) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

namespace {
std::atomic<bool> g_files_written{true};
}  // namespace

void set_files_written(bool written) { g_files_written = written; }
bool files_written() { return g_files_written; }

void write_file_atomically(const std::string& path, std::string_view content) {
  if (!files_written()) return;
  const fs::path target(path);
  if (path.empty() || !target.has_filename()) {
    fail(path, "the path does not name a file", "empty file name");
  }
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");

  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) {
    fail(path, "cannot create directory '" + directory.string() + "'", ec.message());
  }

  // Built by appending: GCC 12 warns falsely (-Wrestrict) about `"." + std::string&&`.
  std::string temp_filename(".");
  temp_filename += target.filename().string();
  temp_filename += ".tmp.";
  temp_filename += std::to_string(::getpid());
  temp_filename += '.';
  temp_filename += std::to_string(g_temp_counter.fetch_add(1));
  const fs::path temp = directory / temp_filename;
  const std::string temp_name = temp.string();

  // "x": fail rather than reuse a file that happens to exist under the temporary name.
  std::FILE* file = std::fopen(temp_name.c_str(), "wbx");
  if (file == nullptr) {
    fail(path, "cannot create temporary file '" + temp_name + "'", std::strerror(errno));
  }

  // From here on every failure closes and removes the temporary file before throwing.
  const auto abandon = [&](const std::string& what, int error_number, bool close_file) {
    if (close_file) std::fclose(file);
    std::remove(temp_name.c_str());
    fail(path, what, std::strerror(error_number));
  };

  if (!content.empty() && std::fwrite(content.data(), 1, content.size(), file) != content.size()) {
    abandon("cannot write temporary file '" + temp_name + "'", errno, true);
  }
  if (std::fflush(file) != 0) {
    abandon("cannot flush temporary file '" + temp_name + "'", errno, true);
  }
  if (::fsync(::fileno(file)) != 0) {
    abandon("cannot sync temporary file '" + temp_name + "' to disk", errno, true);
  }
  if (std::fclose(file) != 0) {
    abandon("cannot close temporary file '" + temp_name + "'", errno, false);
  }
  if (std::rename(temp_name.c_str(), path.c_str()) != 0) {
    abandon("cannot rename temporary file '" + temp_name + "' over the target", errno, false);
  }
  sync_directory(directory);
}

}  // namespace sinew::io
