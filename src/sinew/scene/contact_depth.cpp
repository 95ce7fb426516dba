/// @file contact_depth.cpp
/// The nodal material depths of one body for contact (see contact_depth.hpp).

#include "sinew/scene/contact_depth.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "sinew/collision/material_depth.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/scene/build_contact.hpp"
#include "sinew/scene/build_problem.hpp"

namespace sinew::scene {
namespace {

/// Boundary faces of `all_boundary` that bound a tet of `region` (global region id).
Triangles region_boundary(const Triangles& all_boundary, const fem::Problem& problem, const fem::BodyRange& body,
                          Index region) {
  std::vector<Index> selected;
  for (Index t = body.first_tet; t < body.first_tet + body.num_tets; ++t)
    if (problem.mesh.region[t] == region) selected.push_back(t);
  Tets tets(static_cast<Index>(selected.size()), 4);
  for (std::size_t k = 0; k < selected.size(); ++k) tets.row(static_cast<Index>(k)) = problem.mesh.tets.row(selected[k]);
  const Triangles region_faces = mesh::boundary_triangles(tets);
  std::set<std::array<Index, 3>> keys;
  for (Index f = 0; f < region_faces.rows(); ++f)
    keys.insert(sorted_face(region_faces(f, 0), region_faces(f, 1), region_faces(f, 2)));
  std::vector<Index> rows;
  for (Index f = 0; f < all_boundary.rows(); ++f)
    if (keys.count(sorted_face(all_boundary(f, 0), all_boundary(f, 1), all_boundary(f, 2)))) rows.push_back(f);
  Triangles out(static_cast<Index>(rows.size()), 3);
  for (std::size_t k = 0; k < rows.size(); ++k) out.row(static_cast<Index>(k)) = all_boundary.row(rows[k]);
  return out;
}

/// One body of the problem as a mesh of its own (local node numbering, names without the
/// "<body>/" prefix), for node selectors.
mesh::TetMesh body_mesh(const fem::Problem& problem, const fem::BodyRange& body) {
  const auto& all = problem.mesh;
  const std::string prefix = body.name + "/";
  auto local_name = [&](const std::string& name) {
    return name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name;
  };
  mesh::TetMesh m;
  m.rest = all.rest.middleRows(body.first_node, body.num_nodes);
  m.tets = all.tets.middleRows(body.first_tet, body.num_tets).array() - body.first_node;
  m.region = all.region.segment(body.first_tet, body.num_tets);
  for (const auto& name : all.region_names) m.region_names.push_back(local_name(name));
  for (const auto& [name, nodes] : all.node_sets) {
    if (name.rfind(prefix, 0) != 0) continue;
    auto& local = m.node_sets[local_name(name)];
    for (const Index v : nodes) local.push_back(v - body.first_node);
  }
  for (const auto& [name, faces] : all.face_sets)
    if (name.rfind(prefix, 0) == 0) m.face_sets[local_name(name)] = faces.array() - body.first_node;
  for (const auto& [name, values] : all.node_fields)
    if (name.rfind(prefix, 0) == 0) m.node_fields[local_name(name)] = values.segment(body.first_node, body.num_nodes);
  for (const auto& [name, reason] : all.skipped_node_fields)
    if (name.rfind(prefix, 0) == 0) m.skipped_node_fields[local_name(name)] = reason;
  return m;
}

std::string joined_names(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

/// Nodal depths from the node field `name` of a body's own mesh (local numbering). Throws
/// InputError (without a path) when the field is absent or unusable, or a value is negative or
/// not finite.
VectorX depth_from_field(const mesh::TetMesh& local, const std::string& name) {
  if (const auto skipped = local.skipped_node_fields.find(name); skipped != local.skipped_node_fields.end())
    throw InputError(fmt::format("the mesh file's node field \"{}\" cannot be used: {}", name, skipped->second));
  const auto field = local.node_fields.find(name);
  if (field == local.node_fields.end()) {
    std::vector<std::string> names;
    for (const auto& entry : local.node_fields) names.push_back(entry.first);
    for (const auto& [skipped_name, reason] : local.skipped_node_fields)
      names.push_back(skipped_name + " (unusable: " + reason + ")");
    throw InputError(
        fmt::format("the mesh file has no node field \"{}\" (fields: {})", name, joined_names(names)));
  }
  const VectorX& values = field->second;
  Index bad = 0, first = -1;
  for (Index v = 0; v < values.size(); ++v) {
    if (std::isfinite(values[v]) && values[v] >= 0) continue;
    if (bad++ == 0) first = v;
  }
  if (bad > 0) {
    const auto x = local.rest.row(first);
    const std::string more =
        bad > 1 ? fmt::format(", and {} more node{} with a negative or non-finite value", bad - 1, bad > 2 ? "s" : "")
                : "";
    throw InputError(fmt::format(
        "node field \"{}\" has value {} at node {} (rest position ({:g}, {:g}, {:g})){}; depths must be finite and >= 0",
        name, values[first], first, x(0), x(1), x(2), more));
  }
  return values;
}

/// Largest angle between a face's normal and a plane selector's normal for the face to lie in
/// that plane: a cut's cap faces are parallel to it (to round-off), the side walls that meet
/// the cut are far from it.
constexpr double kPlaneFaceAngleDeg = 30;

/// True when face f of `boundary` (global node rows; `local` holds the body's nodes from
/// `first_node` on) lies in a plane with unit normal `unit_normal`: its normal within
/// kPlaneFaceAngleDeg of ±unit_normal.
bool face_lies_in_plane(const mesh::TetMesh& local, const Triangles& boundary, Index f, Index first_node,
                        const Vector3& unit_normal) {
  static const double min_cosine = std::cos(kPlaneFaceAngleDeg * M_PI / 180);
  const Vector3 a = local.rest.row(boundary(f, 0) - first_node), b = local.rest.row(boundary(f, 1) - first_node),
                c = local.rest.row(boundary(f, 2) - first_node);
  const Vector3 normal = (b - a).cross(c - a);
  const double length = normal.norm();
  if (!(length > 0)) return true;  // degenerate: its nodes decide
  return std::abs(normal.dot(unit_normal)) >= min_cosine * length;
}

/// The faces of `boundary` whose three nodes are all chosen by one of `selectors` (of body
/// `body`), or with `keep_chosen` false the other faces; nothing after an error of a selector
/// (each appended to `errors` as "<path>.<key>[k]: ..."). A plane selector chooses only the
/// faces that lie in its plane (face_lies_in_plane): a side wall that meets a cut plane has
/// faces whose nodes are all within the plane's tolerance near the cut, and they are not the
/// cut (docs/contact.md, "Faces in one plane").
std::optional<Triangles> faces_chosen_by(const fem::Problem& problem, const fem::BodyRange& body,
                                         const std::vector<NodeSelector>& selectors, const Triangles& boundary,
                                         const std::string& path, const char* key, std::vector<std::string>& errors,
                                         bool keep_chosen = true) {
  const mesh::TetMesh local = body_mesh(problem, body);
  std::vector<char> in_surface(static_cast<std::size_t>(boundary.rows()), 0);
  bool failed = false;
  for (std::size_t s = 0; s < selectors.size(); ++s) {
    std::vector<char> chosen(static_cast<std::size_t>(body.num_nodes), 0);
    try {
      for (const Index v : select_nodes(local, selectors[s])) chosen[static_cast<std::size_t>(v)] = 1;
    } catch (const InputError& e) {
      errors.push_back(fmt::format("{}.{}[{}]: {}", path, key, s, e.what()));
      failed = true;
      continue;
    }
    const bool plane = selectors[s].kind == NodeSelector::Kind::Plane;
    const Vector3 unit_normal = plane ? Vector3(selectors[s].normal.normalized()) : Vector3::Zero();
    for (Index f = 0; f < boundary.rows(); ++f) {
      bool all = true;
      for (int k = 0; k < 3; ++k) all = all && chosen[static_cast<std::size_t>(boundary(f, k) - body.first_node)];
      if (all && plane) all = face_lies_in_plane(local, boundary, f, body.first_node, unit_normal);
      if (all) in_surface[static_cast<std::size_t>(f)] = 1;
    }
  }
  if (failed) return std::nullopt;
  std::vector<Index> rows;
  for (Index f = 0; f < boundary.rows(); ++f)
    if ((in_surface[static_cast<std::size_t>(f)] != 0) == keep_chosen) rows.push_back(f);
  Triangles surface(static_cast<Index>(rows.size()), 3);
  for (std::size_t k = 0; k < rows.size(); ++k) surface.row(static_cast<Index>(k)) = boundary.row(rows[k]);
  return surface;
}

/// The zero-depth surface `config` names (the whole boundary by default); nothing after an
/// error (appended to `errors`), including a surface without faces.
std::optional<Triangles> zero_depth_surface(const fem::Problem& problem, const fem::BodyRange& body,
                                            const BodyContactConfig& config, const Triangles& boundary,
                                            const std::string& path, std::vector<std::string>& errors) {
  const auto& mesh = problem.mesh;
  std::optional<Triangles> surface = boundary;
  switch (config.depth_surface) {
    case BodyContactConfig::DepthSurface::Boundary:
      break;
    case BodyContactConfig::DepthSurface::FaceSet: {
      const auto it = mesh.face_sets.find(body.name + "/" + config.depth_surface_name);
      if (it == mesh.face_sets.end()) {
        std::string known;
        for (const auto& [name, faces] : mesh.face_sets)
          if (name.rfind(body.name + "/", 0) == 0) known += (known.empty() ? "" : ", ") + name.substr(body.name.size() + 1);
        errors.push_back(fmt::format("{}.depth_face_set: body \"{}\" has no face set \"{}\" (it has: {})", path,
                                     body.name, config.depth_surface_name, known.empty() ? "none" : known));
        return std::nullopt;
      }
      // Only the faces of the set that are in `boundary` (without the excluded faces).
      std::set<std::array<Index, 3>> keys;
      for (Index f = 0; f < boundary.rows(); ++f) keys.insert(sorted_face(boundary(f, 0), boundary(f, 1), boundary(f, 2)));
      std::vector<Index> rows;
      for (Index f = 0; f < it->second.rows(); ++f)
        if (keys.count(sorted_face(it->second(f, 0), it->second(f, 1), it->second(f, 2)))) rows.push_back(f);
      surface = Triangles(static_cast<Index>(rows.size()), 3);
      for (std::size_t k = 0; k < rows.size(); ++k) surface->row(static_cast<Index>(k)) = it->second.row(rows[k]);
      break;
    }
    case BodyContactConfig::DepthSurface::Nodes:
      surface = faces_chosen_by(problem, body, config.depth_nodes, boundary, path, "depth_nodes", errors);
      if (!surface) return std::nullopt;
      break;
    case BodyContactConfig::DepthSurface::Region: {
      const std::string key = body.name + "/" + config.depth_surface_name;
      const auto it = std::find(mesh.region_names.begin(), mesh.region_names.end(), key);
      if (it == mesh.region_names.end()) {
        errors.push_back(fmt::format("{}.depth_region: body \"{}\" has no region \"{}\"", path, body.name,
                                     config.depth_surface_name));
        return std::nullopt;
      }
      surface = region_boundary(boundary, problem, body, static_cast<Index>(it - mesh.region_names.begin()));
      break;
    }
  }
  if (surface->rows() == 0) {
    errors.push_back(fmt::format("{}: the zero-depth surface of body \"{}\" has no face", path, body.name));
    return std::nullopt;
  }
  return surface;
}

}  // namespace

std::array<Index, 3> sorted_face(Index a, Index b, Index c) {
  std::array<Index, 3> f{a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}

Triangles body_boundary(const fem::Problem& problem, const fem::BodyRange& body) {
  return mesh::boundary_triangles(problem.mesh.tets.middleRows(body.first_tet, body.num_tets));
}

Triangles contact_surface(const fem::Problem& problem, const fem::BodyRange& body, const BodyContactConfig& config,
                          const Triangles& boundary, const std::string& path, std::vector<std::string>& errors) {
  if (config.exclude_faces.empty()) return boundary;
  std::optional<Triangles> kept =
      faces_chosen_by(problem, body, config.exclude_faces, boundary, path, "exclude_faces", errors, false);
  if (!kept) return boundary;
  if (kept->rows() == 0) {
    errors.push_back(fmt::format("{}.exclude_faces: excludes every boundary face of body \"{}\"", path, body.name));
    return boundary;
  }
  return *kept;
}

VectorX read_depth_file(const std::string& path, Index expected) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("depth file {}: cannot be opened", path));
  std::vector<double> values;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      double v = 0;
      std::size_t used = 0;
      try {
        v = std::stod(word, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != word.size())
        throw InputError(fmt::format("depth file {} line {}: \"{}\" is not a number", path, line_number, word));
      if (!std::isfinite(v) || v < 0)
        throw InputError(
            fmt::format("depth file {} line {}: depth {} must be finite and >= 0", path, line_number, word));
      values.push_back(v);
    }
  }
  if (static_cast<Index>(values.size()) != expected)
    throw InputError(fmt::format("depth file {}: has {} depths, the body's mesh has {} nodes", path, values.size(),
                                 expected));
  return Eigen::Map<const VectorX>(values.data(), static_cast<Eigen::Index>(values.size()));
}

