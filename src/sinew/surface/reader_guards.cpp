/// @file reader_guards.cpp

#include "sinew/surface/reader_guards.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <string_view>

#include "sinew/core/error.hpp"

namespace sinew::surface {
namespace {

constexpr std::size_t kMaxPlyHeaderBytes = 64 * 1024;

void check_ply_header(const SurfaceFile& file) {
  const std::size_t scan = std::min(file.bytes.size(), kMaxPlyHeaderBytes);
  const std::string_view head(reinterpret_cast<const char*>(file.bytes.data()), scan);
  if (head.substr(0, 3) != "ply" && head.substr(0, 3) != "PLY") {
    throw InputError(fmt::format("surface file '{}' is not a PLY file: it does not start with 'ply'", file.path));
  }
  // The header ends with a line "end_header" (LF or CRLF); everything before it is text.
  std::size_t end = std::string_view::npos;
  for (std::size_t at = head.find("\nend_header"); at != std::string_view::npos; at = head.find("\nend_header", at + 1)) {
    const std::size_t after = at + 11;
    if (after < head.size() && (head[after] == '\n' || head[after] == '\r')) {
      end = at;
      break;
    }
  }
  if (end == std::string_view::npos) {
    throw InputError(fmt::format("surface file '{}': the PLY header has no 'end_header' line in its first {} bytes",
                                 file.path, kMaxPlyHeaderBytes));
  }
  const auto not_text = std::find_if(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(end), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u > 126 || (u < 32 && c != '\n' && c != '\r' && c != '\t');
  });
  if (not_text != head.begin() + static_cast<std::ptrdiff_t>(end)) {
    throw InputError(fmt::format("surface file '{}': the PLY header holds a byte that is not text (offset {})", file.path,
                                 not_text - head.begin()));
  }
}

}  // namespace

void check_reader_guards(const SurfaceFile& file) {
  if (file.extension == ".ply") check_ply_header(file);
}

}  // namespace sinew::surface
