#pragma once
/// @file mesh_fixtures.hpp
/// Shuffled meshes and geometric measures for the mesh tests (and, from tests/support,
/// box_mesh, TempDir and write_text).

#include <algorithm>
#include <array>
#include <filesystem>
#include <numeric>
#include <random>
#include <set>
#include <string>

#include "sinew/core/error.hpp"
#include "sinew/mesh/read_msh.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "support/box_mesh.hpp"
#include "support/files.hpp"
#include "support/temp_dir.hpp"

namespace sinew::mesh::testing {

using sinew::testing::box_mesh;
using sinew::testing::TempDir;
using sinew::testing::write_text;

/// The same mesh with nodes renumbered and tets reordered at random, each tet's nodes rotated
/// by an even permutation (orientation kept).
inline TetMesh shuffled(const TetMesh& mesh, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<Index> new_node(static_cast<std::size_t>(mesh.num_nodes()));
  std::iota(new_node.begin(), new_node.end(), 0);
  std::shuffle(new_node.begin(), new_node.end(), random);
  std::vector<Index> tet_order(static_cast<std::size_t>(mesh.num_tets()));
  std::iota(tet_order.begin(), tet_order.end(), 0);
  std::shuffle(tet_order.begin(), tet_order.end(), random);

  TetMesh result = mesh;
  for (Index v = 0; v < mesh.num_nodes(); ++v) result.rest.row(new_node[v]) = mesh.rest.row(v);
  const std::array<std::array<int, 4>, 3> even_permutations = {
      {{{0, 1, 2, 3}}, {{1, 2, 0, 3}}, {{0, 2, 3, 1}}}};
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    const Index source = tet_order[t];
    const auto& permutation = even_permutations[random() % 3];
    for (int k = 0; k < 4; ++k) result.tets(t, k) = new_node[mesh.tets(source, permutation[k])];
    result.region(t) = mesh.region(source);
  }
  return result;
}

inline double total_volume(const Positions& x, const Tets& tets) {
  double volume = 0;
  for (Index t = 0; t < tets.rows(); ++t) volume += signed_volume(x, tets, t);
  return volume;
}

inline Vector3 triangle_area_vector(const Positions& x, const Triangles& triangles, Index f) {
  const Vector3 a = x.row(triangles(f, 0)).transpose();
  const Vector3 b = x.row(triangles(f, 1)).transpose();
  const Vector3 c = x.row(triangles(f, 2)).transpose();
  return 0.5 * (b - a).cross(c - a);
}

inline double total_area(const Positions& x, const Triangles& triangles) {
  double area = 0;
  for (Index f = 0; f < triangles.rows(); ++f) area += triangle_area_vector(x, triangles, f).norm();
  return area;
}

/// Volume enclosed by a closed triangulated surface (divergence theorem); positive when the
/// triangles are oriented outward.
inline double enclosed_volume(const Positions& x, const Triangles& triangles) {
  double volume = 0;
  for (Index f = 0; f < triangles.rows(); ++f) {
    const Vector3 a = x.row(triangles(f, 0)).transpose();
    const Vector3 b = x.row(triangles(f, 1)).transpose();
    const Vector3 c = x.row(triangles(f, 2)).transpose();
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

/// V - E + F of a triangulated surface (counting only the nodes it uses).
inline Index euler_characteristic(const Triangles& triangles) {
  std::set<Index> nodes;
  std::set<std::pair<Index, Index>> edges;
  for (Index f = 0; f < triangles.rows(); ++f) {
    for (int e = 0; e < 3; ++e) {
      const Index a = triangles(f, e);
      const Index b = triangles(f, (e + 1) % 3);
      nodes.insert(a);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return static_cast<Index>(nodes.size()) - static_cast<Index>(edges.size()) +
         static_cast<Index>(triangles.rows());
}

/// True when every directed edge of the surface appears once and its reverse once: a closed,
/// consistently oriented 2-manifold (edge-wise).
inline bool is_closed_oriented_surface(const Triangles& triangles) {
  std::multiset<std::pair<Index, Index>> directed;
  for (Index f = 0; f < triangles.rows(); ++f) {
    for (int e = 0; e < 3; ++e) directed.insert({triangles(f, e), triangles(f, (e + 1) % 3)});
  }
  for (const auto& [a, b] : directed) {
    if (directed.count({a, b}) != 1 || directed.count({b, a}) != 1) return false;
  }
  return true;
}

/// The InputError message read_msh gives for `path`, or "no error".
inline std::string read_msh_error(const std::string& path) {
  try {
    read_msh(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace sinew::mesh::testing
