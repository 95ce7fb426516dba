#pragma once
/// @file mesh_fixtures.hpp
/// Hand-built meshes and geometric measures for the mesh tests.

#include <algorithm>
#include <array>
#include <filesystem>
#include <numeric>
#include <random>
#include <set>
#include <string>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh::testing {

/// A box [0, nx] x [0, ny] x [0, nz] (times `spacing`) of unit cubes, each split into six
/// positively oriented tets around its main diagonal (Kuhn subdivision, conforming).
inline TetMesh structured_box(int nx, int ny, int nz, double spacing = 1.0) {
  TetMesh mesh;
  const auto node = [&](int i, int j, int k) {
    return static_cast<Index>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  mesh.rest.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i)
        mesh.rest.row(node(i, j, k)) << i * spacing, j * spacing, k * spacing;
    }
  }
  // Paths from corner (0,0,0) to (1,1,1) along the 6 orderings of the axes.
  const std::array<std::array<int, 3>, 6> axis_orders = {
      {{{0, 1, 2}}, {{0, 2, 1}}, {{1, 0, 2}}, {{1, 2, 0}}, {{2, 0, 1}}, {{2, 1, 0}}}};
  mesh.tets.resize(6 * nx * ny * nz, 4);
  Index t = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        for (const auto& order : axis_orders) {
          std::array<int, 3> corner = {i, j, k};
          mesh.tets(t, 0) = node(corner[0], corner[1], corner[2]);
          for (int step = 0; step < 3; ++step) {
            ++corner[static_cast<std::size_t>(order[static_cast<std::size_t>(step)])];
            mesh.tets(t, step + 1) = node(corner[0], corner[1], corner[2]);
          }
          ++t;
        }
      }
    }
  }
  orient_positively(mesh.rest, mesh.tets);
  mesh.region = IndexVector::Zero(mesh.tets.rows());
  mesh.region_names = {"default"};
  return mesh;
}

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

/// A fresh directory under the system temp dir, removed with the object.
class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(const std::string& stem) {
    std::random_device entropy;
    path_ = std::filesystem::temp_directory_path() /
            (stem + "-" + std::to_string(entropy()) + "-" + std::to_string(entropy()));
    std::filesystem::create_directories(path_);
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace sinew::mesh::testing
