/// @file read_surface_mesh.cpp
/// Scene JSON -> SurfaceMeshConfig and surface::Solid (docs/scene-reference.md, "surfaces" meshes
/// and solids; docs/surface-input.md).

#include <set>

#include "sinew/scene/scene_reading.hpp"

namespace sinew::scene::reading {

surface::Solid read_solid(const json& j, const std::string& path, ReadErrors& errors) {
  using Kind = surface::Solid::Kind;
  surface::Solid solid;
  const std::optional<Kind> kind = kind_key<Kind>(j);
  if (!kind) {
    errors.add(path, "needs one of " + names_list<Kind>());
    return solid;
  }
  solid.kind = *kind;
  const std::string key(name_of(*kind));
  const json& body = j.at(key);
  const std::string body_path = json_path_key(path, key);
  switch (*kind) {
    case Kind::Surface:
      solid.surfaces = {body.get<std::string>()};
      break;
    case Kind::Offset:
      solid.surfaces = body.at("surfaces").get<std::vector<std::string>>();
      solid.distance = body.at("distance").get<double>();
      break;
    case Kind::Box:
      solid.min = to_vector3(body.at("min"));
      solid.max = to_vector3(body.at("max"));
      if (!(solid.min.array() < solid.max.array()).all()) errors.add(body_path, "max must exceed min in every component");
      break;
    case Kind::Capsule:
      solid.a = to_vector3(body.at("a"));
      solid.b = to_vector3(body.at("b"));
      solid.radius = body.at("radius").get<double>();
      break;
    case Kind::Ellipsoid: {
      solid.a = to_vector3(body.at("center"));
      solid.semi_axes = to_vector3(body.at("semi_axes"));
      solid.axis_u = to_vector3(body.at("axis_u"));
      solid.axis_v = to_vector3(body.at("axis_v"));
      if (!(solid.semi_axes.array() > 0).all()) errors.add(json_path_key(body_path, "semi_axes"), "must be > 0 in every component");
      const Vector3 u = solid.axis_u.normalized();
      if ((solid.axis_v - solid.axis_v.dot(u) * u).norm() < 1e-9 * solid.axis_v.norm()) {
        errors.add(json_path_key(body_path, "axis_v"), "must not be parallel to axis_u");
      }
      break;
    }
    case Kind::HalfSpace:
      solid.point = to_vector3(body.at("point"));
      solid.normal = to_vector3(body.at("normal")).normalized();
      break;
    case Kind::Union:
    case Kind::Difference:
    case Kind::Intersection:
      for (std::size_t i = 0; i < body.size(); ++i) {
        solid.children.push_back(read_solid(body[i], json_path_index(body_path, i), errors));
      }
      break;
  }
  return solid;
}

namespace {

/// Every surface name a solid uses, with the path of its use.
void collect_surface_names(const surface::Solid& solid, const std::string& path,
                           std::vector<std::pair<std::string, std::string>>& names) {
  for (const std::string& name : solid.surfaces) names.emplace_back(name, path);
  for (std::size_t i = 0; i < solid.children.size(); ++i) {
    collect_surface_names(solid.children[i], json_path_index(path, i), names);
  }
}

}  // namespace

SurfaceMeshConfig read_surface_mesh(const json& j, const std::string& path, ReadErrors& errors) {
  SurfaceMeshConfig config;
  config.options.element_size = j.at("element_size").get<double>();
  config.options.facet_distance = j.at("facet_distance").get<double>();
  config.options.min_dihedral_deg = j.at("min_dihedral_deg").get<double>();
  for (const auto& [name, entry] : j.at("surfaces").items()) {
    SurfaceFileConfig file;
    file.file = entry.at("file").get<std::string>();
    if (entry.contains("mesh")) file.mesh_name = entry.at("mesh").get<std::string>();
    file.unit_scale = entry.at("unit_scale").get<double>();
    file.translate = to_vector3(entry.at("translate"));
    if (entry.contains("repair")) {
      const json& repair = entry.at("repair");
      surface::RepairOptions options;
      options.drop_degenerate = repair.at("drop_degenerate").get<bool>();
      options.drop_duplicates = repair.at("drop_duplicates").get<bool>();
      options.fill_holes = repair.at("fill_holes").get<bool>();
      options.remesh_edge_length = repair.at("remesh_edge_length").get<double>();
      file.repair = options;
    }
    if (entry.contains("source")) file.source = entry.at("source").get<std::string>();
    config.surfaces.emplace(name, std::move(file));
  }
  std::set<std::string> regions;
  std::vector<std::pair<std::string, std::string>> used;
  const json& parts = j.at("parts");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string part_path = json_path_index(json_path_key(path, "parts"), i);
    surface::SolidPart part;
    part.region = parts[i].at("region").get<std::string>();
    part.solid = read_solid(parts[i].at("solid"), json_path_key(part_path, "solid"), errors);
    if (!regions.insert(part.region).second) {
      errors.add(json_path_key(part_path, "region"), "duplicate part region " + json(part.region).dump());
    }
    collect_surface_names(part.solid, json_path_key(part_path, "solid"), used);
    config.parts.push_back(std::move(part));
  }
  const json& zones = j.at("size_zones");
  for (std::size_t i = 0; i < zones.size(); ++i) {
    surface::SizeZone zone;
    const json& z = zones[i];
    if (z.contains("surfaces")) zone.surfaces = z.at("surfaces").get<std::vector<std::string>>();
    if (z.contains("capsule")) {
      const json& c = z.at("capsule");
      zone.capsule = surface::ZoneCapsule{to_vector3(c.at("a")), to_vector3(c.at("b")), c.at("radius").get<double>()};
    }
    if (zone.surfaces.empty() && !zone.capsule)
      errors.add(json_path_index(json_path_key(path, "size_zones"), i), "a size zone needs \"surfaces\" or a \"capsule\"");
    zone.size = z.at("size").get<double>();
    zone.grading = z.at("grading").get<double>();
    for (const std::string& name : zone.surfaces) used.emplace_back(name, json_path_index(json_path_key(path, "size_zones"), i));
    config.options.size_zones.push_back(std::move(zone));
  }
  for (const auto& [name, where] : used) {
    if (config.surfaces.count(name) == 0) {
      std::string known;
      for (const auto& [key, file] : config.surfaces) known += (known.empty() ? "\"" : ", \"") + key + "\"";
      errors.add(where, "unknown surface \"" + name + "\"; the mesh's surfaces: " + known);
    }
  }
  return config;
}

}  // namespace sinew::scene::reading
