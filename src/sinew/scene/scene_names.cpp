/// @file scene_names.cpp
/// Names that would give a run's tables two columns of one name (see scene_names.hpp).

#include "sinew/scene/scene_names.hpp"

#include <map>

#include <nlohmann/json.hpp>

#include "sinew/scene/schema.hpp"

namespace sinew::scene {

namespace {

/// A name, the group it belongs to, and the key path it comes from.
struct NameSource {
  std::string name;
  std::string group;  ///< "boundary condition", "force" or "rigid region"
  std::string path;
};

std::vector<NameSource> named_entries(const SceneConfig& config) {
  std::vector<NameSource> sources;
  // Rigid regions first: a clash is reported at the condition or force, the name to change.
  for (std::size_t b = 0; b < config.bodies.size(); ++b) {
    const BodyConfig& body = config.bodies[b];
    const std::string regions_path = json_path_key(json_path_index("bodies", b), "regions");
    for (const auto& [key, region] : body.regions) {
      if (region.rigid && key != "*") {
        sources.push_back({body.name + "/" + key, "rigid region", json_path_key(regions_path, key)});
      }
    }
    const auto fallback = body.regions.find("*");
    if (fallback == body.regions.end() || !fallback->second.rigid) continue;
    for (const mesh::Part& part : body.mesh.parts) {
      if (body.regions.count(part.region) == 0) {
        sources.push_back({body.name + "/" + part.region, "rigid region", json_path_key(regions_path, "*")});
      }
    }
  }
  for (std::size_t i = 0; i < config.boundary_conditions.size(); ++i) {
    sources.push_back({config.boundary_conditions[i].name, "boundary condition",
                       json_path_key(json_path_index("boundary_conditions", i), "name")});
  }
  for (std::size_t i = 0; i < config.loads.forces.size(); ++i) {
    sources.push_back({config.loads.forces[i].name, "force", json_path_key(json_path_index("loads.forces", i), "name")});
  }
  return sources;
}

std::string quoted(const std::string& text) { return nlohmann::json(text).dump(); }

}  // namespace

std::vector<std::string> output_name_clashes(const SceneConfig& config) {
  std::vector<std::string> errors;
  std::map<std::string, NameSource> first;
  for (const NameSource& source : named_entries(config)) {
    const auto [it, inserted] = first.emplace(source.name, source);
    if (inserted || it->second.group == source.group) continue;  // same group: the reader reports it
    errors.push_back(source.path + ": the " + source.group + " name " + quoted(source.name) + " is also the name of the " +
                     it->second.group + " at " + it->second.path +
                     "; their reaction columns (<name>.fx, ...) would clash: rename one");
  }
  if (!config.contact.enabled) return errors;

  // Contact columns: "contact.<a>.<b>.fx" for a before b, "contact.<a>.<a>.force".
  std::map<std::string, std::string> pair_of_prefix;  // prefix -> the bodies' key paths
  for (std::size_t a = 0; a < config.bodies.size(); ++a) {
    for (std::size_t b = a; b < config.bodies.size(); ++b) {
      const std::string prefix = "contact." + config.bodies[a].name + "." + config.bodies[b].name;
      const std::string paths = json_path_key(json_path_index("bodies", a), "name") + " and " +
                                json_path_key(json_path_index("bodies", b), "name");
      const auto [it, inserted] = pair_of_prefix.emplace(prefix + (a == b ? "" : "."), paths);
      if (!inserted) {
        errors.push_back(json_path_key(json_path_index("bodies", b), "name") + ": the contact columns of bodies " +
                         paths + " (" + quoted(prefix + "...") + ") are also those of " + it->second +
                         "; rename a body (a '.' in body names makes this possible)");
      }
      if (a == b) continue;
      if (const auto clash = first.find(prefix); clash != first.end()) {
        errors.push_back(clash->second.path + ": the " + clash->second.group + " name " + quoted(prefix) +
                         " gives reaction columns " + quoted(prefix + ".fx") + ", ... that are also the contact "
                         "columns of bodies " + paths + " (contact); rename it");
      }
    }
  }
  return errors;
}

}  // namespace sinew::scene
