#pragma once
/// @file scene_schema.hpp
/// The schema of a scene file: the single source of truth for validation, defaults, the
/// Markdown reference (docs/scene-reference.md) and the JSON Schema export.

#include <string>

#include <nlohmann/json.hpp>

#include "sinew/scene/schema.hpp"

namespace sinew::scene {

/// The scene schema (built once, immutable). Its defaults are taken from default-constructed
/// config structs (solver::StaticSolverOptions, OutputConfig, ...), so they cannot drift.
const Schema& scene_schema();

/// The reference of the scene format as Markdown: conventions, node selectors, shapes, motions,
/// one table per object of the schema, and an example. docs/scene-reference.md holds its output
/// (a test checks they are equal; `sinew schema --markdown` regenerates it).
std::string scene_reference_markdown();

/// The scene schema as a JSON Schema (draft-07) document, for editors and external validators.
/// Checks that JSON Schema cannot express (names that must exist, strictly increasing
/// amplitudes, ...) are made only by sinew itself.
nlohmann::json scene_json_schema();

/// A complete example scene (the one shown in the reference).
const std::string& scene_example_json();

}  // namespace sinew::scene
