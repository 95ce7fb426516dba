#include "sinew/mesh/private_file_copy.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "sinew/core/error.hpp"

namespace sinew::mesh {

namespace {

/// Closes a file descriptor when it goes out of scope.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

std::string system_error_text() { return std::strerror(errno); }

/// Writes all of `data`; false on failure.
bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

}  // namespace

PrivateFileCopy::PrivateFileCopy(const std::string& source, const std::string& file_name,
                                 unsigned long long max_bytes) {
  const std::string context = "mesh file \"" + source + "\"";
  // O_NONBLOCK: opening a FIFO put in the file's place since it was checked must not block.
  const Descriptor in(::open(source.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (in.get() < 0) throw InputError(context + " cannot be opened: " + system_error_text());
  struct stat status {};
  if (::fstat(in.get(), &status) != 0 || !S_ISREG(status.st_mode)) {
    throw InputError(context + " is not a regular file (a directory, FIFO or device)");
  }

  std::string pattern = (std::filesystem::temp_directory_path() / "sinew-input-XXXXXX").string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (::mkdtemp(buffer.data()) == nullptr) {  // mode 0700
    throw Error("cannot create a private temporary directory for " + context + ": " +
                system_error_text());
  }
  directory_ = buffer.data();
  path_ = directory_ + "/" + file_name;
  try {
    const Descriptor out(::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600));
    if (out.get() < 0) throw Error("cannot write " + path_ + ": " + system_error_text());
    std::array<char, 1 << 16> chunk{};
    unsigned long long copied = 0;
    for (;;) {
      const ssize_t got = ::read(in.get(), chunk.data(), chunk.size());
      if (got < 0) {
        if (errno == EINTR) continue;
        throw InputError(context + " cannot be read: " + system_error_text());
      }
      if (got == 0) break;
      copied += static_cast<unsigned long long>(got);
      if (copied > max_bytes) {
        throw InputError(context + " is longer than " + std::to_string(max_bytes) +
                         " bytes, the most sinew reads");
      }
      if (!write_all(out.get(), chunk.data(), static_cast<std::size_t>(got))) {
        throw Error("cannot write " + path_ + ": " + system_error_text());
      }
    }
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
    throw;
  }
}

PrivateFileCopy::~PrivateFileCopy() {
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

}  // namespace sinew::mesh
