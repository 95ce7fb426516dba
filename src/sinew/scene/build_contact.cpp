/// @file build_contact.cpp
/// SceneConfig + fem::Problem -> the contact module's input (see build_contact.hpp): the
/// bodies' surfaces and tets, their material depths (contact_depth.cpp), the per-region penalty
/// factors and the penalty of every pair of bodies.

#include "sinew/scene/build_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/scene/contact_depth.hpp"

namespace sinew::scene {
namespace {

/// The penalty scale of the reference penalty 10 E / h that explicit penalties are compared
/// with (kMaxPenaltyOverAutomatic).
constexpr double kReferencePenaltyScale = 10;

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

/// The smallest initial Young's modulus of the body's deformable tets; +inf for a body whose
/// tets are all rigid.
double body_young_modulus(const fem::Problem& problem, const fem::BodyRange& body) {
  double E = std::numeric_limits<double>::infinity();
  for (Index t = body.first_tet; t < body.first_tet + body.num_tets; ++t)
    if (const auto& law = problem.region_material[static_cast<std::size_t>(problem.mesh.region[t])])
      E = std::min(E, young_modulus(*law));
  return E;
}

/// E and h of a pair of bodies: the smaller Young's modulus (a rigid body takes the other's)
/// and the smaller mean boundary edge length.
std::pair<double, double> pair_modulus_and_length(const ContactSetup& setup, Index a, Index b) {
  const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  return {std::min(setup.body_young_modulus[i], setup.body_young_modulus[j]),
          std::min(setup.body_edge_length[i], setup.body_edge_length[j])};
}

/// The automatic penalty scale * E / h of bodies a and b (docs/scene-reference.md, contact:
/// penalty_scale); nothing when both are rigid (no E).
std::optional<double> automatic_penalty(const ContactSetup& setup, Index a, Index b, double scale) {
  const auto [E, h] = pair_modulus_and_length(setup, a, b);
  if (!std::isfinite(E)) return std::nullopt;
  return scale * E / h;
}

/// Per mesh region: its contact_penalty_scale, from its own entry or else its body's "*" entry
/// (as build_problem chooses), 1 for a region without either.
VectorX region_penalty_scales(const SceneConfig& scene, const fem::Problem& problem) {
  const auto& names = problem.mesh.region_names;
  VectorX scale = VectorX::Ones(static_cast<Index>(names.size()));
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const std::string prefix = problem.bodies[b].name + "/";
    const auto& regions = scene.bodies[b].regions;
    for (std::size_t r = 0; r < names.size(); ++r) {
      if (names[r].rfind(prefix, 0) != 0) continue;
      auto entry = regions.find(names[r].substr(prefix.size()));
      if (entry == regions.end()) entry = regions.find("*");
      if (entry != regions.end()) scale[static_cast<Index>(r)] = entry->second.contact_penalty_scale;
    }
  }
  return scale;
}

/// Fills the geometry's surface (every body's contact surface, in body order), its body ids and, when
/// a region scales its penalty, the factors of every tet and surface triangle: a tet takes its
/// region's, a surface triangle the region of the tet it bounds. Left empty (all 1) otherwise.
void assemble_surfaces(const std::vector<Triangles>& surfaces, const VectorX& region_scale,
                       const fem::Problem& problem, contact::ContactGeometry& g) {
  const auto& mesh = problem.mesh;
  Index total = 0;
  for (const auto& s : surfaces) total += static_cast<Index>(s.rows());
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
  for (std::size_t b = 0; b < surfaces.size(); ++b) {
    const auto& s = surfaces[b];
    g.surface.middleRows(row, s.rows()) = s;
    g.surface_body.segment(row, s.rows()).setConstant(static_cast<Index>(b));
    if (scaled)
      for (Index f = 0; f < s.rows(); ++f)
        g.surface_penalty_scale[row + f] = region_scale[face_region.at(sorted_face(s(f, 0), s(f, 1), s(f, 2)))];
    row += static_cast<Index>(s.rows());
  }
}

/// The penalty of every pair of bodies: a pair's own entry (its penalty, or 0 when disabled),
/// else the global penalty, else the automatic one; self-contact only when enabled. Two rigid
/// bodies have no automatic penalty: not in contact by default, an error for a listed pair.
MatrixX pair_penalties(const ContactConfig& config, const ContactSetup& setup, std::vector<std::string>& errors) {
  const Index bodies = static_cast<Index>(setup.body_names.size());
  auto index_of = [&](const std::string& name) {
    return static_cast<Index>(std::find(setup.body_names.begin(), setup.body_names.end(), name) -
                              setup.body_names.begin());
  };
  MatrixX penalty = MatrixX::Zero(bodies, bodies);
  std::set<std::pair<Index, Index>> listed;
  for (const ContactPairConfig& pair : config.pairs) {
    const Index a = index_of(pair.body_a), b = index_of(pair.body_b);
    listed.insert({std::min(a, b), std::max(a, b)});
  }
  for (Index a = 0; a < bodies; ++a)
    for (Index b = a; b < bodies; ++b) {
      if ((a == b && !config.self_contact) || listed.count({a, b})) continue;
      const std::optional<double> value =
          config.penalty ? config.penalty : automatic_penalty(setup, a, b, config.penalty_scale);
      if (value) penalty(a, b) = penalty(b, a) = *value;
    }
  for (std::size_t k = 0; k < config.pairs.size(); ++k) {
    const ContactPairConfig& pair = config.pairs[k];
    const Index a = index_of(pair.body_a), b = index_of(pair.body_b);
    std::optional<double> value = 0.0;
    if (pair.enabled) {
      value = pair.penalty ? pair.penalty
                           : config.penalty ? config.penalty : automatic_penalty(setup, a, b, config.penalty_scale);
    }
    if (!value) {
      errors.push_back(fmt::format("contact.pairs[{}]: bodies \"{}\" and \"{}\" are both rigid, so there is no "
                                   "automatic penalty; give \"penalty\"",
                                   k, pair.body_a, pair.body_b));
      continue;
    }
    penalty(a, b) = penalty(b, a) = *value;
  }
  return penalty;
}

/// Refuses penalties far above the reference 10 E / h. Such a penalty makes the contact far
/// stiffer than the solids: Newton then crawls through thousands of tiny steps (1e15 on the
/// Hertz ball ran past 300 s; 1e5, 11 000 times the automatic one, took 45 s).
void check_penalties(const ContactSetup& setup, const MatrixX& penalties, double largest_scale,
                     std::vector<std::string>& errors) {
  const Index bodies = penalties.rows();
  for (Index a = 0; a < bodies; ++a)
    for (Index b = a; b < bodies; ++b) {
      const std::optional<double> reference = automatic_penalty(setup, a, b, kReferencePenaltyScale);
      const double penalty = penalties(a, b) * largest_scale;
      if (!(penalty > 0) || !reference || !std::isfinite(*reference) || !(*reference > 0)) continue;
      if (penalty <= kMaxPenaltyOverAutomatic * *reference) continue;
      const auto [E, h] = pair_modulus_and_length(setup, a, b);
      errors.push_back(fmt::format(
          "contact: the penalty between \"{}\" and \"{}\" ({:g}{}) is {:.3g} times the automatic penalty 10 E / h = "
          "{:.4g} (E = {:.4g}, h = {:.4g}); above {:g} times the contact is too stiff for Newton to follow: lower it "
          "(the automatic penalty keeps penetration to a few percent of an element)",
          setup.body_names[static_cast<std::size_t>(a)], setup.body_names[static_cast<std::size_t>(b)], penalty,
          largest_scale != 1 ? fmt::format(", with contact_penalty_scale {:g}", largest_scale) : std::string(),
          penalty / *reference, *reference, E, h, kMaxPenaltyOverAutomatic));
    }
}

}  // namespace

