#include "sinew/io/output_directory.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/io/atomic_file.hpp"

namespace sinew::io {

namespace fs = std::filesystem;

namespace {

/// Files whose presence marks a directory as written by sinew.
constexpr const char* kSinewMarkers[] = {kOutputLockFile, "summary.json", "sinew.pvd"};

std::string quoted(const fs::path& path) { return "\"" + path.string() + "\""; }

/// What the lock file of a directory says about the run holding it ("pid 12, started ...").
std::string lock_holder(const fs::path& lock_path) {
  std::ifstream in(lock_path);
  std::string line;
  std::getline(in, line);
  return line.empty() ? std::string("a run that has not yet recorded itself") : line;
}

[[noreturn]] void throw_in_use(const fs::path& directory, const fs::path& lock_path) {
  throw InputError("output directory " + quoted(directory) + " is in use by another sinew run (" +
                   lock_holder(lock_path) + "); wait for it to finish or choose another directory with -o");
}

/// True when another process holds the lock of `directory` (an existing lock file only).
bool locked_by_another_run(const fs::path& lock_path) {
  const int fd = ::open(lock_path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return false;
  const bool locked = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return locked;
}

/// The entries of `directory` other than the lock file (at most `limit` names).
std::vector<std::string> other_entries(const fs::path& directory, std::size_t limit) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name == kOutputLockFile) continue;
    names.push_back(name);
    if (names.size() >= limit) break;
  }
  return names;
}

bool written_by_sinew(const fs::path& directory) {
  std::error_code ec;
  for (const char* marker : kSinewMarkers)
    if (fs::exists(directory / marker, ec)) return true;
  return false;
}

/// Throws unless `directory` (an existing directory) may be written by this run.
void check_contents(const fs::path& directory, const OutputDirectoryOptions& options) {
  if (options.resume) {
    if (!written_by_sinew(directory))
      throw InputError("output directory " + quoted(directory) +
                       " holds no earlier sinew run (no summary.json, sinew.pvd or .sinew.lock): nothing to resume");
    return;
  }
  const auto entries = other_entries(directory, 3);
  if (entries.empty()) return;
  std::string examples;
  for (const auto& name : entries) examples += (examples.empty() ? "" : ", ") + name;
  if (!options.overwrite)
    throw InputError("output directory " + quoted(directory) + " is not empty (it holds " + examples +
                     (entries.size() >= 3 ? ", ..." : "") +
                     "): choose a new directory with -o, or pass --overwrite to replace an earlier sinew run's results");
  if (!written_by_sinew(directory))
    throw InputError("output directory " + quoted(directory) + " is not empty (it holds " + examples +
                     ") and was not written by sinew (no summary.json, sinew.pvd or .sinew.lock): sinew will not "
                     "empty it even with --overwrite; choose a new directory with -o");
}

/// Removes the temporary files of atomic writes (".<name>.tmp.<pid>.<n>", atomic_file.cpp) that a
/// killed run left in `directory` and its subdirectories; called under the directory's lock.
void remove_stale_temporaries(const fs::path& directory) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (auto it = fs::recursive_directory_iterator(directory, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() > 1 && name[0] == '.' && name.find(".tmp.") != std::string::npos && it->is_regular_file(ec))
      stale.push_back(it->path());
  }
  for (const fs::path& path : stale) fs::remove(path, ec);
}

}  // namespace

void check_output_directory(const std::string& path, const OutputDirectoryOptions& options) {
  if (path.empty()) throw InputError("the output directory is empty: give a directory with -o");
  if (path.find('\0') != std::string::npos) throw InputError("the output directory's name contains a NUL byte");
  if (options.resume && options.overwrite)
    throw InputError("--resume continues the run in the output directory, --overwrite replaces it: give one of them");
  if (!files_written()) return;  // an MPI rank other than 0: rank 0 checks (docs/mpi.md)
  const fs::path directory(path);
  std::error_code ec;
  const auto status = fs::status(directory, ec);
  if (options.resume && !fs::exists(status))
    throw InputError("output directory " + quoted(directory) + " does not exist: there is no run to resume");
  if (fs::exists(status)) {
    if (!fs::is_directory(status))
      throw InputError("output directory " + quoted(directory) + " exists and is not a directory");
    if (::access(directory.c_str(), W_OK | X_OK) != 0)
      throw InputError("output directory " + quoted(directory) + " is not writable: " + std::strerror(errno));
    if (locked_by_another_run(directory / kOutputLockFile)) throw_in_use(directory, directory / kOutputLockFile);
    check_contents(directory, options);
    return;
  }
  // A new directory: its nearest existing ancestor must be a writable directory.
  fs::path ancestor = fs::absolute(directory, ec).parent_path();
  while (!ancestor.empty() && !fs::exists(ancestor, ec) && ancestor != ancestor.root_path())
    ancestor = ancestor.parent_path();
  if (!fs::is_directory(ancestor, ec))
    throw InputError("output directory " + quoted(directory) + " cannot be created: " + quoted(ancestor) +
                     " is not a directory");
  if (::access(ancestor.c_str(), W_OK | X_OK) != 0)
    throw InputError("output directory " + quoted(directory) + " cannot be created in " + quoted(ancestor) + ": " +
                     std::strerror(errno));
}

OutputDirectoryLock::OutputDirectoryLock(const std::string& path, const OutputDirectoryOptions& options,
                                         const std::string& command) {
  check_output_directory(path, options);
  if (!files_written()) return;  // no lock: this process writes nothing
  const fs::path directory(path);
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw OutputError("cannot create output directory " + quoted(directory) + ": " + ec.message());
  const fs::path lock_path = directory / kOutputLockFile;
  fd_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0) throw OutputError("cannot create " + quoted(lock_path) + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw_in_use(directory, lock_path);
  }
  // Under the lock: the contents are checked again (another run may have written in between)
  // and, with overwrite, everything but the lock file goes.
  try {
    check_contents(directory, options);
    if (options.resume) remove_stale_temporaries(directory);
    for (const auto& entry : fs::directory_iterator(directory)) {
      if (options.resume) break;  // the earlier run's outputs are continued
      if (entry.path().filename() == kOutputLockFile) continue;
      fs::remove_all(entry.path(), ec);
      if (ec) throw OutputError("cannot remove " + quoted(entry.path()) + " of an earlier run: " + ec.message());
    }
    const std::string record =
        fmt::format("pid {}, started {:%Y-%m-%d %H:%M:%S} UTC, {}\n", ::getpid(),
                    fmt::gmtime(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now())), command);
    if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, record.data(), record.size(), 0) != static_cast<ssize_t>(record.size()))
      throw OutputError("cannot write " + quoted(lock_path) + ": " + std::strerror(errno));
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

OutputDirectoryLock::~OutputDirectoryLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace sinew::io
