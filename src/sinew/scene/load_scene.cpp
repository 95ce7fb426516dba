/// @file load_scene.cpp
/// Scene JSON -> SceneConfig: schema validation, then conversion with semantic checks.

#include "sinew/scene/load_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <set>

#include "sinew/core/enum_names.hpp"
#include "sinew/core/error.hpp"
#include "sinew/scene/scene_names.hpp"
#include "sinew/scene/scene_reading.hpp"
#include "sinew/scene/scene_schema.hpp"
#include "sinew/scene/scene_text.hpp"

namespace sinew::scene {

using nlohmann::json;
using namespace reading;  // NOLINT(google-build-using-namespace)

std::string reading::quoted_names(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) text += (i > 0 ? ", " : "") + json(names[i]).dump();
  return text.empty() ? "(none)" : text;
}

namespace {

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) text += (i > 0 ? "\n" : "") + lines[i];
  return text;
}

/// "; did you mean "x"?" or "; known: a, b" for a name that is not among `known`.
std::string unknown_name_hint(const std::string& name, const std::vector<std::string>& known, const std::string& what) {
  if (const auto suggestion = closest_match(name, known)) return "; did you mean " + json(*suggestion).dump() + "?";
  return "; " + what + ": " + quoted_names(known);
}

/// Converts a validated, default-completed scene, collecting the errors no schema can see.
class SceneReader {
 public:
  explicit SceneReader(std::string base_directory) : base_directory_(std::move(base_directory)) {}

  ReadErrors errors;

