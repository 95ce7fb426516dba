#include "sinew/scene/build_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "sinew/collision/material_depth.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/scene/build_problem.hpp"

namespace sinew::scene {
namespace {

std::array<Index, 3> sorted_face(Index a, Index b, Index c) {
  std::array<Index, 3> f{a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}

Tets body_tets(const fem::Problem& problem, const fem::BodyRange& body) {
  return problem.mesh.tets.middleRows(body.first_tet, body.num_tets);
}

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

double young_modulus(const material::Material& law) {
  const double mu = law.initial_shear_modulus(), kappa = law.initial_bulk_modulus();
  return 9 * kappa * mu / (3 * kappa + mu);
}

double mean_edge_length(const Positions& x, const Triangles& triangles) {
  double sum = 0;
  for (Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (x.row(triangles(f, k)) - x.row(triangles(f, (k + 1) % 3))).norm();
  return triangles.rows() > 0 ? sum / (3.0 * static_cast<double>(triangles.rows())) : 0.0;
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

}  // namespace

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

ContactSetup build_contact(const SceneConfig& scene, const fem::Problem& problem) {
  const ContactConfig& config = scene.contact;
  ContactSetup setup;
  setup.options.method = config.method;
  setup.options.hessian = config.hessian;
  const auto& mesh = problem.mesh;
  const Index bodies = static_cast<Index>(problem.bodies.size());
  auto& g = setup.geometry;
  g.depth = VectorX::Zero(mesh.num_nodes());
  g.tets = mesh.tets;
  g.tet_body.resize(mesh.num_tets());
  std::vector<Triangles> surfaces;
  std::vector<std::string> errors;
  for (Index b = 0; b < bodies; ++b) {
    const fem::BodyRange& body = problem.bodies[static_cast<std::size_t>(b)];
    const BodyConfig& body_config = scene.bodies[static_cast<std::size_t>(b)];
    const std::string path = fmt::format("bodies[{}].contact", b);
    setup.body_names.push_back(body.name);
    g.tet_body.segment(body.first_tet, body.num_tets).setConstant(b);
    const Triangles boundary = mesh::boundary_triangles(body_tets(problem, body));
    surfaces.push_back(boundary);
    setup.body_edge_length.push_back(mean_edge_length(mesh.rest, boundary));
    double E = std::numeric_limits<double>::infinity();
    for (Index t = body.first_tet; t < body.first_tet + body.num_tets; ++t)
      if (const auto& law = problem.region_material[static_cast<std::size_t>(mesh.region[t])])
        E = std::min(E, young_modulus(*law));
    setup.body_young_modulus.push_back(E);

    const BodyContactConfig& c = body_config.contact;
    if (!c.depth_file.empty()) {
      try {
        g.depth.segment(body.first_node, body.num_nodes) = read_depth_file(c.depth_file, body.num_nodes);
      } catch (const InputError& e) {
        errors.push_back(fmt::format("{}.depth_file: {}", path, e.what()));
      }
      continue;
    }
    if (!c.depth_field.empty()) {
      try {
        g.depth.segment(body.first_node, body.num_nodes) = depth_from_field(body_mesh(problem, body), c.depth_field);
      } catch (const InputError& e) {
        errors.push_back(fmt::format("{}.depth_field: {}", path, e.what()));
      }
      continue;
    }
    Triangles zero_surface = boundary;
    if (c.depth_surface == BodyContactConfig::DepthSurface::FaceSet) {
      const std::string key = body.name + "/" + c.depth_surface_name;
      const auto it = mesh.face_sets.find(key);
      if (it == mesh.face_sets.end()) {
        std::string known;
        for (const auto& [name, faces] : mesh.face_sets)
          if (name.rfind(body.name + "/", 0) == 0) known += (known.empty() ? "" : ", ") + name.substr(body.name.size() + 1);
        errors.push_back(fmt::format("{}.depth_face_set: body \"{}\" has no face set \"{}\" (it has: {})", path,
                                     body.name, c.depth_surface_name, known.empty() ? "none" : known));
        continue;
      }
      zero_surface = it->second;
    } else if (c.depth_surface == BodyContactConfig::DepthSurface::Nodes) {
      const mesh::TetMesh local = body_mesh(problem, body);
      std::vector<char> in_surface(static_cast<std::size_t>(boundary.rows()), 0);
      bool failed = false;
      for (std::size_t s = 0; s < c.depth_nodes.size(); ++s) {
        std::vector<char> chosen(static_cast<std::size_t>(body.num_nodes), 0);
        try {
          for (const Index v : select_nodes(local, c.depth_nodes[s])) chosen[static_cast<std::size_t>(v)] = 1;
        } catch (const InputError& e) {
          errors.push_back(fmt::format("{}.depth_nodes[{}]: {}", path, s, e.what()));
          failed = true;
          continue;
        }
        for (Index f = 0; f < boundary.rows(); ++f) {
          bool all = true;
          for (int k = 0; k < 3; ++k) all = all && chosen[static_cast<std::size_t>(boundary(f, k) - body.first_node)];
          if (all) in_surface[static_cast<std::size_t>(f)] = 1;
        }
      }
      if (failed) continue;
      std::vector<Index> rows;
      for (Index f = 0; f < boundary.rows(); ++f)
        if (in_surface[static_cast<std::size_t>(f)]) rows.push_back(f);
      zero_surface.resize(static_cast<Index>(rows.size()), 3);
      for (std::size_t k = 0; k < rows.size(); ++k) zero_surface.row(static_cast<Index>(k)) = boundary.row(rows[k]);
    } else if (c.depth_surface == BodyContactConfig::DepthSurface::Region) {
      const std::string key = body.name + "/" + c.depth_surface_name;
      const auto it = std::find(mesh.region_names.begin(), mesh.region_names.end(), key);
      if (it == mesh.region_names.end()) {
        errors.push_back(fmt::format("{}.depth_region: body \"{}\" has no region \"{}\"", path, body.name,
                                     c.depth_surface_name));
        continue;
      }
      zero_surface = region_boundary(boundary, problem, body, static_cast<Index>(it - mesh.region_names.begin()));
    }
    if (zero_surface.rows() == 0) {
      errors.push_back(fmt::format("{}: the zero-depth surface of body \"{}\" has no face", path, body.name));
      continue;
    }
    std::vector<Index> nodes(static_cast<std::size_t>(body.num_nodes));
    for (Index i = 0; i < body.num_nodes; ++i) nodes[static_cast<std::size_t>(i)] = body.first_node + i;
    g.depth.segment(body.first_node, body.num_nodes) = collision::material_depth(mesh.rest, zero_surface, nodes);
  }

  Index total = 0;
  for (const auto& s : surfaces) total += static_cast<Index>(s.rows());
  // Per-region penalty factors: on every tet of the region and on the surface triangles whose
  // tet is in the region. Left empty (all 1) when no region sets one.
  // A region takes its own entry's factor, else the body's "*" entry's (as build_problem does).
  VectorX region_scale = VectorX::Ones(static_cast<Index>(mesh.region_names.size()));
  for (Index b = 0; b < bodies; ++b) {
    const std::string prefix = problem.bodies[static_cast<std::size_t>(b)].name + "/";
    const auto& regions = scene.bodies[static_cast<std::size_t>(b)].regions;
    for (std::size_t r = 0; r < mesh.region_names.size(); ++r) {
      const std::string& global = mesh.region_names[r];
      if (global.rfind(prefix, 0) != 0) continue;
      auto entry = regions.find(global.substr(prefix.size()));
      if (entry == regions.end()) entry = regions.find("*");
      if (entry != regions.end()) region_scale[static_cast<Index>(r)] = entry->second.contact_penalty_scale;
    }
  }
  const bool scaled = (region_scale.array() != 1.0).any();
  std::map<std::array<Index, 3>, Index> face_region;  // boundary face -> region of its tet
  if (scaled) {
    g.tet_penalty_scale.resize(mesh.num_tets());
    for (Index t = 0; t < mesh.num_tets(); ++t) {
      g.tet_penalty_scale[t] = region_scale[mesh.region[t]];
      const auto v = mesh.tets.row(t);
      static constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      for (const auto& face : kFaces) face_region[sorted_face(v[face[0]], v[face[1]], v[face[2]])] = mesh.region[t];
    }
    g.surface_penalty_scale.resize(total);
  }
  g.surface.resize(total, 3);
  g.surface_body.resize(total);
  Index row = 0;
  for (Index b = 0; b < bodies; ++b) {
    const auto& s = surfaces[static_cast<std::size_t>(b)];
    g.surface.middleRows(row, s.rows()) = s;
    g.surface_body.segment(row, s.rows()).setConstant(b);
    if (scaled)
      for (Index f = 0; f < s.rows(); ++f)
        g.surface_penalty_scale[row + f] = region_scale[face_region.at(sorted_face(s(f, 0), s(f, 1), s(f, 2)))];
    row += static_cast<Index>(s.rows());
  }

  // Penalties: explicit pair > global > automatic.
  g.penalty = MatrixX::Zero(bodies, bodies);
  auto index_of = [&](const std::string& name) {
    return static_cast<Index>(std::find(setup.body_names.begin(), setup.body_names.end(), name) - setup.body_names.begin());
  };
  std::set<std::pair<Index, Index>> explicit_pairs;
  for (const ContactPairConfig& pair : config.pairs) {
    const Index a = index_of(pair.body_a), b = index_of(pair.body_b);
    explicit_pairs.insert({std::min(a, b), std::max(a, b)});
  }
  for (Index a = 0; a < bodies; ++a)
    for (Index b = a; b < bodies; ++b) {
      if (a == b && !config.self_contact) continue;
      if (explicit_pairs.count({a, b})) continue;
      double penalty = 0;
      if (config.penalty) {
        penalty = *config.penalty;
      } else {
        const double E = std::min(setup.body_young_modulus[static_cast<std::size_t>(a)],
                                  setup.body_young_modulus[static_cast<std::size_t>(b)]);
        const double h = std::min(setup.body_edge_length[static_cast<std::size_t>(a)],
                                  setup.body_edge_length[static_cast<std::size_t>(b)]);
        if (!std::isfinite(E)) continue;  // two rigid bodies: no automatic penalty (see below)
        penalty = config.penalty_scale * E / h;
      }
      g.penalty(a, b) = g.penalty(b, a) = penalty;
    }
  for (std::size_t k = 0; k < config.pairs.size(); ++k) {
    const ContactPairConfig& pair = config.pairs[k];
    const Index a = index_of(pair.body_a), b = index_of(pair.body_b);
    double penalty = 0;
    if (pair.enabled) {
      if (pair.penalty) {
        penalty = *pair.penalty;
      } else if (config.penalty) {
        penalty = *config.penalty;
      } else {
        const double E = std::min(setup.body_young_modulus[static_cast<std::size_t>(a)],
                                  setup.body_young_modulus[static_cast<std::size_t>(b)]);
        if (!std::isfinite(E)) {
          errors.push_back(fmt::format("contact.pairs[{}]: bodies \"{}\" and \"{}\" are both rigid, so there is no "
                                       "automatic penalty; give \"penalty\"",
                                       k, pair.body_a, pair.body_b));
          continue;
        }
        penalty = config.penalty_scale * E /
                  std::min(setup.body_edge_length[static_cast<std::size_t>(a)],
                           setup.body_edge_length[static_cast<std::size_t>(b)]);
      }
    }
    g.penalty(a, b) = g.penalty(b, a) = penalty;
  }
  // A penalty far above the automatic one (10 E / h) makes the contact far stiffer than the
  // solids: Newton then crawls through thousands of tiny steps (1e15 on the Hertz ball ran past
  // 300 s; 1e5, 11 000 times the automatic one, took 45 s). Such penalties are refused.
  const double largest_scale = region_scale.maxCoeff();
  for (Index a = 0; a < bodies; ++a)
    for (Index b = a; b < bodies; ++b) {
      const double E = std::min(setup.body_young_modulus[static_cast<std::size_t>(a)],
                                setup.body_young_modulus[static_cast<std::size_t>(b)]);
      const double h = std::min(setup.body_edge_length[static_cast<std::size_t>(a)],
                                setup.body_edge_length[static_cast<std::size_t>(b)]);
      const double automatic = 10 * E / h;
      const double penalty = g.penalty(a, b) * largest_scale;
      if (!(penalty > 0) || !std::isfinite(automatic) || !(automatic > 0)) continue;
      if (penalty > kMaxPenaltyOverAutomatic * automatic)
        errors.push_back(fmt::format(
            "contact: the penalty between \"{}\" and \"{}\" ({:g}{}) is {:.3g} times the automatic penalty 10 E / h = "
            "{:.4g} (E = {:.4g}, h = {:.4g}); above {:g} times the contact is too stiff for Newton to follow: lower it "
            "(the automatic penalty keeps penetration to a few percent of an element)",
            setup.body_names[static_cast<std::size_t>(a)], setup.body_names[static_cast<std::size_t>(b)], penalty,
            largest_scale != 1 ? fmt::format(", with contact_penalty_scale {:g}", largest_scale) : std::string(),
            penalty / automatic, automatic, E, h, kMaxPenaltyOverAutomatic));
    }
  if (!errors.empty()) {
    std::string message = "the scene's contact set-up has errors:";
    for (const auto& e : errors) message += "\n  " + e;
    throw InputError(message);
  }
  return setup;
}

}  // namespace sinew::scene
