#pragma once
/// @file surface_file.hpp
/// The checked bytes of a surface file: the path is a regular file with a known extension and
/// a bounded size, read into memory once. Nothing else on disk is opened afterwards
/// (docs/surface-input.md: safety).

#include <cstdint>
#include <string>
#include <vector>

namespace sinew::surface {

/// Largest surface file read: 2 GiB.
inline constexpr std::uintmax_t kMaxSurfaceFileBytes = std::uintmax_t{2} << 30;

/// The file extensions read, lower case with the dot.
inline constexpr const char* kSurfaceExtensions[] = {".stl", ".obj", ".ply", ".gltf", ".glb"};

/// A surface file's content.
struct SurfaceFile {
  std::string path;             ///< as given by the caller (used in messages)
  std::string extension;        ///< lower case, with the dot: ".stl", ".obj", ".ply", ".gltf", ".glb"
  std::vector<std::uint8_t> bytes;  ///< the whole file, never empty
};

/// Checks `path` and reads it. Throws InputError naming the file when it is missing, not a
/// regular file (a directory, a FIFO: refused without opening it, a device), has another
/// extension (case-insensitive match), is empty, larger than kMaxSurfaceFileBytes, or unreadable.
SurfaceFile read_surface_file(const std::string& path);

}  // namespace sinew::surface
