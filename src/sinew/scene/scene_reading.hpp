#pragma once
/// @file scene_reading.hpp
/// Pieces of the scene reader (load_scene.cpp) shared by its files: the error list, strict
/// parsing of enumeration names, and the readers of shapes (read_shape.cpp), motions
/// (read_motion.cpp) and solver settings (read_settings.cpp). Each reads JSON that passed the
/// scene schema and records what no schema can see as "<json path>: <message>". Internal to the
/// scene module.

#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sinew/core/enum_names.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/scene/schema.hpp"

namespace sinew::scene::reading {

using nlohmann::json;

inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

/// `"a", "b", "c"` (each name as a JSON string), or "(none)" for no names: the known names in a
/// message about an unknown one.
std::string quoted_names(const std::vector<std::string>& names);

/// The errors found so far, each "<json path>: <message>".
struct ReadErrors {
  std::vector<std::string> lines;

  void add(const std::string& path, const std::string& message) { lines.push_back(path + ": " + message); }
  std::size_t count() const { return lines.size(); }
};

/// A validated vec3 as a Vector3.
inline Vector3 to_vector3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

/// The value of E named by the string j[key] (its name table, sinew/core/enum_names.hpp). An
/// unknown name is an error at "<path>.<key>" naming the value and the allowed names; the
/// table's first value stands in so that reading can go on and report every error.
template <NamedEnum E>
E read_name(const json& j, const std::string& key, const std::string& path, ReadErrors& errors) {
  const std::string name = j.at(key).get<std::string>();
  if (const std::optional<E> value = parse_name<E>(name)) return *value;
  errors.add(json_path_key(path, key), "unknown value " + json(name).dump() + "; allowed: " + names_list<E>());
  return enum_names(E{}).front().first;
}

/// The kind named by the first key of `j` that is a name of E (a shape's or a node selector's
/// kind key, of which the schema requires exactly one), or nothing.
template <NamedEnum E>
std::optional<E> kind_key(const json& j) {
  for (const auto& [value, name] : enum_names(E{})) {
    if (j.contains(std::string(name))) return value;
  }
  return std::nullopt;
}

/// A piecewise-linear amplitude; lambda must increase strictly.
fem::Amplitude read_amplitude(const json& j, const std::string& path, ReadErrors& errors);

/// A rigid motion (translation, rotation in degrees, amplitude), or its keyframes (keyed by
/// lambda, or by time in a dynamic analysis of `end_time`; 0 for a static one).
fem::RigidMotion read_motion(const json& j, const std::string& path, ReadErrors& errors, double end_time);

/// A solid of a generated mesh: a primitive or a boolean of shapes, with its transform.
mesh::Shape read_shape(const json& j, const std::string& path, ReadErrors& errors);

/// A solid of a mesh made from surfaces (read_surface_mesh.cpp).
surface::Solid read_solid(const json& j, const std::string& path, ReadErrors& errors);

/// A body's "surfaces" mesh source; every surface name a part or size zone uses must be declared.
SurfaceMeshConfig read_surface_mesh(const json& j, const std::string& path, ReadErrors& errors);

/// The "solver" section.
solver::StaticSolverOptions read_solver(const json& j, ReadErrors& errors);

/// The "dynamics" section (enabled).
DynamicsConfig read_dynamics(const json& j, ReadErrors& errors);

}  // namespace sinew::scene::reading