VectorX body_depths(const fem::Problem& problem, const fem::BodyRange& body, const BodyContactConfig& config,
                    const Triangles& boundary, const std::string& path, std::vector<std::string>& errors) {
  try {
    if (!config.depth_file.empty()) return read_depth_file(config.depth_file, body.num_nodes);
  } catch (const InputError& e) {
    errors.push_back(fmt::format("{}.depth_file: {}", path, e.what()));
    return {};
  }
  try {
    if (!config.depth_field.empty()) return depth_from_field(body_mesh(problem, body), config.depth_field);
  } catch (const InputError& e) {
    errors.push_back(fmt::format("{}.depth_field: {}", path, e.what()));
    return {};
  }
  const std::optional<Triangles> surface = zero_depth_surface(problem, body, config, boundary, path, errors);
  if (!surface) return {};
  std::vector<Index> nodes(static_cast<std::size_t>(body.num_nodes));
  for (Index i = 0; i < body.num_nodes; ++i) nodes[static_cast<std::size_t>(i)] = body.first_node + i;
  try {
    return collision::material_depth(problem.mesh.rest, *surface, nodes);
  } catch (const InputError& e) {
    errors.push_back(fmt::format("{}: {}", path, e.what()));
    return {};
  }
}

}  // namespace sinew::scene
