#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "sinew/collision/material_depth.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "support/box_mesh.hpp"

namespace sinew::collision {
namespace {

std::vector<Index> all_nodes(Index n) {
  std::vector<Index> v(static_cast<std::size_t>(n));
  std::iota(v.begin(), v.end(), 0);
  return v;
}

TEST(MaterialDepth, StructuredBoxIsTheDistanceToTheNearestFace) {
  const Vector3 lo(-1, 0, 2), hi(1, 1, 5);  // thickness 2 x 1 x 3: half-thickness 0.5
  const mesh::TetMesh m = testing::box_mesh(6, 4, 8, lo, hi);
  const Triangles surface = mesh::boundary_triangles(m.tets);
  const std::vector<Index> nodes = all_nodes(m.num_nodes());
  const VectorX depth = material_depth(m.rest, surface, nodes);
  const VectorX oracle = material_depth_exhaustive(m.rest, surface, nodes);
  ASSERT_EQ(depth.size(), m.num_nodes());
  for (Index a = 0; a < m.num_nodes(); ++a) {
    const Vector3 p = m.rest.row(a).transpose();
    const double analytic = std::min((p - lo).minCoeff(), (hi - p).minCoeff());
    EXPECT_NEAR(depth[a], analytic, 1e-12) << a;
    EXPECT_NEAR(depth[a], oracle[a], 1e-12) << a;
    if (analytic < 1e-12) {
      EXPECT_EQ(depth[a], 0.0) << a;  // surface nodes: exactly 0
    }
  }
  // The box's center is a node (even subdivisions): its depth is the half-thickness.
  const Vector3 center = (lo + hi) / 2;
  Index c = -1;
  for (Index a = 0; a < m.num_nodes(); ++a)
    if ((m.rest.row(a).transpose() - center).norm() < 1e-12) {
      c = a;
    }
  ASSERT_GE(c, 0);
  EXPECT_NEAR(depth[c], 0.5, 1e-12);
}

TEST(MaterialDepth, BvhMatchesExhaustiveOnPerturbedMeshAndSubsets) {
  std::mt19937 rng(21);
  mesh::TetMesh m = testing::box_mesh(7, 6, 5, Vector3(0, 0, 0), Vector3(1.4, 1.2, 1.0));
  std::uniform_real_distribution<double> jitter(-0.04, 0.04);
  for (Index v = 0; v < m.num_nodes(); ++v)
    for (int k = 0; k < 3; ++k) m.rest(v, k) += jitter(rng);
  const Triangles surface = mesh::boundary_triangles(m.tets);
  // All nodes, and a shuffled subset with repeats, plus points far outside the body.
  std::vector<Index> nodes = all_nodes(m.num_nodes());
  std::shuffle(nodes.begin(), nodes.end(), rng);
  nodes.resize(nodes.size() / 2);
  nodes.push_back(nodes.front());
  for (const auto& subset : {all_nodes(m.num_nodes()), nodes}) {
    const VectorX depth = material_depth(m.rest, surface, subset);
    const VectorX oracle = material_depth_exhaustive(m.rest, surface, subset);
    ASSERT_EQ(depth.size(), static_cast<Index>(subset.size()));
    for (Index i = 0; i < depth.size(); ++i) EXPECT_NEAR(depth[i], oracle[i], 1e-12) << i;
  }
  // Restricting the zero-depth surface to one side (a scene may do this): still the oracle.
  Triangles bottom(0, 3);
  for (Index f = 0; f < surface.rows(); ++f) {
    bool on_bottom = true;
    for (int k = 0; k < 3; ++k) on_bottom = on_bottom && surface(f, k) < (7 + 1) * (6 + 1);  // z-layer 0
    if (on_bottom) {
      bottom.conservativeResize(bottom.rows() + 1, 3);
      bottom.row(bottom.rows() - 1) = surface.row(f);
    }
  }
  ASSERT_EQ(bottom.rows(), 2 * 7 * 6);
  const std::vector<Index> every = all_nodes(m.num_nodes());
  const VectorX d1 = material_depth(m.rest, bottom, every), d2 = material_depth_exhaustive(m.rest, bottom, every);
  for (Index i = 0; i < d1.size(); ++i) EXPECT_NEAR(d1[i], d2[i], 1e-12) << i;
}

TEST(MaterialDepth, EmptyInputs) {
  const mesh::TetMesh m = testing::box_mesh(1, 1, 1, Vector3::Zero(), Vector3::Ones());
  EXPECT_EQ(material_depth(m.rest, Triangles(0, 3), {}).size(), 0);
  EXPECT_THROW(material_depth(m.rest, Triangles(0, 3), {0}), InputError);
  EXPECT_THROW(material_depth(m.rest, mesh::boundary_triangles(m.tets), {99}), InputError);
}

/// Timing printout for ~50k nodes (a benchmark figure, not asserted).
TEST(MaterialDepth, TimingFiftyThousandNodes) {
  const mesh::TetMesh m = testing::box_mesh(36, 36, 36, Vector3::Zero(), Vector3::Ones());
  const Triangles surface = mesh::boundary_triangles(m.tets);
  const std::vector<Index> nodes = all_nodes(m.num_nodes());
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const VectorX depth = material_depth(m.rest, surface, nodes);
  const auto t1 = Clock::now();
  // The exhaustive search on a strided subset, extrapolated to all nodes.
  std::vector<Index> some;
  for (std::size_t i = 0; i < nodes.size(); i += 50) some.push_back(nodes[i]);
  const VectorX oracle = material_depth_exhaustive(m.rest, surface, some);
  const auto t2 = Clock::now();
  for (std::size_t i = 0; i < some.size(); ++i)
    EXPECT_NEAR(depth[some[i]], oracle[static_cast<Index>(i)], 1e-12);
  const double bvh = std::chrono::duration<double>(t1 - t0).count();
  const double exhaustive = std::chrono::duration<double>(t2 - t1).count() * double(nodes.size()) / double(some.size());
  std::printf("[ timing ] material depth, %zu nodes, %ld surface triangles: BVH %.3f s, exhaustive ~%.1f s "
              "(extrapolated from %zu nodes)\n",
              nodes.size(), static_cast<long>(surface.rows()), bvh, exhaustive, some.size());
}

}  // namespace
}  // namespace sinew::collision
