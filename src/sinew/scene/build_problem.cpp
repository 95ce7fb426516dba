/// @file build_problem.cpp
/// SceneConfig -> fem::Problem.

#include "sinew/scene/build_problem.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/material/material_spec.hpp"
#include "sinew/mesh/generate.hpp"
#include "sinew/mesh/read_msh.hpp"
#include "sinew/mesh/tet_mesh_bytes.hpp"
#include "sinew/parallel/ranks.hpp"
#include "sinew/parallel/root_for_all.hpp"
#include "sinew/scene/build_surface_mesh.hpp"
#include "sinew/scene/mesh_cache.hpp"
#include "sinew/scene/resource_estimate.hpp"
#include "sinew/scene/scene_reading.hpp"
#include "sinew/scene/schema.hpp"

namespace sinew::scene {

namespace {

using reading::quoted_names;

template <typename Map>
std::vector<std::string> keys_of(const Map& map) {
  std::vector<std::string> keys;
  for (const auto& entry : map) keys.push_back(entry.first);
  return keys;
}

std::string show_point(const Positions& rest, Index node) {
  std::string text = "(";
  for (int k = 0; k < 3; ++k) {
    if (k > 0) text.append(", ");
    text.append(format_number(rest(node, k)));
  }
  text.append(")");
  return text;
}

std::vector<Index> sorted_unique(std::vector<Index> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

/// The selector's kind by its scene name, with the set or region name: `set "top"`, `box`.
std::string describe_selector(const NodeSelector& selector) {
  std::string text(name_of(selector.kind));
  if (selector.kind == NodeSelector::Kind::Set || selector.kind == NodeSelector::Kind::Region)
    text += " \"" + selector.name + "\"";
  return text;
}

/// The mesh of one body, placed, with the scene's entry for each of its regions.
struct PlacedBody {
  mesh::TetMesh mesh;
  std::vector<const RegionConfig*> region_config;  ///< per mesh region
  std::vector<std::string> region_config_key;      ///< per mesh region: its entry's key in `regions`
};

class ProblemBuilder {
 public:
  explicit ProblemBuilder(const SceneConfig& scene) : scene_(scene) {}

  fem::Problem build() {
    check_resource_limits(scene_);  // before any Gmsh call
    std::vector<PlacedBody> bodies;
    for (std::size_t b = 0; b < scene_.bodies.size(); ++b) bodies.push_back(place_body(b));
    throw_if_errors();

    for (std::size_t b = 0; b < bodies.size(); ++b) append_body(b, bodies[b]);
    throw_if_errors();

    const Index num_nodes = problem_.mesh.num_nodes();
    prescribed_by_.assign(static_cast<std::size_t>(num_nodes), -1);
    rigid_body_of_.assign(static_cast<std::size_t>(num_nodes), -1);
    for (std::size_t r = 0; r < problem_.rigid_bodies.size(); ++r) {
      mark_rigid_members(r);
      check_rigid_name(r);
    }
    throw_if_errors();

    for (std::size_t i = 0; i < scene_.boundary_conditions.size(); ++i) add_boundary_condition(i, bodies);
    for (std::size_t i = 0; i < scene_.loads.forces.size(); ++i) {
      const ForceConfig& force = scene_.loads.forces[i];
      const std::string path = json_path_key(json_path_index("loads.forces", i), "nodes");
      fem::NodalForce nodal{force.name, resolve(force.nodes, path, bodies), force.total_force, force.amplitude, {}};
      if (force.traction) spread_traction(*force.traction, nodal, path);
      problem_.forces.push_back(std::move(nodal));
    }
    problem_.gravity = scene_.loads.gravity;
    throw_if_errors();
    return std::move(problem_);
  }

 private:
  const SceneConfig& scene_;
  fem::Problem problem_;
  std::vector<std::string> errors_;
  std::map<std::string, std::size_t> body_index_;
  std::map<std::string, material::MaterialPtr> shared_materials_;  ///< by material name (no override)
  std::vector<int> prescribed_by_;   ///< per node: boundary condition index, or -1
  std::vector<int> rigid_body_of_;   ///< per node: rigid body index, or -1
  std::vector<std::string> rigid_paths_;  ///< per rigid body: the path of its region entry
  Triangles boundary_faces_;              ///< of the whole mesh, computed for the first traction

  void error(const std::string& path, const std::string& message) { errors_.push_back(path + ": " + message); }

  void throw_if_errors() const {
    if (errors_.empty()) return;
    std::string text;
    for (std::size_t i = 0; i < errors_.size(); ++i) text += (i > 0 ? "\n" : "") + errors_[i];
    throw InputError(text);
  }

  static std::string body_path(std::size_t b) { return json_path_index("bodies", b); }

  /// A traction (force / rest area) on the boundary faces whose three nodes are all in `force`:
  /// the total force and each node's share (a third of the area of each such face it belongs to).
  void spread_traction(const Vector3& traction, fem::NodalForce& force, const std::string& path) {
    if (boundary_faces_.rows() == 0) boundary_faces_ = mesh::boundary_triangles(problem_.mesh.tets);
    std::map<Index, std::size_t> entry_of;
    for (std::size_t i = 0; i < force.nodes.size(); ++i) entry_of.emplace(force.nodes[i], i);
    std::vector<double> area_of_entry(force.nodes.size(), 0.0);
    double area = 0;
    for (Index f = 0; f < boundary_faces_.rows(); ++f) {
      std::array<std::size_t, 3> entries{};
      bool selected = true;
      for (int k = 0; k < 3 && selected; ++k) {
        const auto it = entry_of.find(boundary_faces_(f, k));
        selected = it != entry_of.end();
        if (selected) entries[static_cast<std::size_t>(k)] = it->second;
      }
      if (!selected) continue;
      const auto& x = problem_.mesh.rest;
      const Vector3 a = x.row(boundary_faces_(f, 0)), b = x.row(boundary_faces_(f, 1)), c = x.row(boundary_faces_(f, 2));
      const double face_area = 0.5 * (b - a).cross(c - a).norm();
      for (std::size_t entry : entries) area_of_entry[entry] += face_area / 3.0;
      area += face_area;
    }
    if (!(area > 0)) {
      error(path, "selects no whole boundary face: a traction acts on the boundary faces whose three nodes are all selected");
      return;
    }
    force.total_force = area * traction;
    force.shares.resize(force.nodes.size());
    for (std::size_t i = 0; i < force.nodes.size(); ++i) force.shares[i] = area_of_entry[i] / area;
  }

  /// The body's mesh made from shapes or surfaces. On several MPI ranks rank 0 makes it and
  /// sends it to the others (docs/mpi.md), which then run no mesher: they hold the same mesh to
  /// the last bit without its time and memory. A failure on rank 0 is thrown on every rank with
  /// its message and kind (parallel::on_root_for_all).
  mesh::TetMesh generated_mesh(const BodyConfig& config) const {
    if (parallel::size() <= 1) return generated_mesh_here(config);
    mesh::TetMesh made;
    std::string bytes;
    parallel::on_root_for_all([&] {
      made = generated_mesh_here(config);
      bytes = mesh::tet_mesh_bytes(made);
      if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw Error(fmt::format("the mesh of body \"{}\" takes {} bytes, more than MPI sends to the other ranks at "
                                "once (2^31 - 1): give the body a .msh file instead (\"mesh\": {{\"file\": ...}}), "
                                "which every rank reads",
                                config.name, bytes.size()));
    });
    bytes = parallel::broadcast(bytes);
    if (parallel::is_root()) return made;
    return mesh::tet_mesh_from_bytes(bytes);
  }

  /// The body's mesh made here from shapes or surfaces, through the mesh cache when there is one.
  mesh::TetMesh generated_mesh_here(const BodyConfig& config) const {
    const std::string& data_directory = scene_.data_directory.empty() ? scene_.base_directory : scene_.data_directory;
    const auto make = [&] {
      if (!config.mesh.surfaces) return mesh::generate_mesh(config.mesh.parts, config.mesh.generate);
      SurfaceMeshConfig surfaces = *config.mesh.surfaces;
      surfaces.options.what = "body \"" + config.name + "\"";
      surfaces.options.max_tets = scene_.limits.max_tets;
      return build_surface_mesh(surfaces, data_directory);
    };
    if (scene_.mesh_cache_directory.empty()) return make();
    const std::optional<std::string> key = mesh_cache_key(config.mesh, data_directory);
    if (!key) return make();  // a surface file is unreadable: the mesher says which
    const std::string file = mesh_cache_file(scene_.mesh_cache_directory, *key);
    std::string problem;
    if (std::optional<mesh::TetMesh> cached = read_cached_mesh(file, *key, problem)) {
      logger().info("body \"{}\": mesh from the cache, {} ({} nodes, {} tets)", config.name, file, cached->num_nodes(),
                    cached->num_tets());
      return std::move(*cached);
    }
    if (!problem.empty()) logger().warn("body \"{}\": mesh cache entry {} not used: {}; meshing anew", config.name, file, problem);
    mesh::TetMesh made = make();
    try {
      write_cached_mesh(file, *key, made);
      logger().info("body \"{}\": mesh stored in the cache, {}", config.name, file);
    } catch (const OutputError& e) {
      logger().warn("body \"{}\": the mesh cache was not written: {}", config.name, e.what());
    }
    return made;
  }

  PlacedBody place_body(std::size_t b) {
    const BodyConfig& config = scene_.bodies[b];
    const std::string path = body_path(b);
    PlacedBody body;
    try {
      body.mesh = config.mesh.file.empty() ? generated_mesh(config) : mesh::read_msh(config.mesh.file);
    } catch (const InputError& e) {
      error(json_path_key(path, "mesh"), e.what());
      return body;
    }
    apply_transform(body.mesh, config.mesh);
    if (!body_index_.emplace(config.name, b).second) error(json_path_key(path, "name"), "duplicate body name");

    const std::string regions_path = json_path_key(path, "regions");
    const std::vector<std::string>& mesh_regions = body.mesh.region_names;
    for (const auto& [name, region] : config.regions) {
      if (name != "*" && std::find(mesh_regions.begin(), mesh_regions.end(), name) == mesh_regions.end()) {
        error(json_path_key(regions_path, name),
              "the mesh has no region \"" + name + "\"; its regions: " + quoted_names(mesh_regions));
      }
    }
    const auto fallback = config.regions.find("*");
    for (const std::string& name : mesh_regions) {
      auto entry = config.regions.find(name);
      if (entry == config.regions.end()) entry = fallback;
      if (entry == config.regions.end()) {
        error(regions_path, "mesh region \"" + name + "\" has no entry and there is no \"*\" entry");
        body.region_config.push_back(nullptr);
        body.region_config_key.emplace_back();
      } else {
        body.region_config.push_back(&entry->second);
        body.region_config_key.push_back(entry->first);
      }
    }
    return body;
  }

  /// A per-element fiber field: every tet of the region gets its own law, the region's material
  /// with the fiber along the fiber_path segment nearest the tet's rest centroid.
  void orient_along_path(const RegionConfig& region, const std::string& path, const std::vector<Index>& tets) {
    const auto spec = scene_.materials.find(region.material);
    if (spec == scene_.materials.end() || !spec->second.fiber) return;  // reported by region_material
    const std::vector<Vector3>& points = region.fiber_path;
    std::map<std::size_t, material::MaterialPtr> law_of_segment;  // one law per segment, shared
    for (const Index t : tets) {
      Vector3 centroid = Vector3::Zero();
      for (int k = 0; k < 4; ++k) centroid += problem_.mesh.rest.row(problem_.mesh.tets(t, k)).transpose() / 4.0;
      std::size_t nearest = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const Vector3 segment = points[i + 1] - points[i];
        const double s = std::clamp((centroid - points[i]).dot(segment) / segment.squaredNorm(), 0.0, 1.0);
        const double distance = (centroid - points[i] - s * segment).norm();
        if (distance < best) best = distance, nearest = i;
      }
      material::MaterialPtr& law = law_of_segment[nearest];
      if (!law) {
        material::MaterialSpec oriented = spec->second;
        oriented.fiber->direction = (points[nearest + 1] - points[nearest]).normalized();
        try {
          law = material::make_material(oriented);
        } catch (const InputError& e) {
          error(json_path_key(path, "fiber_path"), e.what());
          return;
        }
      }
      problem_.element_material[t] = law;
    }
  }

  material::MaterialPtr region_material(const RegionConfig& region, const std::string& path) {
    const auto spec = scene_.materials.find(region.material);
    if (spec == scene_.materials.end()) {
      error(json_path_key(path, "material"), "unknown material \"" + region.material + "\"");
      return nullptr;
    }
    try {
      if (!region.fiber_direction) {
        auto& shared = shared_materials_[region.material];
        if (!shared) shared = material::make_material(spec->second);
        return shared;
      }
      material::MaterialSpec oriented = spec->second;
      if (!oriented.fiber) {
        error(json_path_key(path, "fiber_direction"), "material \"" + region.material + "\" has no fiber to orient");
        return nullptr;
      }
      oriented.fiber->direction = *region.fiber_direction;
      return material::make_material(oriented);
    } catch (const InputError& e) {
      error(path, e.what());
      return nullptr;
    }
  }

  void append_body(std::size_t b, const PlacedBody& body) {
    const BodyConfig& config = scene_.bodies[b];
    const mesh::TetMesh& local = body.mesh;
    mesh::TetMesh& global = problem_.mesh;
    fem::BodyRange range{config.name, global.num_nodes(), local.num_nodes(), global.num_tets(), local.num_tets()};
    const Index first_region = static_cast<Index>(global.region_names.size());

    global.rest.conservativeResize(range.first_node + range.num_nodes, 3);
    global.rest.bottomRows(range.num_nodes) = local.rest;
    global.tets.conservativeResize(range.first_tet + range.num_tets, 4);
    global.tets.bottomRows(range.num_tets) = (local.tets.array() + range.first_node).matrix();
    global.region.conservativeResize(range.first_tet + range.num_tets);
    global.region.tail(range.num_tets) = (local.region.array() + first_region).matrix();
    for (const std::string& name : local.region_names) global.region_names.push_back(config.name + "/" + name);
    for (const auto& [name, nodes] : local.node_sets) {
      std::vector<Index>& shifted = global.node_sets[config.name + "/" + name];
      for (Index node : nodes) shifted.push_back(node + range.first_node);
    }
    for (const auto& [name, triangles] : local.face_sets) {
      global.face_sets[config.name + "/" + name] = (triangles.array() + range.first_node).matrix();
    }
    // Node fields span all nodes: earlier bodies' fields are NaN at this body's nodes and this
    // body's fields NaN at theirs.
    const Index num_nodes = range.first_node + range.num_nodes;
    for (auto& [name, values] : global.node_fields) {
      values.conservativeResize(num_nodes);
      values.tail(range.num_nodes).setConstant(std::numeric_limits<double>::quiet_NaN());
    }
    for (const auto& [name, values] : local.node_fields) {
      VectorX& spread = global.node_fields[config.name + "/" + name];
      spread = VectorX::Constant(num_nodes, std::numeric_limits<double>::quiet_NaN());
      spread.tail(range.num_nodes) = values;
    }
    for (const auto& [name, reason] : local.skipped_node_fields) {
      global.skipped_node_fields[config.name + "/" + name] = reason;
    }

    std::vector<std::vector<Index>> tets_of_region(local.region_names.size());
    for (Index t = 0; t < local.num_tets(); ++t) {
      tets_of_region[static_cast<std::size_t>(local.region(t))].push_back(t + range.first_tet);
    }
    const std::string regions_path = json_path_key(body_path(b), "regions");
    for (std::size_t r = 0; r < local.region_names.size(); ++r) {
      const RegionConfig* region = body.region_config[r];
      if (region == nullptr) {
        problem_.region_material.push_back(nullptr);
        problem_.region_density.push_back(0);
        continue;
      }
      const std::string path = json_path_key(regions_path, body.region_config_key[r]);
      problem_.region_density.push_back(region->density);
      if (region->rigid) {
        problem_.region_material.push_back(nullptr);
        if (region->fiber_direction) error(json_path_key(path, "fiber_direction"), "a rigid region has no fibers");
        if (!region->material.empty()) error(path, "a rigid region takes no material");
        fem::RigidBody rigid;
        rigid.name = config.name + "/" + local.region_names[r];
        rigid.tets = tets_of_region[r];
        rigid.kind = region->rigid_kind;
        rigid.motion = region->rigid_motion;
        if (!rigid.tets.empty()) {
          problem_.rigid_bodies.push_back(std::move(rigid));
          rigid_paths_.push_back(path);
        }
      } else if (region->material.empty()) {
        problem_.region_material.push_back(nullptr);
        error(path, "needs \"material\" (deformable) or \"rigid\"");
      } else {
        problem_.region_material.push_back(region_material(*region, path));
        if (!region->fiber_path.empty()) orient_along_path(*region, path, tets_of_region[r]);
      }
    }
    problem_.bodies.push_back(std::move(range));
  }

  /// Global node indices of a selector; records an error (and returns none) when it fails.
  std::vector<Index> resolve(const NodeSelector& selector, const std::string& path, const std::vector<PlacedBody>& bodies) {
    const auto body = body_index_.find(selector.body);
    if (body == body_index_.end()) {
      error(json_path_key(path, "body"), "unknown body \"" + selector.body + "\"; bodies: " + quoted_names(keys_of(body_index_)));
      return {};
    }
    std::vector<Index> nodes;
    try {
      nodes = select_nodes(bodies[body->second].mesh, selector);
    } catch (const InputError& e) {
      error(path, e.what());
      return {};
    }
    if (nodes.empty()) {
      error(path, "selects no node of body \"" + selector.body + "\" (" + describe_selector(selector) +
                      "); positions are rest positions after the body's transform");
      return {};
    }
    const Index offset = problem_.bodies[body->second].first_node;
    for (Index& node : nodes) node += offset;
    return nodes;
  }

  /// Records which rigid body each node follows; a node shared by two rigid regions is an error.
  void mark_rigid_members(std::size_t r) {
    std::map<int, Index> shared;  // other rigid body -> first shared node
    for (Index t : problem_.rigid_bodies[r].tets) {
      for (int k = 0; k < 4; ++k) {
        const Index node = problem_.mesh.tets(t, k);
        int& owner = rigid_body_of_[static_cast<std::size_t>(node)];
        if (owner >= 0 && owner != static_cast<int>(r)) {
          shared.emplace(owner, node);
        } else {
          owner = static_cast<int>(r);
        }
      }
    }
    for (const auto& [other, node] : shared) {
      error(rigid_paths_[r], "rigid region \"" + problem_.rigid_bodies[r].name + "\" shares node(s) with rigid region \"" +
                                 problem_.rigid_bodies[static_cast<std::size_t>(other)].name + "\", e.g. node " +
                                 std::to_string(node) + " at " + show_point(problem_.mesh.rest, node) +
                                 "; a node can follow only one rigid body: make them one region or keep them apart");
    }
  }

  /// A rigid region a "*" entry covers in a mesh file is known only now: its name must not be a
  /// condition's or force's (their reaction columns "<name>.fx", ... would clash; the load-time
  /// check, scene_names.hpp, covers the regions it can see).
  void check_rigid_name(std::size_t r) {
    const std::string& name = problem_.rigid_bodies[r].name;
    const auto clash = [&](const std::string& path, const char* group) {
      error(path, std::string("the ") + group + " name \"" + name + "\" is also the name of the rigid region at " +
                      rigid_paths_[r] + "; their reaction columns (<name>.fx, ...) would clash: rename one");
    };
    for (std::size_t i = 0; i < scene_.boundary_conditions.size(); ++i) {
      if (scene_.boundary_conditions[i].name == name) {
        clash(json_path_key(json_path_index("boundary_conditions", i), "name"), "boundary condition");
      }
    }
    for (std::size_t i = 0; i < scene_.loads.forces.size(); ++i) {
      if (scene_.loads.forces[i].name == name) clash(json_path_key(json_path_index("loads.forces", i), "name"), "force");
    }
  }

  void check_rigid_members(const std::vector<Index>& nodes, const BoundaryConditionConfig& bc, const std::string& path) {
    std::map<int, std::pair<std::size_t, Index>> hits;  // rigid body -> (count, first node)
    for (Index node : nodes) {
      const int rigid = rigid_body_of_[static_cast<std::size_t>(node)];
      if (rigid < 0) continue;
      auto [it, inserted] = hits.emplace(rigid, std::make_pair(std::size_t{0}, node));
      ++it->second.first;
    }
    for (const auto& [rigid, hit] : hits) {
      error(path, std::to_string(hit.first) + " node(s) of \"" + bc.name + "\", e.g. node " + std::to_string(hit.second) +
                      " at " + show_point(problem_.mesh.rest, hit.second) + ", belong to rigid region \"" +
                      problem_.rigid_bodies[static_cast<std::size_t>(rigid)].name +
                      "\"; the rigid body's motion rules them: prescribe the rigid region instead "
                      "(\"rigid\": {\"prescribed\": ...}) or select nodes outside it");
    }
  }

  void add_boundary_condition(std::size_t i, const std::vector<PlacedBody>& bodies) {
    const BoundaryConditionConfig& bc = scene_.boundary_conditions[i];
    const std::string path = json_path_key(json_path_index("boundary_conditions", i), "nodes");
    std::vector<Index> nodes = resolve(bc.nodes, path, bodies);
    check_rigid_members(nodes, bc, path);
    if (bc.kind == BoundaryConditionConfig::Kind::Planar) {
      problem_.planar.push_back({bc.name, std::move(nodes), bc.normal, bc.displacement, bc.amplitude});
      return;
    }
    std::map<int, std::pair<std::size_t, Index>> conflicts;  // earlier condition -> (count, first node)
    for (Index node : nodes) {
      int& owner = prescribed_by_[static_cast<std::size_t>(node)];
      if (owner >= 0) {
        auto [it, inserted] = conflicts.emplace(owner, std::make_pair(std::size_t{0}, node));
        ++it->second.first;
      } else {
        owner = static_cast<int>(i);
      }
    }
    for (const auto& [other, hit] : conflicts) {
      error(path, std::to_string(hit.first) + " node(s), e.g. node " + std::to_string(hit.second) + " at " +
                      show_point(problem_.mesh.rest, hit.second) + ", are already prescribed by \"" +
                      scene_.boundary_conditions[static_cast<std::size_t>(other)].name + "\" (boundary_conditions[" +
                      std::to_string(other) + "]); a node may follow only one fixed or prescribed condition");
    }
    fem::PrescribedNodes prescribed;
    prescribed.name = bc.name;
    prescribed.nodes = std::move(nodes);
    if (bc.kind == BoundaryConditionConfig::Kind::Prescribed) prescribed.motion = bc.motion;
    problem_.prescribed.push_back(std::move(prescribed));
  }
};

}  // namespace

void apply_transform(mesh::TetMesh& mesh, const MeshSourceConfig& source) {
  Matrix3 rotation = Matrix3::Identity();
  if (source.rotate_angle != 0) rotation = Eigen::AngleAxisd(source.rotate_angle, source.rotate_axis.normalized()).toRotationMatrix();
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    const Vector3 X = mesh.rest.row(v).transpose();
    mesh.rest.row(v) = (rotation * X + source.translate).transpose();
  }
}

