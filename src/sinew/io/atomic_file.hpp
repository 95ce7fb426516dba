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

}  // namespace sinew::io
