/// @file surface_file.cpp
/// Path, type and size checks, then one read through a descriptor opened without blocking
/// (a FIFO swapped in after the check must not hang the reader).

#include "sinew/surface/surface_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::surface {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string kind_of(const std::filesystem::file_status& status) {
  using std::filesystem::file_type;
  switch (status.type()) {
    case file_type::directory: return "a directory";
    case file_type::fifo: return "a FIFO (named pipe)";
    case file_type::socket: return "a socket";
    case file_type::block: return "a block device";
    case file_type::character: return "a character device";
    default: return "not a regular file";
  }
}

/// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  explicit Descriptor(int d) : fd(d) {}
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
};

std::string known_extensions() {
  std::string list;
  for (const char* e : kSurfaceExtensions) list += (list.empty() ? "" : ", ") + std::string(e);
  return list;
}

}  // namespace

SurfaceFile read_surface_file(const std::string& path) {
  namespace fs = std::filesystem;
  SurfaceFile file{.path = path, .extension = lower(fs::path(path).extension().string()), .bytes = {}};
  const bool known = std::any_of(std::begin(kSurfaceExtensions), std::end(kSurfaceExtensions),
                                 [&](const char* e) { return file.extension == e; });
  if (!known) {
    throw InputError(fmt::format("surface file '{}': unknown extension '{}'; the surface formats are {}",
                                 path, file.extension, known_extensions()));
  }
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // stat only: a FIFO is never opened
  if (ec || !fs::exists(status)) {
    throw InputError(fmt::format("surface file '{}' does not exist or cannot be accessed{}", path,
                                 ec ? " (" + ec.message() + ")" : ""));
  }
  if (!fs::is_regular_file(status)) {
    throw InputError(fmt::format("surface file '{}' is {}, not a regular file", path, kind_of(status)));
  }
  const Descriptor in(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (in.fd < 0) {
    throw InputError(fmt::format("surface file '{}' cannot be opened: {}", path, std::strerror(errno)));
  }
  struct stat st{};
  if (::fstat(in.fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    throw InputError(fmt::format("surface file '{}' is not a regular file", path));
  }
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size == 0) throw InputError(fmt::format("surface file '{}' is empty", path));
  if (size > kMaxSurfaceFileBytes) {
    throw InputError(fmt::format("surface file '{}' has {} bytes, more than the limit of {} bytes (2 GiB)",
                                 path, size, kMaxSurfaceFileBytes));
  }
  file.bytes.resize(static_cast<std::size_t>(size));
  std::size_t done = 0;
  while (done < file.bytes.size()) {
    const ssize_t got = ::read(in.fd, file.bytes.data() + done, file.bytes.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(fmt::format("surface file '{}' cannot be read: {}", path, std::strerror(errno)));
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  if (done != file.bytes.size()) {
    throw InputError(fmt::format("surface file '{}' changed while it was read ({} of {} bytes)", path, done,
                                 file.bytes.size()));
  }
  return file;
}

}  // namespace sinew::surface