std::vector<Index> select_nodes(const mesh::TetMesh& mesh, const NodeSelector& selector) {
  std::vector<Index> nodes;
  switch (selector.kind) {
    case NodeSelector::Kind::Set: {
      if (const auto set = mesh.node_sets.find(selector.name); set != mesh.node_sets.end()) {
        return sorted_unique(set->second);
      }
      if (const auto faces = mesh.face_sets.find(selector.name); faces != mesh.face_sets.end()) {
        nodes.assign(faces->second.data(), faces->second.data() + faces->second.size());
        return sorted_unique(std::move(nodes));
      }
      std::set<std::string> names;
      for (const auto& entry : mesh.node_sets) names.insert(entry.first);
      for (const auto& entry : mesh.face_sets) names.insert(entry.first);
      std::string message = "the mesh has no node or face set \"" + selector.name + "\"";
      if (const auto suggestion = closest_match(selector.name, {names.begin(), names.end()})) {
        message += "; did you mean \"" + *suggestion + "\"?";
      }
      throw InputError(message + "; its sets: " + quoted_names({names.begin(), names.end()}));
    }
    case NodeSelector::Kind::Region: {
      const auto region = std::find(mesh.region_names.begin(), mesh.region_names.end(), selector.name);
      if (region == mesh.region_names.end()) {
        throw InputError("the mesh has no region \"" + selector.name + "\"; its regions: " + quoted_names(mesh.region_names));
      }
      const Index id = static_cast<Index>(region - mesh.region_names.begin());
      for (Index t = 0; t < mesh.num_tets(); ++t) {
        if (mesh.region(t) != id) continue;
        for (int k = 0; k < 4; ++k) nodes.push_back(mesh.tets(t, k));
      }
      return sorted_unique(std::move(nodes));
    }
    case NodeSelector::Kind::Box: {
      const Eigen::RowVector3d lower = (selector.box_min.array() - selector.tolerance).transpose();
      const Eigen::RowVector3d upper = (selector.box_max.array() + selector.tolerance).transpose();
      for (Index v = 0; v < mesh.num_nodes(); ++v) {
        if ((mesh.rest.row(v).array() >= lower.array()).all() && (mesh.rest.row(v).array() <= upper.array()).all()) {
          nodes.push_back(v);
        }
      }
      return nodes;
    }
    case NodeSelector::Kind::Plane: {
      const Vector3 normal = selector.normal.normalized();
      for (Index v = 0; v < mesh.num_nodes(); ++v) {
        const Vector3 X = mesh.rest.row(v).transpose();
        if (std::abs(normal.dot(X - selector.point)) <= selector.tolerance) nodes.push_back(v);
      }
      return nodes;
    }
    case NodeSelector::Kind::All:
      nodes.resize(static_cast<std::size_t>(mesh.num_nodes()));
      std::iota(nodes.begin(), nodes.end(), Index{0});
      return nodes;
  }
  return nodes;
}

fem::Problem build_problem(const SceneConfig& scene) { return ProblemBuilder(scene).build(); }

}  // namespace sinew::scene
