/// @file load_scene.cpp
/// Scene JSON -> SceneConfig: schema validation, then conversion with semantic checks.

#include "sinew/scene/load_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>

#include "sinew/core/error.hpp"
#include "sinew/scene/scene_names.hpp"
#include "sinew/scene/scene_schema.hpp"
#include "sinew/scene/scene_text.hpp"

namespace sinew::scene {

using nlohmann::json;

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) text += (i > 0 ? "\n" : "") + lines[i];
  return text;
}

std::string quoted_names(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) text += (i > 0 ? ", " : "") + json(names[i]).dump();
  return text.empty() ? "(none)" : text;
}

/// "; did you mean "x"?" or "; known: a, b" for a name that is not among `known`.
std::string unknown_name_hint(const std::string& name, const std::vector<std::string>& known, const std::string& what) {
  if (const auto suggestion = closest_match(name, known)) return "; did you mean " + json(*suggestion).dump() + "?";
  return "; " + what + ": " + quoted_names(known);
}

Vector3 to_vector3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

/// Converts a validated, default-completed scene, collecting the errors no schema can see.
class SceneReader {
 public:
  explicit SceneReader(std::string base_directory) : base_directory_(std::move(base_directory)) {}

  std::vector<std::string> errors;

  SceneConfig read(const json& scene) {
    SceneConfig config;
    config.name = scene.at("name").get<std::string>();
    config.description = scene.at("description").get<std::string>();
    config.units = scene.at("units").get<std::string>();
    config.base_directory = base_directory_;

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
      if (!contact.contains("depth_nodes")) continue;
      config.bodies[b].contact.depth_surface = BodyContactConfig::DepthSurface::Nodes;
      const json& selectors = contact.at("depth_nodes");
      for (std::size_t k = 0; k < selectors.size(); ++k) {
        json selector = selectors[k];
        selector["body"] = config.bodies[b].name;
        config.bodies[b].contact.depth_nodes.push_back(read_selector(
            selector,
            json_path_index(json_path_key(json_path_key(json_path_index("bodies", b), "contact"), "depth_nodes"), k),
            config));
      }
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
      f.total_force = to_vector3(force.at("total_force"));
      if (force.contains("amplitude")) f.amplitude = read_amplitude(force.at("amplitude"), json_path_key(path, "amplitude"));
      if (!force_names.insert(f.name).second) error(json_path_key(path, "name"), "duplicate force name " + json(f.name).dump());
      config.loads.forces.push_back(std::move(f));
    }

