// ContactEnergy for both methods: zero depths and zero penalties, collapsed triangles, the
// contact report against independent computations, and the bookkeeping contract (pattern
// revisions, missing Hessian blocks, stale positions).

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/collision/material_depth.hpp"
#include "sinew/collision/polygon_quadrature.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/contact_report.hpp"
#include "support/box_mesh.hpp"
#include "support/contact_fixtures.hpp"
#include "support/fd_check.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;
using st::gradient_at;
using st::hessian_at;


// ---------------------------------------------------------------------------------------------
// Zero depths, zero penalties

class ContactMethods : public ::testing::TestWithParam<ContactMethod> {};

TEST_P(ContactMethods, AllDepthsZeroMeansNoEnergy) {
  auto boxes = st::two_boxes(2, Vector3(0.5, 0.3, 0.2), 0.3, 7.0);
  boxes.geometry.depth.setZero();
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::Exact});
  energy.update(boxes.x);
  EXPECT_TRUE(energy.active_pairs().empty());
  EXPECT_EQ(energy.value(boxes.x), 0.0);
  EXPECT_EQ(gradient_at(energy, boxes.x).norm(), 0.0);
  EXPECT_EQ(hessian_at(energy, boxes.x).norm(), 0.0);
}

TEST_P(ContactMethods, TetsWithZeroDepthContributeNothing) {
  // n = 3: some tets have four surface nodes (depth 0 everywhere). Removing them from the
  // geometry changes nothing; none of them is ever an active pair.
  const auto boxes = st::two_boxes(3, Vector3(0.45, 0.3, 0.2), 0.3, 7.0, false);
  const auto& g = boxes.geometry;
  std::vector<Index> keep;
  std::set<Index> zero;
  for (Index t = 0; t < g.tets.rows(); ++t) {
    bool any = false;
    for (int k = 0; k < 4; ++k) any = any || g.depth[g.tets(t, k)] > 0;
    if (any)
      keep.push_back(t);
    else
      zero.insert(t);
  }
  ASSERT_GT(zero.size(), 10u);
  ContactGeometry reduced = g;
  reduced.tets.resize(static_cast<Index>(keep.size()), 4);
  reduced.tet_body.resize(static_cast<Index>(keep.size()));
  for (std::size_t i = 0; i < keep.size(); ++i) {
    reduced.tets.row(static_cast<Index>(i)) = g.tets.row(keep[i]);
    reduced.tet_body[static_cast<Index>(i)] = g.tet_body[keep[i]];
  }
  ContactEnergy full(g, {GetParam(), PairHessian::Exact});
  ContactEnergy part(reduced, {GetParam(), PairHessian::Exact});
  full.update(boxes.x);
  part.update(boxes.x);
  ASSERT_FALSE(full.active_pairs().empty());
  for (const auto& [f, t] : full.active_pairs()) EXPECT_EQ(zero.count(t), 0u) << "tet " << t;
  EXPECT_EQ(full.active_pairs().size(), part.active_pairs().size());
  EXPECT_NEAR(full.value(boxes.x), part.value(boxes.x), 1e-14 * full.value(boxes.x));
  EXPECT_LT(st::relative_error(gradient_at(full, boxes.x), gradient_at(part, boxes.x)), 1e-14);
  EXPECT_LT(st::relative_error(hessian_at(full, boxes.x), hessian_at(part, boxes.x)), 1e-14);
}

TEST_P(ContactMethods, CollapsedSurfaceTriangleGivesFiniteValues) {
  // A surface triangle of body 1 inside body 0 collapsed to a segment (one node moved onto
  // another): its pairs contribute nothing, everything stays finite (regression: NaN).
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 1.0, false);
  const auto& g = boxes.geometry;
  ContactEnergy energy(g, {GetParam(), PairHessian::Exact});
  energy.update(boxes.x);
  Index f = -1;
  for (const auto& [tri, tet] : energy.active_pairs())
    if (g.surface_body[tri] == 1) {
      f = tri;
      break;
    }
  ASSERT_GE(f, 0);
  Positions x = boxes.x;
  x.row(g.surface(f, 1)) = x.row(g.surface(f, 0));
  energy.update(x);
  const double value = energy.value(x);
  EXPECT_TRUE(std::isfinite(value));
  EXPECT_GT(value, 0);
  EXPECT_TRUE(gradient_at(energy, x).allFinite());
  EXPECT_TRUE(hessian_at(energy, x).allFinite());
  EXPECT_TRUE(std::isfinite(contact_report(energy, x).area));
}

