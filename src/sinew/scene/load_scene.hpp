#pragma once
/// @file load_scene.hpp
/// JSON scene files -> SceneConfig: schema validation (scene_schema.hpp), defaults, then the
/// checks a schema cannot make (names that must exist, unique names, material parameters,
/// strictly increasing amplitudes, mesh files that exist).

#include <string>

#include <nlohmann/json.hpp>

#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// Reads, validates and converts a scene file. Relative mesh paths resolve against the file's
/// directory. Throws InputError: when the file is missing, unreadable, not a regular file,
/// larger than 16 MiB or nested deeper than 64 levels (scene_text.hpp; naming the path); when
/// the JSON is malformed ("<file>:<line>:<column>: malformed JSON: <parser message>"); when an
/// object repeats a key; and for every error parse_scene reports, with a last line naming the
/// file.
SceneConfig load_scene_file(const std::string& path);

/// Validates and converts a scene given as JSON. Relative mesh paths resolve against
/// `base_directory` (kept in SceneConfig::base_directory; empty = the working directory).
/// Throws InputError listing every error found, one per line, each starting with the JSON path
/// of the offending key, e.g. "bodies[0].regions.muscle.density: must be >= 0, got -1".
/// Schema errors are reported first; the semantic checks run only on a scene that passes the
/// schema.
SceneConfig parse_scene(const nlohmann::json& scene, const std::string& base_directory);

/// The conversion step of parse_scene alone: `completed` must have passed the schema (every
/// default filled in). Names of enumerations are parsed strictly even so: an unknown one is an
/// error "<path>: unknown value \"x\"; allowed: \"a\", \"b\"". Throws InputError listing every
/// error found, one per line.
SceneConfig read_scene(const nlohmann::json& completed, const std::string& base_directory);

}  // namespace sinew::scene
