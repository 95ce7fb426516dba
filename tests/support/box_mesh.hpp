#pragma once
/// @file box_mesh.hpp
/// A structured tet mesh of an axis-aligned box for tests: n_x x n_y x n_z cubes, each split into
/// six tets along its main diagonal (conforming), positively oriented. Needs no Gmsh.

#include <array>
#include <utility>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::testing {

namespace detail {

/// The grid of nx x ny x nz cubes whose node (i, j, k) is at position(i, j, k), each cube split
/// into six tets along monotone paths from its corner (0,0,0) to (1,1,1) (Kuhn subdivision,
/// conforming); a negatively oriented tet gets its last two nodes swapped.
template <typename Position>
mesh::TetMesh kuhn_box(int nx, int ny, int nz, const Position& position) {
  mesh::TetMesh m;
  auto id = [&](int i, int j, int k) { return static_cast<Index>(i + (nx + 1) * (j + (ny + 1) * k)); };
  m.rest.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.rest.row(id(i, j, k)) = position(i, j, k).transpose();
  const std::array<std::array<int, 3>, 6> orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  m.tets.resize(6 * nx * ny * nz, 4);
  Index t = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& order : orders) {
          std::array<int, 3> c{i, j, k};
          m.tets(t, 0) = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[order[s]];
            m.tets(t, s + 1) = id(c[0], c[1], c[2]);
          }
          if (mesh::signed_volume(m.rest, m.tets, t) < 0) std::swap(m.tets(t, 2), m.tets(t, 3));
          ++t;
        }
  m.region = IndexVector::Zero(m.tets.rows());
  m.region_names = {"default"};
  return m;
}

}  // namespace detail

/// The box [lo, hi] divided into nx x ny x nz equal cells.
inline mesh::TetMesh box_mesh(int nx, int ny, int nz, const Vector3& lo, const Vector3& hi) {
  return detail::kuhn_box(nx, ny, nz, [&](int i, int j, int k) -> Vector3 {
    const Vector3 s(double(i) / nx, double(j) / ny, double(k) / nz);
    return (lo.array() + s.array() * (hi - lo).array()).matrix();
  });
}

/// The box [0, nx] x [0, ny] x [0, nz] times `spacing`: node (i, j, k) at exactly
/// (i, j, k) * spacing.
inline mesh::TetMesh box_mesh(int nx, int ny, int nz, double spacing = 1.0) {
  return detail::kuhn_box(nx, ny, nz, [&](int i, int j, int k) { return Vector3(i * spacing, j * spacing, k * spacing); });
}

/// Nodes of `m` whose coordinate `axis` equals `value` (within 1e-12).
inline std::vector<Index> nodes_on_plane(const mesh::TetMesh& m, int axis, double value) {
  std::vector<Index> out;
  for (Index a = 0; a < m.num_nodes(); ++a)
    if (std::abs(m.rest(a, axis) - value) < 1e-12) out.push_back(a);
  return out;
}

}  // namespace sinew::testing