TEST_P(ContactMethods, ZeroPenaltyBetweenTwoBodiesMeansNoPairsBetweenThem) {
  auto boxes = st::two_boxes(2, Vector3(0.5, 0.3, 0.2), 0.3, 7.0);
  const auto& g = boxes.geometry;
  // Only the other body's penalty: all pairs are cross-body.
  ContactEnergy cross(g, {GetParam(), PairHessian::GaussNewton});
  cross.update(boxes.x);
  ASSERT_FALSE(cross.active_pairs().empty());
  // Penalty only within each body: the overlapping boxes have no pair at all (self pairs need
  // a body to fold onto itself).
  ContactGeometry self_only = g;
  self_only.penalty << 7, 0, 0, 7;
  ContactEnergy self(self_only, {GetParam(), PairHessian::GaussNewton});
  self.update(boxes.x);
  for (const auto& [f, t] : self.active_pairs()) EXPECT_EQ(g.surface_body[f], g.tet_body[t]);
  EXPECT_TRUE(self.active_pairs().empty());
  EXPECT_EQ(self.value(boxes.x), 0.0);
  // The energy is linear in the penalty.
  ContactGeometry scaled = g;
  scaled.penalty << 0, 3, 3, 0;
  ContactEnergy three(scaled, {GetParam(), PairHessian::GaussNewton});
  three.update(boxes.x);
  EXPECT_EQ(three.active_pairs(), cross.active_pairs());
  EXPECT_NEAR(three.value(boxes.x), 3.0 / 7.0 * cross.value(boxes.x), 1e-14 * cross.value(boxes.x));
}

// ---------------------------------------------------------------------------------------------
// Statistics

TEST_P(ContactMethods, StatisticsAgreeWithIndependentComputations) {
  const ContactMethod method = GetParam();
  const auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  const auto& g = boxes.geometry;
  const Positions& x = boxes.x;
  ContactEnergy energy(g, {method, PairHessian::GaussNewton});
  const ContactReport s = contact_report(energy, x);  // the energy is not updated by the report
  EXPECT_TRUE(energy.active_pairs().empty());
  energy.update(x);
  const auto pairs = energy.active_pairs();
  ASSERT_GT(pairs.size(), 10u);
  EXPECT_EQ(s.pairs, static_cast<Index>(pairs.size()));

  // Area, energy, max penetration from the collision module, pair by pair.
  double area = 0, integral = 0, max_depth = 0;
  for (const auto& [f, t] : pairs) {
    Matrix3 tri;
    Eigen::Matrix<double, 4, 3> tet;
    Eigen::Vector4d depth;
    for (int i = 0; i < 3; ++i) tri.row(i) = x.row(g.surface(f, i));
    for (int k = 0; k < 4; ++k) {
      tet.row(k) = x.row(g.tets(t, k));
      depth[k] = g.depth[g.tets(t, k)];
    }
    const double eps = g.penalty(g.surface_body[f], g.tet_body[t]);
    if (method == ContactMethod::Area) {
      const collision::ClipPolygon p = collision::clip_triangle_tet(tri, tet);
      ASSERT_GE(p.count, 3);
      const collision::PolygonIntegral pi = collision::polygon_quadratic_integral(p, depth);
      area += pi.area;
      integral += 0.5 * eps * pi.integral;
      for (int k = 0; k < p.count; ++k)
        max_depth = std::max(max_depth, depth.dot(p.barycentric[static_cast<std::size_t>(k)]));
    } else {
      const collision::CollocationPoints c = collision::triangle_vertices_in_tet(tri, tet);
      ASSERT_GE(c.count, 1);
      const double A3 = 0.5 * (tri.row(1) - tri.row(0)).cross(tri.row(2) - tri.row(0)).norm() / 3;
      for (int k = 0; k < c.count; ++k) {
        const double gk = depth.dot(c.barycentric[static_cast<std::size_t>(k)]);
        area += A3;
        integral += 0.5 * eps * A3 * gk * gk;
        max_depth = std::max(max_depth, gk);
      }
    }
  }
  EXPECT_NEAR(s.area, area, 1e-12 * area);
  EXPECT_NEAR(s.energy, integral, 1e-12 * integral);
  EXPECT_NEAR(s.max_penetration, max_depth, 1e-12);
  energy.update(x);
  EXPECT_EQ(s.energy, energy.value(x));
  EXPECT_GT(s.mean_penetration, 0);
  EXPECT_LE(s.mean_penetration, s.max_penetration);
  EXPECT_LE(s.max_penetration, g.depth.maxCoeff());

  // Nodal forces are minus the gradient; the force on body 0 from body 1 is minus the sum over
  // body 1's nodes (and the sum over body 0's nodes).
  const NodalVectors grad = gradient_at(energy, x);
  EXPECT_LT(st::relative_error(s.nodal_force, -grad), 1e-14);
  const Index na = x.rows() / 2;
  ASSERT_EQ(s.body_pair_force.size(), 4u);
  const Vector3 on0 = s.body_pair_force[0 * 2 + 1];
  const Vector3 sum0 = s.nodal_force.topRows(na).colwise().sum().transpose();
  const Vector3 sum1 = s.nodal_force.bottomRows(na).colwise().sum().transpose();
  EXPECT_GT(on0.norm(), 0);
  EXPECT_LT((on0 + sum1).norm(), 1e-12 * on0.norm());
  EXPECT_LT((on0 - sum0).norm(), 1e-12 * on0.norm());
  EXPECT_EQ(s.body_pair_force[1 * 2 + 0].norm(), 0.0);  // only i < j is filled
  EXPECT_EQ(s.body_pair_force[0].norm(), 0.0);           // diagonal unused
  EXPECT_EQ(s.body_pair_force[3].norm(), 0.0);
  ASSERT_EQ(s.self_contact_force_magnitude.size(), 2);
  EXPECT_EQ(s.self_contact_force_magnitude.norm(), 0.0);  // no self-contact here
  // Pressure is non-negative and positive somewhere.
  EXPECT_GE(s.nodal_pressure.minCoeff(), 0.0);
  EXPECT_GT(s.nodal_pressure.maxCoeff(), 0.0);
}

