#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "sinew/collision/aabb.hpp"
#include "sinew/collision/aabb_tree.hpp"

namespace sinew::collision {
namespace {

std::vector<Aabb> random_boxes(std::mt19937& rng, int n, double size) {
  std::uniform_real_distribution<double> pos(0.0, 10.0), ext(0.0, size);
  std::vector<Aabb> boxes;
  for (int i = 0; i < n; ++i) {
    const Vector3 lo(pos(rng), pos(rng), pos(rng));
    boxes.emplace_back(lo, lo + Vector3(ext(rng), ext(rng), ext(rng)));
  }
  return boxes;
}

std::vector<Index> brute_force(const std::vector<Aabb>& boxes, const Aabb& q) {
  std::vector<Index> out;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (overlaps(boxes[i], q)) out.push_back(static_cast<Index>(i));
  return out;
}

std::vector<Index> tree_query(const AabbTree& tree, const Aabb& q) {
  std::vector<Index> out;
  tree.query(q, out);
  std::sort(out.begin(), out.end());
  return out;
}

/// Every node's box bounds its children's (or its primitives') boxes; leaves cover each
/// primitive exactly once.
void expect_consistent(const AabbTree& tree, const std::vector<Aabb>& boxes, int leaf_size) {
  std::vector<int> seen(boxes.size(), 0);
  for (const auto& node : tree.nodes()) {
    if (node.is_leaf()) {
      EXPECT_LE(node.count, leaf_size);
      for (Index k = node.first; k < node.first + node.count; ++k) {
        const Index p = tree.primitive_order()[static_cast<std::size_t>(k)];
        ++seen[static_cast<std::size_t>(p)];
        EXPECT_TRUE(node.box.contains(boxes[static_cast<std::size_t>(p)]));
      }
    } else {
      EXPECT_TRUE(node.box.contains(tree.nodes()[static_cast<std::size_t>(node.first)].box));
      EXPECT_TRUE(node.box.contains(tree.nodes()[static_cast<std::size_t>(node.first + 1)].box));
    }
  }
  for (const int s : seen) EXPECT_EQ(s, 1);
}

TEST(Aabb, OverlapTouchingAndEmpty) {
  const Aabb a(Vector3(0, 0, 0), Vector3(1, 1, 1));
  EXPECT_TRUE(overlaps(a, Aabb(Vector3(1, 1, 1), Vector3(2, 2, 2))));
  EXPECT_FALSE(overlaps(a, Aabb(Vector3(1.0001, 0, 0), Vector3(2, 1, 1))));
  EXPECT_FALSE(overlaps(a, Aabb()));
  EXPECT_DOUBLE_EQ(squared_distance(a, Vector3(2, 0.5, -1)), 2.0);
  EXPECT_DOUBLE_EQ(squared_distance(a, Vector3(0.5, 0.5, 0.5)), 0.0);
  EXPECT_TRUE(overlaps(inflated(a, 0.1), Aabb(Vector3(1.05, 0, 0), Vector3(2, 1, 1))));
}

TEST(AabbTree, EmptyAndSingle) {
  AabbTree tree(std::vector<Aabb>{});
  EXPECT_TRUE(tree.empty());
  EXPECT_TRUE(tree_query(tree, Aabb(Vector3::Zero(), Vector3::Ones())).empty());
  EXPECT_EQ(tree.nearest(Vector3::Zero(), [](Index) { return 0.0; }).first, -1);
  tree.build({Aabb(Vector3::Zero(), Vector3::Ones())});
  EXPECT_EQ(tree_query(tree, Aabb(Vector3::Constant(0.5), Vector3::Constant(2))), std::vector<Index>{0});
}

TEST(AabbTree, QueryMatchesBruteForceAfterBuildAndRefit) {
  std::mt19937 rng(7);
  for (const int leaf_size : {1, 4, 7}) {
    std::vector<Aabb> boxes = random_boxes(rng, 1000, 0.8);
    AabbTree tree(boxes, leaf_size);
    expect_consistent(tree, boxes, leaf_size);
    const std::vector<Aabb> queries = random_boxes(rng, 200, 2.0);
    for (const Aabb& q : queries) EXPECT_EQ(tree_query(tree, q), brute_force(boxes, q));
    // Move every box, refit, query again.
    std::normal_distribution<double> d(0.0, 0.5);
    for (Aabb& b : boxes) {
      const Vector3 shift(d(rng), d(rng), d(rng));
      b = Aabb(b.min() + shift, b.max() + shift);
    }
    tree.refit(boxes);
    expect_consistent(tree, boxes, leaf_size);
    for (const Aabb& q : queries) EXPECT_EQ(tree_query(tree, q), brute_force(boxes, q));
  }
}

TEST(AabbTree, RefitRejectsWrongSize) {
  std::mt19937 rng(1);
  AabbTree tree(random_boxes(rng, 10, 1.0));
  EXPECT_THROW(tree.refit(random_boxes(rng, 9, 1.0)), std::invalid_argument);
}

TEST(AabbTree, NearestMatchesBruteForceOnPointBoxes) {
  std::mt19937 rng(3);
  std::vector<Aabb> boxes = random_boxes(rng, 2000, 0.0);  // degenerate boxes = points
  const AabbTree tree(boxes);
  std::uniform_real_distribution<double> u(-2.0, 12.0);
  for (int i = 0; i < 300; ++i) {
    const Vector3 p(u(rng), u(rng), u(rng));
    auto dist = [&](Index k) { return (boxes[static_cast<std::size_t>(k)].min() - p).squaredNorm(); };
    double best = 1e300;
    for (std::size_t k = 0; k < boxes.size(); ++k) best = std::min(best, dist(static_cast<Index>(k)));
    const auto found = tree.nearest(p, dist);
    EXPECT_EQ(found.second, best);
    EXPECT_EQ(dist(found.first), best);
  }
}

}  // namespace
}  // namespace sinew::collision
