#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "sinew/collision/aabb_tree.hpp"
#include "sinew/collision/broad_phase.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "support/box_mesh.hpp"

namespace sinew::collision {
namespace {

using Pairs = std::vector<std::pair<Index, Index>>;

/// O(F T) reference: every (triangle, tet) pair whose boxes overlap and that shares no node.
Pairs brute_force(const Positions& x, const Triangles& triangles, const Tets& tets, double tet_inflate) {
  const std::vector<Aabb> fb = triangle_boxes(x, triangles);
  const std::vector<Aabb> tb = tet_boxes(x, tets, tet_inflate);
  Pairs out;
  for (Index f = 0; f < triangles.rows(); ++f)
    for (Index t = 0; t < tets.rows(); ++t) {
      bool shared = false;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) shared = shared || triangles(f, i) == tets(t, j);
      if (!shared && overlaps(fb[static_cast<std::size_t>(f)], tb[static_cast<std::size_t>(t)])) out.emplace_back(f, t);
    }
  return out;  // already sorted
}

/// Two randomly perturbed structured boxes overlapping each other, as one node array with both
/// bodies' tets and boundary triangles.
struct TwoBodies {
  Positions x;
  Tets tets;
  Triangles triangles;
  Index tets_of_first = 0;
};

TwoBodies two_overlapping_boxes(std::mt19937& rng) {
  const mesh::TetMesh a = testing::box_mesh(4, 3, 3, Vector3(0, 0, 0), Vector3(1, 0.8, 0.7));
  const mesh::TetMesh b = testing::box_mesh(3, 4, 3, Vector3(0.6, 0.3, 0.4), Vector3(1.5, 1.2, 1.1));
  TwoBodies m;
  const Index na = a.num_nodes();
  m.x.resize(na + b.num_nodes(), 3);
  m.x << a.rest, b.rest;
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (Index v = 0; v < m.x.rows(); ++v)
    for (int k = 0; k < 3; ++k) m.x(v, k) += jitter(rng);
  m.tets.resize(a.num_tets() + b.num_tets(), 4);
  m.tets << a.tets, (b.tets.array() + na).matrix();
  m.tets_of_first = a.num_tets();
  const Triangles fa = mesh::boundary_triangles(a.tets), fb = mesh::boundary_triangles(b.tets);
  m.triangles.resize(fa.rows() + fb.rows(), 3);
  m.triangles << fa, (fb.array() + na).matrix();
  return m;
}

TEST(BroadPhase, BoxesBoundTheirNodesWithInflation) {
  Positions x(4, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3;
  Tets t(1, 4);
  t << 0, 1, 2, 3;
  Triangles f(1, 3);
  f << 1, 2, 3;
  const Aabb tb = tet_boxes(x, t, 0.5)[0];
  EXPECT_EQ(tb.min(), Vector3(-0.5, -0.5, -0.5));
  EXPECT_EQ(tb.max(), Vector3(1.5, 2.5, 3.5));
  const Aabb fb = triangle_boxes(x, f)[0];
  EXPECT_EQ(fb.min(), Vector3(0, 0, 0));
  EXPECT_EQ(fb.max(), Vector3(1, 2, 3));
  EXPECT_TRUE(shares_node(f, 0, t, 0));
}

TEST(BroadPhase, CandidatesMatchBruteForceAfterRefitAndRebuild) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 rng(seed);
    TwoBodies m = two_overlapping_boxes(rng);
    const double inflate = seed == 2u ? 0.02 : 0.0;
    AabbTree tree(tet_boxes(m.x, m.tets, inflate));
    const Pairs initial = triangle_tet_candidates(m.x, m.triangles, m.tets, tree);
    EXPECT_EQ(initial, brute_force(m.x, m.triangles, m.tets, inflate));

    // Both kinds are present: pairs between the bodies and self pairs (non-adjacent, same body).
    const Index faces_of_first = static_cast<Index>(mesh::boundary_triangles(m.tets.topRows(m.tets_of_first)).rows());
    bool cross = false, self = false;
    for (const auto& [f, t] : initial) {
      const bool f_first = f < faces_of_first, t_first = t < m.tets_of_first;
      (f_first == t_first ? self : cross) = true;
    }
    EXPECT_TRUE(cross);
    EXPECT_TRUE(self);

    // A random motion: a rigid shift of the second body plus nodal noise.
    std::normal_distribution<double> noise(0.0, 0.03);
    const Vector3 shift(-0.2, -0.1, 0.05);
    const Index first_nodes = m.tets.topRows(m.tets_of_first).maxCoeff() + 1;
    for (Index v = 0; v < m.x.rows(); ++v) {
      for (int k = 0; k < 3; ++k) m.x(v, k) += noise(rng);
      if (v >= first_nodes) m.x.row(v) += shift.transpose();
    }
    const Pairs reference = brute_force(m.x, m.triangles, m.tets, inflate);
    tree.refit(tet_boxes(m.x, m.tets, inflate));
    EXPECT_EQ(triangle_tet_candidates(m.x, m.triangles, m.tets, tree), reference);
    tree.build(tet_boxes(m.x, m.tets, inflate));
    EXPECT_EQ(triangle_tet_candidates(m.x, m.triangles, m.tets, tree), reference);
    EXPECT_NE(reference, initial);
  }
}

