/// @file scene_text.cpp
/// Safe reading of scene files (see scene_text.hpp).

#include "sinew/scene/scene_text.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "sinew/core/error.hpp"

namespace sinew::scene {

namespace {

const char* describe_file_type(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::directory: return "a directory";
    case std::filesystem::file_type::fifo: return "a FIFO (named pipe)";
    case std::filesystem::file_type::socket: return "a socket";
    case std::filesystem::file_type::block:
    case std::filesystem::file_type::character: return "a device";
    default: return "not a file";
  }
}

}  // namespace

std::string read_scene_text(const std::string& path, const SceneTextLimits& limits) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found) throw InputError("scene file not found: " + path);
  if (ec) throw InputError("cannot read scene file " + path + ": " + ec.message());
  if (status.type() != std::filesystem::file_type::regular) {
    throw InputError(path + ": is not a regular file (it is " + describe_file_type(status.type()) +
                     "); a scene must be a JSON file");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError("cannot read scene file " + path + ": " + ec.message());
  if (size > limits.max_bytes) {
    throw InputError(path + ": scene file too large (" + std::to_string(size) + " bytes; the limit is " +
                     std::to_string(limits.max_bytes) + " bytes); meshes belong in .msh files");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read scene file " + path);
  std::string text;
  text.reserve(static_cast<std::size_t>(size));
  // Read at most one byte past the limit: a file that grows after the size check is still caught.
  std::istreambuf_iterator<char> it(in), end;
  for (; it != end && text.size() <= limits.max_bytes; ++it) text.push_back(*it);
  if (in.bad()) throw InputError("cannot read scene file " + path);
  if (text.size() > limits.max_bytes) {
    throw InputError(path + ": scene file too large (more than " + std::to_string(limits.max_bytes) + " bytes)");
  }
  return text;
}

void check_json_depth(const std::string& text, std::size_t max_depth, const std::string& path) {
  std::size_t depth = 0, line = 1, column = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
    }
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) {
        throw InputError(path + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": JSON nested deeper than " + std::to_string(max_depth) +
                         " levels of arrays and objects; a scene needs far fewer");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace sinew::scene
