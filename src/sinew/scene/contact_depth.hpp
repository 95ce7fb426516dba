#pragma once
/// @file contact_depth.hpp
/// The nodal material depths of one body for contact (docs/theory.md, material depth): the
/// rest distance to the body's zero-depth surface (its whole boundary, a face set, the boundary
/// of a region, or the faces chosen by node selectors), or depths given by a file or a node
/// field of the body's mesh file. Internal to the scene module (build_contact.cpp).

#include <array>
#include <string>
#include <vector>

#include "sinew/fem/problem.hpp"
#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// The three node indices of a face, sorted: a key equal for every orientation of the face.
std::array<Index, 3> sorted_face(Index a, Index b, Index c);

/// The boundary triangles of one body of the problem (global node numbering).
Triangles body_boundary(const fem::Problem& problem, const fem::BodyRange& body);

/// The contact surface of one body: its boundary triangles `boundary` without the faces that
/// config.exclude_faces chooses (all three nodes chosen by one selector). On a selector error
/// appends "<path>.exclude_faces[k]: ..." to `errors` and returns `boundary`, likewise when every
/// face would be excluded.
Triangles contact_surface(const fem::Problem& problem, const fem::BodyRange& body, const BodyContactConfig& config,
                          const Triangles& boundary, const std::string& path, std::vector<std::string>& errors);

/// The depths of body `body`'s nodes (in its node order) as `config` asks, with `boundary`
/// its contact surface (contact_surface: the boundary without the excluded faces; a depth face
/// set is also restricted to it). Appends an error "<path>...: message" and returns an empty vector
/// when the configured surface, file or field is missing or unusable.
VectorX body_depths(const fem::Problem& problem, const fem::BodyRange& body, const BodyContactConfig& config,
                    const Triangles& boundary, const std::string& path, std::vector<std::string>& errors);

}  // namespace sinew::scene
