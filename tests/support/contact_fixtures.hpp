#pragma once
/// @file contact_fixtures.hpp
/// Shared configurations for the contact tests: two overlapping structured boxes (bodies 0 and
/// 1) as one ContactGeometry, a random intersecting triangle-tet pair, and the gradient and
/// Hessian of a contact energy at a configuration.

#include <random>
#include <utility>
#include <vector>

#include "sinew/collision/material_depth.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "support/box_mesh.hpp"
#include "support/flat_positions.hpp"

namespace sinew::testing {

/// Two boxes of n^3 cubes: body 0 = [0,1]^3, body 1 = the same box shifted by `offset` and rotated
/// by `angle` (radians) about the axis (1, 2, 3). Returns rest positions (the current positions
/// of the test) and the geometry with exact material depths and penalty `penalty` everywhere.
struct TwoBoxes {
  Positions x;
  contact::ContactGeometry geometry;
};

inline TwoBoxes two_boxes(int n, const Vector3& offset, double angle, double penalty, bool self_contact = true) {
  const mesh::TetMesh a = box_mesh(n, n, n, Vector3::Zero(), Vector3::Ones());
  const Index na = static_cast<Index>(a.rest.rows());
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  TwoBoxes out;
  out.x.resize(2 * na, 3);
  out.x.topRows(na) = a.rest;
  for (Index i = 0; i < na; ++i)
    out.x.row(na + i) = (R * (a.rest.row(i).transpose() - Vector3::Constant(0.5)) + Vector3::Constant(0.5) + offset)
                            .transpose();
  const Triangles surface = mesh::boundary_triangles(a.tets);
  auto& g = out.geometry;
  g.surface.resize(2 * surface.rows(), 3);
  g.surface.topRows(surface.rows()) = surface;
  g.surface.bottomRows(surface.rows()) = surface.array() + na;
  g.surface_body.resize(g.surface.rows());
  g.surface_body.head(surface.rows()).setZero();
  g.surface_body.tail(surface.rows()).setOnes();
  g.tets.resize(2 * a.tets.rows(), 4);
  g.tets.topRows(a.tets.rows()) = a.tets;
  g.tets.bottomRows(a.tets.rows()) = a.tets.array() + na;
  g.tet_body.resize(g.tets.rows());
  g.tet_body.head(a.tets.rows()).setZero();
  g.tet_body.tail(a.tets.rows()).setOnes();
  std::vector<Index> nodes(static_cast<std::size_t>(na));
  for (Index i = 0; i < na; ++i) nodes[static_cast<std::size_t>(i)] = i;
  const VectorX d = collision::material_depth(a.rest, surface, nodes);
  g.depth.resize(2 * na);
  g.depth << d, d;
  g.penalty = MatrixX::Constant(2, 2, penalty);
  if (!self_contact) g.penalty.diagonal().setZero();
  return out;
}

/// -dEc/dx... as the energy adds it: the gradient of `energy` at x (#V x 3), after update(x).
inline NodalVectors gradient_at(contact::ContactEnergy& energy, const Positions& x) {
  energy.update(x);
  NodalVectors g = NodalVectors::Zero(x.rows(), 3);
  energy.add_gradient(x, g);
  return g;
}

/// The dense Hessian of `energy` at x (3#V x 3#V), after update(x).
inline MatrixX hessian_at(contact::ContactEnergy& energy, const Positions& x) {
  energy.update(x);
  std::vector<std::pair<Index, Index>> pairs;
  energy.hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(static_cast<Index>(x.rows()), pairs);
  energy.add_hessian(x, H);
  return H.to_dense();
}

}  // namespace sinew::testing
