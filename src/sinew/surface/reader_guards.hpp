#pragma once
/// @file reader_guards.hpp
/// Checks made before Assimp sees a file, for inputs its 5.2 readers are known to mishandle
/// (docs/surface-input.md: safety). Not parsers: each looks at one structural landmark.

#include "sinew/surface/surface_file.hpp"

namespace sinew::surface {

/// Throws InputError naming the file when a known reader pitfall is present:
/// a .ply whose header (text up to the `end_header` line, at most 64 KiB) is incomplete or not
/// text: Assimp 5.2's PLY header parser loops forever on a header cut short.
void check_reader_guards(const SurfaceFile& file);

}  // namespace sinew::surface