    if (scene.contains("contact")) config.contact = read_contact(scene.at("contact"), config);
    config.solver = read_solver(scene.at("solver"));
    if (scene.contains("dynamics")) {
      config.dynamics = read_dynamics(scene.at("dynamics"));
      // Each output writes a VTU of the whole mesh: 1e6 of them is already far too many.
      const double outputs = config.dynamics.options.end_time / config.dynamics.options.output_interval;
      if (outputs > 1e6) {
        error("dynamics.output_interval", "gives " + format_number(std::ceil(outputs)) +
                                              " outputs over end_time; at most 1e+06 are allowed");
      }
    }
    config.output.vtu = scene.at("output").at("vtu").get<bool>();
    config.output.every = scene.at("output").at("every").get<int>();
    for (std::string& clash : output_name_clashes(config)) errors.push_back(std::move(clash));
    return config;
  }

 private:
  std::string base_directory_;

  void error(const std::string& path, const std::string& message) { errors.push_back(path + ": " + message); }

  material::MaterialSpec read_material(const json& j, const std::string& path) {
    material::MaterialSpec spec;
    const std::string law = j.at("law").get<std::string>();
    if (law == "mooney-rivlin") {
      spec.base = material::MooneyRivlinParams{j.at("C1").get<double>(), j.at("C2").get<double>(), j.at("a").get<double>()};
    } else if (law == "veronda-westmann") {
      spec.base = material::VerondaWestmannParams{j.at("alpha").get<double>(), j.at("beta").get<double>(),
                                                  j.at("a").get<double>()};
    } else {
      spec.base = material::NeoHookeanParams{j.at("mu").get<double>(), j.at("lambda").get<double>()};
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

  mesh::Shape read_shape(const json& j, const std::string& path) {
    mesh::Shape shape;
    if (j.contains("box")) {
      shape.kind = mesh::Shape::Kind::Box;
      shape.min = to_vector3(j.at("box").at("min"));
      shape.max = to_vector3(j.at("box").at("max"));
      if (!(shape.min.array() < shape.max.array()).all()) {
        error(json_path_key(path, "box"), "max must exceed min in every component");
      }
    } else if (j.contains("sphere")) {
      shape.kind = mesh::Shape::Kind::Sphere;
      shape.center = to_vector3(j.at("sphere").at("center"));
      shape.radius = j.at("sphere").at("radius").get<double>();
    } else if (j.contains("cylinder")) {
      shape.kind = mesh::Shape::Kind::Cylinder;
      shape.center = to_vector3(j.at("cylinder").at("base"));
      shape.axis = to_vector3(j.at("cylinder").at("axis"));
      shape.radius = j.at("cylinder").at("radius").get<double>();
    } else if (j.contains("torus")) {
      read_torus(j.at("torus"), json_path_key(path, "torus"), shape);
    } else {
      const std::string key = j.contains("union") ? "union" : j.contains("difference") ? "difference" : "intersection";
      shape.kind = key == "union"        ? mesh::Shape::Kind::Union
                   : key == "difference" ? mesh::Shape::Kind::Difference
                                         : mesh::Shape::Kind::Intersection;
      const json& children = j.at(key);
      for (std::size_t i = 0; i < children.size(); ++i) {
        shape.children.push_back(read_shape(children[i], json_path_index(json_path_key(path, key), i)));
      }
    }
    if (j.contains("transform")) {
      const json& transform = j.at("transform");
      shape.translation = to_vector3(transform.at("translate"));
      if (transform.contains("rotate")) {
        const json& rotate = transform.at("rotate");
        shape.rotation_axis = to_vector3(rotate.at("axis"));
        shape.rotation_center = to_vector3(rotate.at("center"));
        shape.rotation_angle_deg = rotate.at("angle_deg").get<double>();
      }
    }
    return shape;
  }

  void read_torus(const json& j, const std::string& path, mesh::Shape& shape) {
    shape.kind = mesh::Shape::Kind::Torus;
    shape.center = to_vector3(j.at("center"));
    shape.axis = to_vector3(j.at("axis"));
    shape.radius = j.at("radius").get<double>();
    shape.minor_radius = j.at("minor_radius").get<double>();
    shape.angle_deg = j.at("angle_deg").get<double>();
    if (!(shape.minor_radius < shape.radius)) {
      error(json_path_key(path, "minor_radius"), "must be < radius (" + format_number(shape.radius) + "), got " +
                                                     format_number(shape.minor_radius));
    }
    if (j.contains("start_direction")) {
      shape.start_direction = to_vector3(j.at("start_direction"));
      const Vector3 axis = shape.axis.normalized();
      const Vector3 start = shape.start_direction.normalized();
      if ((start - start.dot(axis) * axis).norm() < 1e-9) {
        error(json_path_key(path, "start_direction"), "must not be parallel to axis");
      }
    }
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
    } else {
      const json& generate = source.at("generate");
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
        part.shape = read_shape(parts[i].at("shape"), json_path_key(part_path, "shape"));
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
      } else if (region.fiber_direction && !material->second.fiber) {
        error(json_path_key(path, "fiber_direction"),
              "material " + json(region.material).dump() + " has no \"fiber\" to orient");
      }
    }
    if (has_rigid) {
      region.rigid = true;
      const json& rigid = j.at("rigid");
      if (rigid.is_string()) {
        region.rigid_kind = rigid.get<std::string>() == "fixed" ? fem::RigidBody::Kind::Fixed : fem::RigidBody::Kind::Free;
      } else {
        region.rigid_kind = fem::RigidBody::Kind::Prescribed;
        region.rigid_motion = read_motion(rigid.at("prescribed"), json_path_key(json_path_key(path, "rigid"), "prescribed"));
      }
      if (region.fiber_direction) {
        error(json_path_key(path, "fiber_direction"), "a rigid region has no fibers");
      }
    }
    return region;
  }

  ContactConfig read_contact(const json& j, const SceneConfig& config) {
    ContactConfig contact;
    contact.enabled = true;
    contact.method = j.at("method").get<std::string>() == "point" ? contact::ContactMethod::Point
                                                                  : contact::ContactMethod::Area;
    const std::string hessian = j.at("hessian").get<std::string>();
    contact.hessian = hessian == "exact"       ? contact::PairHessian::Exact
                      : hessian == "projected" ? contact::PairHessian::Projected
                                               : contact::PairHessian::GaussNewton;
    if (j.contains("penalty")) contact.penalty = j.at("penalty").get<double>();
    contact.penalty_scale = j.at("penalty_scale").get<double>();
    contact.self_contact = j.at("self_contact").get<bool>();
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
      pair.enabled = pairs[k].at("enabled").get<bool>();
      if (!pair.enabled && pair.penalty)
        error(json_path_key(path, "penalty"), "a disabled pair has no penalty (remove one of the two)");
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

  fem::Amplitude read_amplitude(const json& j, const std::string& path) {
    fem::Amplitude amplitude;
    for (std::size_t i = 0; i < j.size(); ++i) {
      const double lambda = j[i][0].get<double>();
      if (i > 0 && !(lambda > amplitude.points.back().first)) {
        error(json_path_index(json_path_index(path, i), 0),
              "lambda must be strictly increasing, got " + format_number(lambda) + " after " +
                  format_number(amplitude.points.back().first));
      }
      amplitude.points.emplace_back(lambda, j[i][1].get<double>());
    }
    return amplitude;
  }

  fem::RigidMotion read_motion(const json& j, const std::string& path) {
    fem::RigidMotion motion;
    motion.translation = to_vector3(j.at("translation"));
    if (j.contains("rotation")) {
      const json& rotation = j.at("rotation");
      motion.axis = to_vector3(rotation.at("axis"));
      motion.axis_point = to_vector3(rotation.at("point"));
      motion.angle = rotation.at("angle_deg").get<double>() * kRadiansPerDegree;
    }
    if (j.contains("amplitude")) motion.amplitude = read_amplitude(j.at("amplitude"), json_path_key(path, "amplitude"));
    return motion;
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
    if (j.contains("set")) {
      selector.kind = NodeSelector::Kind::Set;
      selector.name = j.at("set").get<std::string>();
    } else if (j.contains("region")) {
      selector.kind = NodeSelector::Kind::Region;
      selector.name = j.at("region").get<std::string>();
    } else if (j.contains("box")) {
      selector.kind = NodeSelector::Kind::Box;
      selector.box_min = to_vector3(j.at("box").at("min"));
      selector.box_max = to_vector3(j.at("box").at("max"));
      selector.tolerance = j.at("box").at("padding").get<double>();
      if (!(selector.box_min.array() <= selector.box_max.array()).all()) {
        error(json_path_key(path, "box"), "max must be >= min in every component");
      }
    } else if (j.contains("plane")) {
      selector.kind = NodeSelector::Kind::Plane;
      selector.point = to_vector3(j.at("plane").at("point"));
      selector.normal = to_vector3(j.at("plane").at("normal"));
      selector.tolerance = j.at("plane").at("tolerance").get<double>();
    } else {
      selector.kind = NodeSelector::Kind::All;
    }
    return selector;
  }

  BoundaryConditionConfig read_boundary_condition(const json& j, const std::string& path, const SceneConfig& config) {
    BoundaryConditionConfig bc;
    bc.name = j.at("name").get<std::string>();
    bc.nodes = read_selector(j.at("nodes"), json_path_key(path, "nodes"), config);
    const std::string type = j.at("type").get<std::string>();
    if (type == "fixed") {
      bc.kind = BoundaryConditionConfig::Kind::Fixed;
    } else if (type == "prescribed") {
      bc.kind = BoundaryConditionConfig::Kind::Prescribed;
      bc.motion = read_motion(j.at("motion"), json_path_key(path, "motion"));
    } else {
      bc.kind = BoundaryConditionConfig::Kind::Planar;
      bc.normal = to_vector3(j.at("normal"));
      bc.displacement = j.at("displacement").get<double>();
      if (j.contains("amplitude")) bc.amplitude = read_amplitude(j.at("amplitude"), json_path_key(path, "amplitude"));
    }
    return bc;
  }

  template <typename Enum, typename NameOf>
  static Enum enum_from_name(const std::string& name, std::initializer_list<Enum> values, NameOf name_of) {
    for (Enum value : values) {
      if (name == name_of(value)) return value;
    }
    return *values.begin();  // unreachable: the schema allows only these names
  }

  static DynamicsConfig read_dynamics(const json& j) {
    using Integrator = solver::DynamicOptions::Integrator;
    DynamicsConfig d;
    d.enabled = true;
    const std::string integrator = j.at("integrator").get<std::string>();
    d.options.integrator = integrator == "explicit"      ? Integrator::Explicit
                           : integrator == "quasistatic" ? Integrator::Quasistatic
                                                         : Integrator::ImplicitEuler;
    d.options.end_time = j.at("end_time").get<double>();
    d.options.output_interval = j.at("output_interval").get<double>();
    if (j.contains("time_step")) d.options.time_step = j.at("time_step").get<double>();
    if (j.contains("max_time_step")) d.options.max_time_step = j.at("max_time_step").get<double>();
    if (j.contains("min_time_step")) d.options.min_time_step = j.at("min_time_step").get<double>();
    d.options.growth = j.at("growth").get<double>();
    d.options.easy_iterations = j.at("easy_iterations").get<int>();
    d.options.explicit_safety = j.at("explicit_safety").get<double>();
    d.mass = j.at("mass").get<std::string>() == "consistent" ? fem::MassKind::Consistent : fem::MassKind::Lumped;
    d.mass_damping = j.at("mass_damping").get<double>();
    d.stiffness_damping = j.at("stiffness_damping").get<double>();
    return d;
  }

  static solver::StaticSolverOptions read_solver(const json& j) {
    using Predictor = solver::LoadSteppingOptions::Predictor;
    using Rule = solver::NewtonOptions::LineSearchRule;
    using Kind = solver::LinearSolverOptions::Kind;
    solver::StaticSolverOptions options;
    options.stepping.increments = j.at("increments").get<int>();
    options.stepping.predictor = enum_from_name(j.at("predictor").get<std::string>(),
                                                {Predictor::None, Predictor::TwoPoint, Predictor::Tangent}, predictor_name);
    options.stepping.min_step = j.at("min_step").get<double>();
    options.stepping.growth = j.at("growth").get<double>();
    options.stepping.easy_iterations = j.at("easy_iterations").get<int>();
    options.stepping.snap_through_after_cuts = j.at("snap_through_after_cuts").get<int>();
    options.stepping.snap_through_iterations = j.at("snap_through_iterations").get<int>();
    const json& newton = j.at("newton");
    options.newton.max_iterations = newton.at("max_iterations").get<int>();
    options.newton.residual_tolerance = newton.at("residual_tolerance").get<double>();
    options.newton.increment_tolerance = newton.at("increment_tolerance").get<double>();
    options.newton.line_search =
        enum_from_name(newton.at("line_search").get<std::string>(), {Rule::Energy, Rule::Residual}, line_search_name);
    options.newton.max_line_search_steps = newton.at("max_line_search_steps").get<int>();
    options.newton.quasi_viscosity = newton.at("quasi_viscosity").get<double>();
    options.newton.project_element_hessians = newton.at("project_hessians").get<bool>();
    const json& linear = j.at("linear");
    options.linear.kind = enum_from_name(linear.at("solver").get<std::string>(),
                                         {Kind::Cholmod, Kind::Gmres, Kind::ConjugateGradient}, linear_solver_name);
    options.linear.tolerance = linear.at("tolerance").get<double>();
    options.linear.max_iterations = linear.at("max_iterations").get<int>();
    options.linear.gmres_restart = linear.at("gmres_restart").get<int>();
    return options;
  }
};

}  // namespace

SceneConfig parse_scene(const json& scene, const std::string& base_directory) {
  SchemaValidation validation = validate_and_complete(scene_schema(), scene);
  if (!validation.errors.empty()) throw InputError(join_lines(validation.errors));
  SceneReader reader(base_directory);
  SceneConfig config = reader.read(validation.completed);
  if (!reader.errors.empty()) throw InputError(join_lines(reader.errors));
  return config;
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