void check_penalty_bounds(const ContactSetup& setup, const MatrixX& penalties) {
  std::vector<std::string> errors;
  check_penalties(setup, penalties, setup.largest_penalty_scale, errors);
  if (errors.empty()) return;
  std::string message = errors.front();
  for (std::size_t k = 1; k < errors.size(); ++k) message += "\n  " + errors[k];
  throw InputError(message);
}

ContactSetup build_contact(const SceneConfig& scene, const fem::Problem& problem) {
  ContactSetup setup;
  setup.options.method = scene.contact.method;
  setup.options.hessian = scene.contact.hessian;
  const auto& mesh = problem.mesh;
  auto& g = setup.geometry;
  g.depth = VectorX::Zero(mesh.num_nodes());
  g.tets = mesh.tets;
  g.tet_body.resize(mesh.num_tets());
  std::vector<Triangles> surfaces;
  std::vector<std::string> errors;
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const fem::BodyRange& body = problem.bodies[b];
    setup.body_names.push_back(body.name);
    g.tet_body.segment(body.first_tet, body.num_tets).setConstant(static_cast<Index>(b));
    const std::string path = fmt::format("bodies[{}].contact", b);
    surfaces.push_back(contact_surface(problem, body, scene.bodies[b].contact, body_boundary(problem, body), path, errors));
    setup.body_edge_length.push_back(mean_edge_length(mesh.rest, surfaces.back()));
    setup.body_young_modulus.push_back(body_young_modulus(problem, body));
    const VectorX depths = body_depths(problem, body, scene.bodies[b].contact, surfaces.back(), path, errors);
    if (depths.size() == body.num_nodes) g.depth.segment(body.first_node, body.num_nodes) = depths;
  }
  const VectorX region_scale = region_penalty_scales(scene, problem);
  assemble_surfaces(surfaces, region_scale, problem, g);
  g.penalty = pair_penalties(scene.contact, setup, errors);
  setup.largest_penalty_scale = region_scale.maxCoeff();
  check_penalties(setup, g.penalty, setup.largest_penalty_scale, errors);
  if (!errors.empty()) {
    std::string message = "the scene's contact set-up has errors:";
    for (const auto& e : errors) message += "\n  " + e;
    throw InputError(message);
  }
  return setup;
}

}  // namespace sinew::scene
