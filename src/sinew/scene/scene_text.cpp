/// @file scene_text.cpp
/// Safe reading of scene files (see scene_text.hpp).

#include "sinew/scene/scene_text.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <vector>

#include "sinew/core/error.hpp"
#include "sinew/scene/schema.hpp"

namespace sinew::scene {

namespace {

using nlohmann::json;

/// Tracks the JSON path during parsing to report keys an object repeats (nlohmann keeps the last
/// one silently). It keeps a path per open bracket: it parses only text whose depth
/// check_json_depth has bounded.
class DuplicateKeyFinder {
 public:
  std::vector<std::string> errors;

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: frames_.push_back({false, value_path(), {}, {}, 0}); break;
      case json::parse_event_t::array_start: frames_.push_back({true, value_path(), {}, {}, 0}); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!frames_.empty()) frames_.pop_back();
        break;
      case json::parse_event_t::key: {
        Frame& frame = frames_.back();
        frame.current_key = parsed.get<std::string>();
        if (!frame.keys.insert(frame.current_key).second) {
          errors.push_back(json_path_key(frame.path, frame.current_key) + ": duplicate key");
        }
        break;
      }
      case json::parse_event_t::value: value_path(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool is_array;
    std::string path;
    std::set<std::string> keys;
    std::string current_key;
    std::size_t next_index;
  };
  std::vector<Frame> frames_;

  /// The path of the value that starts now (advances the parent array's index).
  std::string value_path() {
    if (frames_.empty()) return "";
    Frame& parent = frames_.back();
    if (parent.is_array) return json_path_index(parent.path, parent.next_index++);
    return json_path_key(parent.path, parent.current_key);
  }
};

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

json parse_scene_json(const std::string& text, const std::string& path, const SceneTextLimits& limits) {
  check_json_depth(text, limits.max_depth, path);
  DuplicateKeyFinder duplicates;
  json scene;
  try {
    scene = json::parse(text, std::ref(duplicates));
  } catch (const json::parse_error& e) {
    // Line and column where parsing stopped, counted as nlohmann's lexer counts them (e.byte
    // characters read, the end of input included; a newline starts the next line at column 0),
    // so they agree with the position in its message.
    std::size_t line = 1, column = 0;
    for (std::size_t i = 0; i < e.byte; ++i) {
      ++column;
      if (i < text.size() && text[i] == '\n') {
        ++line;
        column = 0;
      }
    }
    throw InputError(path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": malformed JSON: " + e.what());
  } catch (const json::exception& e) {
    // e.g. out_of_range 406: a number too large for a double ("1e999"): JSON has no infinity.
    throw InputError(path + ": malformed JSON: " + e.what() +
                     " (numbers must be finite and within the range of a double)");
  }
  if (!duplicates.errors.empty()) {
    std::string message;
    for (const std::string& error : duplicates.errors) message += error + "\n";
    throw InputError(message + "(in scene file " + path + ")");
  }
  return scene;
}

}  // namespace sinew::scene