TEST_P(ContactMethods, StatisticsWithoutContactAreZero) {
  const auto boxes = st::two_boxes(2, Vector3(3, 0, 0), 0.4, 7.0);
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::GaussNewton});
  const ContactReport s = contact_report(energy, boxes.x);
  EXPECT_EQ(s.pairs, 0);
  EXPECT_EQ(s.area, 0.0);
  EXPECT_EQ(s.energy, 0.0);
  EXPECT_EQ(s.max_penetration, 0.0);
  EXPECT_EQ(s.mean_penetration, 0.0);
  EXPECT_EQ(s.nodal_force.norm(), 0.0);
  for (const Vector3& f : s.body_pair_force) EXPECT_EQ(f.norm(), 0.0);
  EXPECT_EQ(s.self_contact_force_magnitude.norm(), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Bookkeeping contract

TEST_P(ContactMethods, PatternRevisionGrowsOnlyWhenNewBlocksAppear) {
  auto apart = st::two_boxes(2, Vector3(3, 0, 0), 0.3, 7.0);
  const auto shallow = st::two_boxes(2, Vector3(0.9, 0.1, 0.05), 0.3, 7.0);
  const auto deep = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  ContactEnergy energy(apart.geometry, {GetParam(), PairHessian::GaussNewton});
  energy.begin_step(apart.x);
  EXPECT_TRUE(energy.active_pairs().empty());
  const auto r0 = energy.pattern_revision();
  std::vector<std::pair<Index, Index>> pattern;
  energy.hessian_pattern(pattern);
  EXPECT_TRUE(pattern.empty());

  energy.update(deep.x);
  ASSERT_FALSE(energy.active_pairs().empty());
  const auto r1 = energy.pattern_revision();
  EXPECT_GT(r1, r0);
  // The same x again: nothing new.
  energy.update(deep.x);
  EXPECT_EQ(energy.pattern_revision(), r1);
  energy.update(Positions(deep.x));
  EXPECT_EQ(energy.pattern_revision(), r1);
  // Back to no contact and to the same contact: the pattern is a union, no growth.
  energy.update(apart.x);
  EXPECT_TRUE(energy.active_pairs().empty());
  EXPECT_EQ(energy.pattern_revision(), r1);
  energy.update(deep.x);
  EXPECT_EQ(energy.pattern_revision(), r1);
  // Every active pair's blocks are in the pattern: add_hessian succeeds.
  EXPECT_NO_THROW(hessian_at(energy, deep.x));

  // A shallow overlap uses pairs the deep one did not (other triangles near the surface)?
  // If so the revision grows, otherwise it stays.
  pattern.clear();
  energy.hessian_pattern(pattern);
  std::set<std::pair<Index, Index>> before;
  for (auto [a, b] : pattern) before.emplace(std::min(a, b), std::max(a, b));
  energy.update(shallow.x);
  pattern.clear();
  energy.hessian_pattern(pattern);
  std::set<std::pair<Index, Index>> after;
  for (auto [a, b] : pattern) after.emplace(std::min(a, b), std::max(a, b));
  EXPECT_TRUE(std::includes(after.begin(), after.end(), before.begin(), before.end()));
  if (after.size() > before.size()) {
    EXPECT_GT(energy.pattern_revision(), r1);
  } else {
    EXPECT_EQ(energy.pattern_revision(), r1);
  }
}

TEST_P(ContactMethods, AddHessianThrowsWhenThePatternLacksAContactBlock) {
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::GaussNewton});
  energy.update(boxes.x);
  ASSERT_FALSE(energy.active_pairs().empty());
  BlockSparseMatrix diagonal_only;
  diagonal_only.set_pattern(static_cast<Index>(boxes.x.rows()), {});
  EXPECT_THROW(energy.add_hessian(boxes.x, diagonal_only), std::logic_error);
  // One block short of the full pattern.
  std::vector<std::pair<Index, Index>> pattern;
  energy.hessian_pattern(pattern);
  ASSERT_FALSE(pattern.empty());
  // Drop a block some active pair needs: the first pair's triangle vertex 0 with its tet vertex 0.
  const auto [f, t] = energy.active_pairs().front();
  const Index a = boxes.geometry.surface(f, 0), b = boxes.geometry.tets(t, 0);
  std::erase_if(pattern, [&](const auto& p) { return (p.first == a && p.second == b) || (p.first == b && p.second == a); });
  BlockSparseMatrix short_one;
  short_one.set_pattern(static_cast<Index>(boxes.x.rows()), pattern);
  EXPECT_THROW(energy.add_hessian(boxes.x, short_one), std::logic_error);
}

