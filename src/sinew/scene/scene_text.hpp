#pragma once
/// @file scene_text.hpp
/// Reading a scene file's text safely, before it is parsed: only regular files (a FIFO or a
/// device would block or never end), bounded in size, and bounded in nesting depth (the parser
/// keeps state per open bracket, so 100,000 nested "[" would exhaust memory); then parsing it,
/// with the position of malformed text and every repeated key reported.

#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace sinew::scene {

/// Bounds on a scene file's text. Real scenes are a few kB and nest about 16 levels deep
/// (examples/knee-flexion.json: 10 kB, 16 levels).
struct SceneTextLimits {
  std::uintmax_t max_bytes = 16u << 20;  ///< largest file accepted (bytes): 16 MiB
  std::size_t max_depth = 64;            ///< deepest nesting of arrays and objects accepted
};

/// The text of the scene file at `path`. Throws InputError naming the path when it does not
/// exist, is not a regular file (directory, FIFO, socket, device: "is not a regular file"),
/// is larger than limits.max_bytes, or cannot be read; the file is not opened in the first
/// three cases.
std::string read_scene_text(const std::string& path, const SceneTextLimits& limits = {});

/// Throws InputError "<path>:<line>:<column>: JSON nested deeper than <max> levels ..." at the
/// first bracket ("[" or "{") that opens level max_depth + 1, counting brackets outside
/// strings only (escaped quotes inside strings are skipped). Lines and columns start at 1.
/// Malformed text is left to the parser: this scan only bounds depth.
void check_json_depth(const std::string& text, std::size_t max_depth, const std::string& path);

/// The scene text as JSON: checks its depth (check_json_depth), then parses it. Throws
/// InputError "<path>:<line>:<column>: malformed JSON: <parser message>" for malformed text or a
/// number beyond a double's range, and "<json path>: duplicate key" (one per repeated key,
/// then "(in scene file <path>)") for an object that repeats a key, which nlohmann would keep
/// silently.
nlohmann::json parse_scene_json(const std::string& text, const std::string& path, const SceneTextLimits& limits = {});

}  // namespace sinew::scene