  SceneConfig read(const json& scene) {
    SceneConfig config;
    // Keyframes keyed by time need it before the bodies and boundary conditions are read.
    if (scene.contains("dynamics")) end_time_ = scene.at("dynamics").at("end_time").get<double>();
    config.name = scene.at("name").get<std::string>();
    config.description = scene.at("description").get<std::string>();
    config.units = scene.at("units").get<std::string>();
    config.base_directory = base_directory_;
    if (scene.contains("data_dir")) config.data_directory = resolve(scene.at("data_dir").get<std::string>());
    if (scene.contains("initial_state")) config.initial_state = resolve(scene.at("initial_state").get<std::string>());

    for (const auto& [name, material] : scene.at("materials").items()) {
      config.materials[name] = read_material(material, json_path_key("materials", name));
    }
    const json& bodies = scene.at("bodies");
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      config.bodies.push_back(read_body(bodies[b], json_path_index("bodies", b), config));
    }
    check_body_names(config);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const json& contact = bodies[b].at("contact");
      // Selectors of this body's nodes: depth_nodes, exclude_faces.
      auto read_selectors = [&](const char* key, std::vector<NodeSelector>& out) {
        const json& selectors = contact.at(key);
        for (std::size_t k = 0; k < selectors.size(); ++k) {
          json selector = selectors[k];
          selector["body"] = config.bodies[b].name;
          out.push_back(read_selector(
              selector, json_path_index(json_path_key(json_path_key(json_path_index("bodies", b), "contact"), key), k),
              config));
        }
      };
      if (contact.contains("exclude_faces")) read_selectors("exclude_faces", config.bodies[b].contact.exclude_faces);
      if (!contact.contains("depth_nodes")) continue;
      config.bodies[b].contact.depth_surface = BodyContactConfig::DepthSurface::Nodes;
      read_selectors("depth_nodes", config.bodies[b].contact.depth_nodes);
    }

    const json& conditions = scene.at("boundary_conditions");
    std::set<std::string> condition_names;
    for (std::size_t i = 0; i < conditions.size(); ++i) {
      const std::string path = json_path_index("boundary_conditions", i);
      config.boundary_conditions.push_back(read_boundary_condition(conditions[i], path, config));
      if (!condition_names.insert(config.boundary_conditions.back().name).second) {
        error(json_path_key(path, "name"), "duplicate boundary condition name " +
                                               json(config.boundary_conditions.back().name).dump());
      }
    }

    const json& loads = scene.at("loads");
    config.loads.gravity = to_vector3(loads.at("gravity"));
    std::set<std::string> force_names;
    for (std::size_t i = 0; i < loads.at("forces").size(); ++i) {
      const std::string path = json_path_index("loads.forces", i);
      const json& force = loads.at("forces")[i];
      ForceConfig f;
      f.name = force.at("name").get<std::string>();
      f.nodes = read_selector(force.at("nodes"), json_path_key(path, "nodes"), config);
      if (force.contains("total_force") == force.contains("traction")) {
        error(path, "give either total_force (force, in equal nodal shares) or traction (force per area on the selected boundary faces)");
      } else if (force.contains("traction")) {
        f.traction = to_vector3(force.at("traction"));
      } else {
        f.total_force = to_vector3(force.at("total_force"));
      }
      if (force.contains("amplitude")) f.amplitude = read_amplitude(force.at("amplitude"), json_path_key(path, "amplitude"), errors);
      if (!force_names.insert(f.name).second) error(json_path_key(path, "name"), "duplicate force name " + json(f.name).dump());
      config.loads.forces.push_back(std::move(f));
    }

    if (scene.contains("contact")) config.contact = read_contact(scene.at("contact"), config);
    config.solver = read_solver(scene.at("solver"), errors);
    if (scene.contains("dynamics")) {
      config.dynamics = read_dynamics(scene.at("dynamics"), errors);
      // Each output writes a VTU of the whole mesh: 1e6 of them is already far too many.
      const double outputs = config.dynamics.options.end_time / config.dynamics.options.output_interval;
      if (outputs > 1e6) {
        error("dynamics.output_interval", "gives " + format_number(std::ceil(outputs)) +
                                              " outputs over end_time; at most 1e+06 are allowed");
      }
      if (config.contact.enforcement.method != contact::ContactEnforcement::Penalty &&
          config.dynamics.options.integrator == solver::DynamicOptions::Integrator::Explicit)
        error("contact.enforcement.method",
              "explicit integration keeps the penalty it started with (its stable step depends on it) and does not "
              "solve a step again: use \"implicit-euler\" or \"quasistatic\" with this method");
      bool friction = config.contact.friction.coefficient > 0;
      for (const ContactPairConfig& pair : config.contact.pairs) friction = friction || pair.friction.value_or(0) > 0;
      if (friction && config.dynamics.options.integrator == solver::DynamicOptions::Integrator::Explicit)
        error("contact.friction", "friction needs an implicit solve (its sticking branch is a stiff spring "
                                  "of 2 mu N / slip_threshold): use \"implicit-euler\" or \"quasistatic\"");
    }
    config.output.vtu = scene.at("output").at("vtu").get<bool>();
    config.output.every = scene.at("output").at("every").get<int>();
    config.output.checkpoint_every = scene.at("output").at("checkpoint_every").get<int>();
    for (std::string& clash : output_name_clashes(config)) errors.lines.push_back(std::move(clash));
    return config;
  }

 private:
  std::string base_directory_;
  double end_time_ = 0;  ///< the dynamic analysis's end time, 0 for a static one

  void error(const std::string& path, const std::string& message) { errors.add(path, message); }

  material::MaterialSpec read_material(const json& j, const std::string& path) {
    material::MaterialSpec spec;
    const std::size_t errors_before = errors.count();
    const material::Law law = read_name<material::Law>(j, "law", path, errors);
    if (errors.count() != errors_before) return spec;  // an unknown law: its parameters mean nothing
    switch (law) {
      case material::Law::MooneyRivlin:
        spec.base = material::MooneyRivlinParams{j.at("C1").get<double>(), j.at("C2").get<double>(),
                                                 j.at("a").get<double>()};
        break;
      case material::Law::VerondaWestmann:
        spec.base = material::VerondaWestmannParams{j.at("alpha").get<double>(), j.at("beta").get<double>(),
                                                    j.at("a").get<double>()};
        break;
      case material::Law::NeoHookean:
        spec.base = material::NeoHookeanParams{j.at("mu").get<double>(), j.at("lambda").get<double>()};
        break;
    }
    if (j.contains("fiber")) {
      const json& fiber = j.at("fiber");
      spec.fiber = material::FiberParams{fiber.at("alpha").get<double>(), fiber.at("beta").get<double>(),
                                         to_vector3(fiber.at("direction"))};
    }
    try {
      material::validate(spec);
    } catch (const InputError& e) {
      error(path, e.what());
    }
    return spec;
  }

  std::string resolve(const std::string& file) const {
    std::filesystem::path p(file);
    if (p.is_relative() && !base_directory_.empty()) p = std::filesystem::path(base_directory_) / p;
    return p.lexically_normal().string();
  }

  MeshSourceConfig read_mesh(const json& body, const std::string& path) {
    MeshSourceConfig mesh;
    const json& source = body.at("mesh");
    const std::string mesh_path = json_path_key(path, "mesh");
    if (source.contains("file")) {
      mesh.file = resolve(source.at("file").get<std::string>());
      std::error_code ec;
      if (!std::filesystem::exists(mesh.file, ec)) {
        error(json_path_key(mesh_path, "file"), "mesh file not found: " + mesh.file);
      } else if (!std::filesystem::is_regular_file(mesh.file, ec)) {
        error(json_path_key(mesh_path, "file"), "not a regular file: " + mesh.file);
      }
    } else if (source.contains("surfaces")) {
      mesh.surfaces = read_surface_mesh(source.at("surfaces"), json_path_key(mesh_path, "surfaces"), errors);
      mesh.cache_key = source.at("surfaces").dump();
    } else {
      const json& generate = source.at("generate");
      mesh.cache_key = generate.dump();
      const std::string generate_path = json_path_key(mesh_path, "generate");
      mesh.generate.element_size = generate.at("element_size").get<double>();
      mesh.generate.optimize_passes = generate.at("optimize_passes").get<int>();
      mesh.generate.elements_per_turn = generate.at("elements_per_turn").get<double>();
      std::set<std::string> region_names;
      const json& parts = generate.at("parts");
      for (std::size_t i = 0; i < parts.size(); ++i) {
        const std::string part_path = json_path_index(json_path_key(generate_path, "parts"), i);
        mesh::Part part;
        part.region = parts[i].at("region").get<std::string>();
        part.shape = read_shape(parts[i].at("shape"), json_path_key(part_path, "shape"), errors);
        if (!region_names.insert(part.region).second) {
          error(json_path_key(part_path, "region"), "duplicate part region " + json(part.region).dump());
        }
        mesh.parts.push_back(std::move(part));
      }
    }
    const json& transform = body.at("transform");
    mesh.translate = to_vector3(transform.at("translate"));
    mesh.rotate_axis = to_vector3(transform.at("rotate").at("axis"));
    mesh.rotate_angle = transform.at("rotate").at("angle_deg").get<double>() * kRadiansPerDegree;
    return mesh;
  }

  RegionConfig read_region(const json& j, const std::string& path, const SceneConfig& config) {
    RegionConfig region;
    region.density = j.at("density").get<double>();
    region.contact_penalty_scale = j.at("contact_penalty_scale").get<double>();
    if (j.contains("fiber_direction")) region.fiber_direction = to_vector3(j.at("fiber_direction"));
    if (j.contains("fiber_path")) {
      for (const json& point : j.at("fiber_path")) region.fiber_path.push_back(to_vector3(point));
      if (region.fiber_direction) error(json_path_key(path, "fiber_path"), "give fiber_direction or fiber_path, not both");
      for (std::size_t i = 1; i < region.fiber_path.size(); ++i) {
        if ((region.fiber_path[i] - region.fiber_path[i - 1]).norm() == 0) {
          error(json_path_index(json_path_key(path, "fiber_path"), i), "repeats the point before it (a segment needs a direction)");
        }
      }
    }
    const bool has_material = j.contains("material");
    const bool has_rigid = j.contains("rigid");
    if (has_material == has_rigid) {
      error(path, has_material ? "has both \"material\" and \"rigid\"; a region is either deformable or rigid"
                               : "needs \"material\" (deformable) or \"rigid\"");
    }
    if (has_material) {
      region.material = j.at("material").get<std::string>();
      const auto material = config.materials.find(region.material);
      if (material == config.materials.end()) {
        std::vector<std::string> known;
        for (const auto& entry : config.materials) known.push_back(entry.first);
        error(json_path_key(path, "material"), "unknown material " + json(region.material).dump() +
                                                   unknown_name_hint(region.material, known, "materials"));
      } else if ((region.fiber_direction || !region.fiber_path.empty()) && !material->second.fiber) {
        error(json_path_key(path, region.fiber_direction ? "fiber_direction" : "fiber_path"),
              "material " + json(region.material).dump() + " has no \"fiber\" to orient");
      }
    }
    if (has_rigid) {
      region.rigid = true;
      const json& rigid = j.at("rigid");
      using RigidKind = fem::RigidBody::Kind;
      const std::string prescribed(name_of(RigidKind::Prescribed));
      if (rigid.is_string()) {
        // A string names the fixed or free kind; the prescribed one is an object {"prescribed": motion}.
        const std::string name = rigid.get<std::string>();
        const std::optional<RigidKind> kind = parse_name<RigidKind>(name);
        if (kind && *kind != RigidKind::Prescribed) {
          region.rigid_kind = *kind;
        } else {
          error(json_path_key(path, "rigid"), "unknown value " + json(name).dump() + "; allowed: " +
                                                  json(std::string(name_of(RigidKind::Fixed))).dump() + ", " +
                                                  json(std::string(name_of(RigidKind::Free))).dump() + " or {\"" + prescribed +
                                                  "\": motion}");
        }
      } else {
        region.rigid_kind = RigidKind::Prescribed;
        region.rigid_motion =
            read_motion(rigid.at(prescribed), json_path_key(json_path_key(path, "rigid"), prescribed), errors,
                        end_time_);
      }
      if (region.fiber_direction) {
        error(json_path_key(path, "fiber_direction"), "a rigid region has no fibers");
      }
      if (!region.fiber_path.empty()) error(json_path_key(path, "fiber_path"), "a rigid region has no fibers");
    }
    return region;
  }

  void read_enforcement(const json& j, ContactConfig& contact) {
    contact::ContactEnforcementOptions& e = contact.enforcement;
    e.method = read_name<contact::ContactEnforcement>(j, "method", "contact.enforcement", errors);
    e.max_updates = j.at("max_updates").get<int>();
    e.max_growth = j.at("max_growth").get<double>();
    const bool absolute = j.contains("penetration_tolerance"), relative = j.contains("relative_tolerance");
    if (absolute) e.penetration_tolerance = j.at("penetration_tolerance").get<double>();
    if (relative) contact.relative_penetration_tolerance = j.at("relative_tolerance").get<double>();
    if (absolute && relative)
      error("contact.enforcement.relative_tolerance", "give penetration_tolerance or relative_tolerance, not both");
    if (e.method != contact::ContactEnforcement::Penalty && !absolute && !relative)
      error("contact.enforcement", "\"" + std::string(name_of(e.method)) +
                                       "\" needs a tolerance: penetration_tolerance (length) or relative_tolerance "
                                       "(fraction of the mean contact-surface edge)");
  }

  ContactConfig read_contact(const json& j, const SceneConfig& config) {
    ContactConfig contact;
    contact.enabled = true;
    contact.method = read_name<contact::ContactMethod>(j, "method", "contact", errors);
    contact.hessian = read_name<contact::PairHessian>(j, "hessian", "contact", errors);
    if (j.contains("penalty")) contact.penalty = j.at("penalty").get<double>();
    contact.penalty_scale = j.at("penalty_scale").get<double>();
    contact.self_contact = j.at("self_contact").get<bool>();
    read_enforcement(j.at("enforcement"), contact);
    const json& friction = j.at("friction");
    contact.friction.coefficient = friction.at("coefficient").get<double>();
    if (friction.contains("slip_threshold")) contact.friction.slip_threshold = friction.at("slip_threshold").get<double>();
    if (friction.contains("slip_velocity_threshold")) {
      contact.friction.slip_velocity_threshold = friction.at("slip_velocity_threshold").get<double>();
      if (contact.friction.slip_threshold)
        error("contact.friction.slip_velocity_threshold",
              "give either slip_threshold (length) or slip_velocity_threshold (length / time), not both");
      if (!(end_time_ > 0))
        error("contact.friction.slip_velocity_threshold",
              "a slip velocity needs time steps: give a \"dynamics\" section, or slip_threshold (length) in a static "
              "analysis");
    }
    contact.friction.max_updates = friction.at("max_updates").get<int>();
    contact.friction.tolerance = friction.at("tolerance").get<double>();
    std::vector<std::string> body_names;
    for (const BodyConfig& body : config.bodies) body_names.push_back(body.name);
    std::set<std::pair<std::string, std::string>> seen;
    const json& pairs = j.at("pairs");
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::string path = json_path_index("contact.pairs", k);
      ContactPairConfig pair;
      const json& names = pairs[k].at("bodies");
      pair.body_a = names[0].get<std::string>();
      pair.body_b = names[1].get<std::string>();
      bool known = true;
      for (std::size_t i = 0; i < 2; ++i) {
        const std::string name = names[i].get<std::string>();
        if (std::find(body_names.begin(), body_names.end(), name) == body_names.end()) {
          error(json_path_index(json_path_key(path, "bodies"), i),
                "unknown body " + json(name).dump() + unknown_name_hint(name, body_names, "bodies"));
          known = false;
        }
      }
      if (pairs[k].contains("penalty")) pair.penalty = pairs[k].at("penalty").get<double>();
      if (pairs[k].contains("friction")) pair.friction = pairs[k].at("friction").get<double>();
      pair.enabled = pairs[k].at("enabled").get<bool>();
      if (!pair.enabled && pair.penalty)
        error(json_path_key(path, "penalty"), "a disabled pair has no penalty (remove one of the two)");
      if (!pair.enabled && pair.friction)
        error(json_path_key(path, "friction"), "a disabled pair has no friction (remove one of the two)");
      const auto key = std::minmax(pair.body_a, pair.body_b);
      if (known && !seen.insert({key.first, key.second}).second)
        error(json_path_key(path, "bodies"), "this pair of bodies is listed twice");
      contact.pairs.push_back(std::move(pair));
    }
    return contact;
  }

  BodyConfig read_body(const json& j, const std::string& path, const SceneConfig& config) {
    BodyConfig body;
    body.name = j.at("name").get<std::string>();
    body.mesh = read_mesh(j, path);
    const json& contact = j.at("contact");
    const std::string contact_path = json_path_key(path, "contact");
    const int depth_sources = static_cast<int>(contact.contains("depth_face_set")) +
                              static_cast<int>(contact.contains("depth_nodes")) +
                              static_cast<int>(contact.contains("depth_region")) +
                              static_cast<int>(contact.contains("depth_file")) +
                              static_cast<int>(contact.contains("depth_field"));
    if (depth_sources > 1)
      error(contact_path, "give at most one of \"depth_face_set\", \"depth_region\", \"depth_nodes\", "
                          "\"depth_file\" and \"depth_field\"");
    if (contact.contains("depth_face_set")) {
      body.contact.depth_surface = BodyContactConfig::DepthSurface::FaceSet;
      body.contact.depth_surface_name = contact.at("depth_face_set").get<std::string>();
    } else if (contact.contains("depth_region")) {
      body.contact.depth_surface = BodyContactConfig::DepthSurface::Region;
      body.contact.depth_surface_name = contact.at("depth_region").get<std::string>();
    } else if (contact.contains("depth_file")) {
      body.contact.depth_file = resolve(contact.at("depth_file").get<std::string>());
      if (!std::filesystem::exists(body.contact.depth_file))
        error(json_path_key(contact_path, "depth_file"), "depth file not found: " + body.contact.depth_file);
    } else if (contact.contains("depth_field")) {
      body.contact.depth_field = contact.at("depth_field").get<std::string>();
      if (body.mesh.file.empty())
        error(json_path_key(contact_path, "depth_field"),
              "needs a mesh file (\"mesh\": {\"file\": ...}); a generated mesh has no node fields");
    }
    for (const auto& [name, region] : j.at("regions").items()) {
      body.regions[name] = read_region(region, json_path_key(json_path_key(path, "regions"), name), config);
    }
    return body;
  }

  void check_body_names(const SceneConfig& config) {
    std::set<std::string> names;
    for (std::size_t b = 0; b < config.bodies.size(); ++b) {
      const std::string& name = config.bodies[b].name;
      const std::string path = json_path_key(json_path_index("bodies", b), "name");
      if (!names.insert(name).second) error(path, "duplicate body name " + json(name).dump());
      if (name.find('/') != std::string::npos) error(path, "must not contain '/' (it separates body and region names)");
    }
  }

  NodeSelector read_selector(const json& j, const std::string& path, const SceneConfig& config) {
    NodeSelector selector;
    std::vector<std::string> body_names;
    for (const BodyConfig& body : config.bodies) body_names.push_back(body.name);
    if (j.contains("body")) {
      selector.body = j.at("body").get<std::string>();
      if (std::find(body_names.begin(), body_names.end(), selector.body) == body_names.end()) {
        error(json_path_key(path, "body"),
              "unknown body " + json(selector.body).dump() + unknown_name_hint(selector.body, body_names, "bodies"));
      }
    } else if (body_names.size() == 1) {
      selector.body = body_names.front();
    } else {
      error(json_path_key(path, "body"), "required when the scene has more than one body (bodies: " +
                                             quoted_names(body_names) + ")");
    }
    using Kind = NodeSelector::Kind;
    const std::optional<Kind> kind = kind_key<Kind>(j);
    if (!kind) {
      error(path, "needs one of " + names_list<Kind>());
      return selector;
    }
    selector.kind = *kind;
    const std::string key(name_of(*kind));
    const json& value = j.at(key);
    switch (*kind) {
      case Kind::Set:
      case Kind::Region:
        selector.name = value.get<std::string>();
        break;
      case Kind::Box:
        selector.box_min = to_vector3(value.at("min"));
        selector.box_max = to_vector3(value.at("max"));
        selector.tolerance = value.at("padding").get<double>();
        if (!(selector.box_min.array() <= selector.box_max.array()).all()) {
          error(json_path_key(path, key), "max must be >= min in every component");
        }
        break;
      case Kind::Plane:
        selector.point = to_vector3(value.at("point"));
        selector.normal = to_vector3(value.at("normal"));
        selector.tolerance = value.at("tolerance").get<double>();
        break;
      case Kind::All:
        break;
    }
    return selector;
  }

  BoundaryConditionConfig read_boundary_condition(const json& j, const std::string& path, const SceneConfig& config) {
    BoundaryConditionConfig bc;
    bc.name = j.at("name").get<std::string>();
    bc.nodes = read_selector(j.at("nodes"), json_path_key(path, "nodes"), config);
    const std::size_t errors_before = errors.count();
    bc.kind = read_name<BoundaryConditionConfig::Kind>(j, "type", path, errors);
    if (errors.count() != errors_before) return bc;  // an unknown type: its other keys mean nothing
    switch (bc.kind) {
      case BoundaryConditionConfig::Kind::Fixed:
        break;
      case BoundaryConditionConfig::Kind::Prescribed:
        bc.motion = read_motion(j.at("motion"), json_path_key(path, "motion"), errors, end_time_);
        break;
      case BoundaryConditionConfig::Kind::Planar:
        bc.normal = to_vector3(j.at("normal"));
        bc.displacement = j.at("displacement").get<double>();
        if (j.contains("amplitude")) bc.amplitude = read_amplitude(j.at("amplitude"), json_path_key(path, "amplitude"), errors);
        break;
    }
    return bc;
  }

};

}  // namespace

SceneConfig read_scene(const json& completed, const std::string& base_directory) {
  SceneReader reader(base_directory);
  SceneConfig config = reader.read(completed);
  if (reader.errors.count() > 0) throw InputError(join_lines(reader.errors.lines));
  return config;
}

SceneConfig parse_scene(const json& scene, const std::string& base_directory) {
  SchemaValidation validation = validate_and_complete(scene_schema(), scene);
  if (!validation.errors.empty()) throw InputError(join_lines(validation.errors));
  return read_scene(validation.completed, base_directory);
}

SceneConfig load_scene_file(const std::string& path) {
  const json scene = parse_scene_json(read_scene_text(path), path);
  const std::string where = "\n(in scene file " + path + ")";
  const std::string directory = std::filesystem::absolute(path).parent_path().lexically_normal().string();
  try {
    return parse_scene(scene, directory);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + where);
  }
}

}  // namespace sinew::scene
