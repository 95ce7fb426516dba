#pragma once
/// @file build_contact.hpp
/// SceneConfig + fem::Problem -> the contact module's plain input: every body's boundary
/// triangles and tets, the nodal material depths (from each body's zero-depth surface, a depth
/// file, or a node field of its mesh file), and the penalty of every pair of bodies (explicit,
/// or the automatic default).

#include <string>
#include <vector>

#include "sinew/contact/contact_energy.hpp"
#include "sinew/fem/problem.hpp"
#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

struct ContactSetup {
  contact::ContactGeometry geometry;
  contact::ContactOptions options;
  std::vector<std::string> body_names;  ///< index = body id in the geometry
  std::vector<double> body_young_modulus;  ///< initial E per body (+inf for all-rigid bodies)
  std::vector<double> body_edge_length;    ///< mean boundary edge length per body (length)
  double largest_penalty_scale = 1;        ///< largest contact_penalty_scale of any region
};

/// A pair's penalty (times the largest contact_penalty_scale) may be at most this many times
/// the automatic penalty 10 E / h of the pair: stiffer contact leaves Newton crawling.
inline constexpr double kMaxPenaltyOverAutomatic = 1e5;

/// Requires scene.contact.enabled. Throws InputError, each message naming the config path, for:
/// a depth face set or region the body does not have, a depth file that cannot be read, has
/// the wrong count of numbers or a negative/non-finite value, a depth field the mesh file does
/// not have (the fields it has are listed) or cannot use (not scalar, not at every node), or with
/// a negative/non-finite value (the first such node is named), and a pair of all-rigid bodies
/// without an explicit penalty, and a penalty above kMaxPenaltyOverAutomatic times the automatic one.
ContactSetup build_contact(const SceneConfig& scene, const fem::Problem& problem);

/// Throws InputError when a pair's penalty in `penalties` (#B x #B, force / length³) times
/// setup.largest_penalty_scale exceeds kMaxPenaltyOverAutomatic times the pair's automatic
/// penalty 10 E / h (build_contact's check, for penalties chosen after it, as model::set_contact does).
void check_penalty_bounds(const ContactSetup& setup, const MatrixX& penalties);

/// Nodal depths from a text file: whitespace-separated numbers, `expected` of them, each
/// finite and >= 0; '#' starts a comment. Throws InputError naming the file and the problem.
VectorX read_depth_file(const std::string& path, Index expected);

}  // namespace sinew::scene