TEST_P(ContactMethods, EvaluatingAtAnotherXThanTheLastUpdateThrows) {
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::GaussNewton});
  // Before any update.
  EXPECT_THROW((void)energy.value(boxes.x), std::logic_error);
  energy.update(boxes.x);
  EXPECT_NO_THROW((void)energy.value(boxes.x));
  Positions moved = boxes.x;
  moved(0, 0) += 1e-9;
  EXPECT_THROW((void)energy.value(moved), std::logic_error);
  NodalVectors g = NodalVectors::Zero(moved.rows(), 3);
  EXPECT_THROW(energy.add_gradient(moved, g), std::logic_error);
  std::vector<std::pair<Index, Index>> pattern;
  energy.hessian_pattern(pattern);
  BlockSparseMatrix H;
  H.set_pattern(static_cast<Index>(moved.rows()), pattern);
  EXPECT_THROW(energy.add_hessian(moved, H), std::logic_error);
  // A different number of rows.
  const Positions fewer = boxes.x.topRows(boxes.x.rows() - 1);
  EXPECT_THROW((void)energy.value(fewer), std::logic_error);
  EXPECT_THROW(energy.update(fewer), std::invalid_argument);
  // After update(moved) it is fine.
  energy.update(moved);
  EXPECT_NO_THROW((void)energy.value(moved));
  EXPECT_THROW((void)energy.value(boxes.x), std::logic_error);
}

INSTANTIATE_TEST_SUITE_P(Methods, ContactMethods, ::testing::Values(ContactMethod::Area, ContactMethod::Point),
                         [](const auto& info) { return info.param == ContactMethod::Area ? "Area" : "Point"; });

}  // namespace
}  // namespace sinew::contact