// Trees over subsets of the tets, each triangle's group naming the trees it is tested against:
// the all-tets candidates restricted to those trees, in the same order.
TEST(BroadPhase, GroupedTreesGiveTheCandidatesOfTheTreesEachGroupNames) {
  std::mt19937 rng(5);
  const TwoBodies m = two_overlapping_boxes(rng);
  const Pairs all = brute_force(m.x, m.triangles, m.tets, 0.0);
  const Index faces_of_first = static_cast<Index>(mesh::boundary_triangles(m.tets.topRows(m.tets_of_first)).rows());
  IndexVector group(m.triangles.rows());
  for (Index f = 0; f < m.triangles.rows(); ++f) group[f] = f < faces_of_first ? 0 : 1;
  // Tree 0: the first body's tets with an even index; tree 1: all of the second body's.
  std::vector<TetSubsetTree> trees(2);
  for (Index t = 0; t < m.tets.rows(); ++t) {
    if (t < m.tets_of_first && t % 2 == 0) trees[0].tets.push_back(t);
    if (t >= m.tets_of_first) trees[1].tets.push_back(t);
  }
  for (TetSubsetTree& t : trees) t.tree.build(subset_boxes(m.x, m.tets, t.tets));
  const auto in_tree = [&](int k, Index t) {
    const std::vector<Index>& tets = trees[static_cast<std::size_t>(k)].tets;
    return std::binary_search(tets.begin(), tets.end(), t);
  };
  // Group 0 (the first body's triangles) against the second body only; group 1 against both.
  const std::vector<std::vector<int>> trees_of_group{{1}, {0, 1}};
  Pairs expected;
  for (const auto& [f, t] : all) {
    const bool wanted = group[f] == 0 ? in_tree(1, t) : (in_tree(0, t) || in_tree(1, t));
    if (wanted) expected.emplace_back(f, t);
  }
  const Pairs grouped = triangle_tet_candidates(m.x, m.triangles, m.tets, trees, group, trees_of_group);
  EXPECT_EQ(grouped, expected);
  EXPECT_LT(grouped.size(), all.size());
  EXPECT_GT(grouped.size(), 0u);
  // A group with no trees is tested against nothing.
  EXPECT_TRUE(triangle_tet_candidates(m.x, m.triangles, m.tets, trees, group, {{}, {}}).empty());
  // Arrays that do not match the trees are programming errors.
  EXPECT_THROW(triangle_tet_candidates(m.x, m.triangles, m.tets, trees, IndexVector(3), trees_of_group),
               std::invalid_argument);
}

TEST(BroadPhase, TriangleInflationFindsNearbyTets) {
  Positions x(7, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1,  // tet
      0, 0, 1.1, 1, 0, 1.1, 0, 1, 1.1;     // triangle just above
  Tets t(1, 4);
  t << 0, 1, 2, 3;
  Triangles f(1, 3);
  f << 4, 5, 6;
  const AabbTree tree(tet_boxes(x, t));
  EXPECT_TRUE(triangle_tet_candidates(x, f, t, tree).empty());
  EXPECT_EQ(triangle_tet_candidates(x, f, t, tree, 0.2), (Pairs{{0, 0}}));
  EXPECT_THROW(triangle_tet_candidates(x, f, Tets(2, 4), tree), std::invalid_argument);
}

}  // namespace
}  // namespace sinew::collision
