/// @file test_tet_quality.cpp
/// tet_shape and mesh_quality on tets whose angles and radius ratios are known in closed form.

#include "sinew/mesh/tet_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "mesh/mesh_fixtures.hpp"

namespace sinew::mesh {
namespace {

constexpr double kDegree = 180.0 / std::numbers::pi;

/// One tet of the four given corners (rows), nodes 0..3.
std::pair<Positions, Tets> single_tet(const std::vector<Vector3>& corners) {
  Positions x(4, 3);
  for (Index k = 0; k < 4; ++k) x.row(k) = corners[static_cast<std::size_t>(k)].transpose();
  Tets tets(1, 4);
  tets << 0, 1, 2, 3;
  return {x, tets};
}

TetShape shape_of(const std::vector<Vector3>& corners) {
  const auto [x, tets] = single_tet(corners);
  return tet_shape(x, tets, 0);
}

const std::vector<Vector3> kRegular{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
const std::vector<Vector3> kRightCorner{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
/// The classic sliver: the four corners of a unit square, two of them lifted by h.
std::vector<Vector3> sliver(double h) { return {{0, 0, 0}, {1, 1, 0}, {1, 0, h}, {0, 1, h}}; }

TEST(TetQuality, RegularTetHasEqualDihedralAnglesAndRatioOne) {
  const TetShape shape = shape_of(kRegular);
  const double expected = std::acos(1.0 / 3.0) * kDegree;  // 70.5288 degrees
  EXPECT_NEAR(expected, 70.5288, 1e-4);
  EXPECT_NEAR(shape.min_dihedral_deg, expected, 1e-10);
  EXPECT_NEAR(shape.max_dihedral_deg, expected, 1e-10);
  EXPECT_NEAR(shape.radius_ratio, 1.0, 1e-12);
}

TEST(TetQuality, RightCornerTetHasRightAnglesAndTheSlantedOnes) {
  const TetShape shape = shape_of(kRightCorner);
  // Three right angles at the edges through the corner; the slanted face meets each other face
  // at acos(1/sqrt(3)) = 54.7356 degrees.
  EXPECT_NEAR(shape.max_dihedral_deg, 90.0, 1e-10);
  EXPECT_NEAR(shape.min_dihedral_deg, std::acos(1.0 / std::sqrt(3.0)) * kDegree, 1e-10);
  EXPECT_NEAR(shape.min_dihedral_deg, 54.7356, 1e-4);
  // r_in = 1 / (3 + sqrt 3), R = sqrt(3) / 2: 3 r_in / R = sqrt(3) - 1.
  EXPECT_NEAR(shape.radius_ratio, std::sqrt(3.0) - 1.0, 1e-12);
}

TEST(TetQuality, NearlyFlatSliverHasAnglesNearZeroAndOneEighty) {
  const TetShape shape = shape_of(sliver(1e-3));
  EXPECT_GT(shape.min_dihedral_deg, 0.0);
  EXPECT_LT(shape.min_dihedral_deg, 0.5);
  EXPECT_GT(shape.max_dihedral_deg, 179.5);
  EXPECT_LE(shape.max_dihedral_deg, 180.0);
  EXPECT_GT(shape.radius_ratio, 0.0);
  EXPECT_LT(shape.radius_ratio, 0.01);
  // Flatter is worse.
  const TetShape flatter = shape_of(sliver(1e-5));
  EXPECT_LT(flatter.min_dihedral_deg, shape.min_dihedral_deg);
  EXPECT_LT(flatter.radius_ratio, shape.radius_ratio);
}

TEST(TetQuality, ExactlyFlatTetHasZeroAngleAndRatio) {
  const TetShape flat = shape_of(sliver(0.0));
  EXPECT_EQ(flat.min_dihedral_deg, 0.0);
  EXPECT_EQ(flat.radius_ratio, 0.0);
  // Four corners on one line: no face has an area.
  const TetShape collinear = shape_of({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
  EXPECT_EQ(collinear.min_dihedral_deg, 0.0);
  EXPECT_EQ(collinear.radius_ratio, 0.0);
}

TEST(TetQuality, ShapeDoesNotDependOnOrientationPlacementOrScale) {
  const TetShape reference = shape_of(kRightCorner);
  // Inverted (two corners swapped) and every even renumbering.
  const std::vector<std::vector<int>> orders{{1, 0, 2, 3}, {0, 1, 3, 2}, {1, 2, 0, 3}, {3, 2, 1, 0}, {2, 3, 0, 1}};
  for (const auto& order : orders) {
    std::vector<Vector3> corners;
    for (int k : order) corners.push_back(kRightCorner[static_cast<std::size_t>(k)]);
    const TetShape shape = shape_of(corners);
    EXPECT_NEAR(shape.min_dihedral_deg, reference.min_dihedral_deg, 1e-10);
    EXPECT_NEAR(shape.max_dihedral_deg, reference.max_dihedral_deg, 1e-10);
    EXPECT_NEAR(shape.radius_ratio, reference.radius_ratio, 1e-12);
  }
  // Rotated, scaled by 250 and moved far from the origin.
  const Matrix3 rotation = Eigen::AngleAxisd(0.7, Vector3(1, 2, -0.5).normalized()).toRotationMatrix();
  std::vector<Vector3> moved;
  for (const Vector3& c : kRightCorner) moved.push_back(250.0 * rotation * c + Vector3(1e3, -4e3, 7e2));
  const TetShape shape = shape_of(moved);
  EXPECT_NEAR(shape.min_dihedral_deg, reference.min_dihedral_deg, 1e-8);
  EXPECT_NEAR(shape.max_dihedral_deg, reference.max_dihedral_deg, 1e-8);
  EXPECT_NEAR(shape.radius_ratio, reference.radius_ratio, 1e-10);
}

TEST(TetQuality, MeshQualityFindsTheWorstTetAndCountsSlivers) {
  // Three separate tets: right-corner (0), sliver (1), regular (2).
  std::vector<std::vector<Vector3>> shapes{kRightCorner, sliver(1e-3), kRegular};
  Positions x(12, 3);
  Tets tets(3, 4);
  for (Index t = 0; t < 3; ++t) {
    for (Index k = 0; k < 4; ++k) {
      x.row(4 * t + k) = (shapes[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)] + Vector3(5.0 * t, 0, 0)).transpose();
      tets(t, k) = 4 * t + k;
    }
  }
  const TetShape sliver_shape = shape_of(shapes[1]);
  const MeshQuality quality = mesh_quality(x, tets);
  EXPECT_EQ(quality.worst_tet, 1);
  EXPECT_EQ(quality.slivers, 1);
  EXPECT_DOUBLE_EQ(quality.min_dihedral_deg, sliver_shape.min_dihedral_deg);
  EXPECT_DOUBLE_EQ(quality.max_dihedral_deg, sliver_shape.max_dihedral_deg);
  EXPECT_DOUBLE_EQ(quality.worst_radius_ratio, sliver_shape.radius_ratio);
  EXPECT_NEAR(quality.mean_radius_ratio, (std::sqrt(3.0) - 1.0 + sliver_shape.radius_ratio + 1.0) / 3.0, 1e-12);
  // Below 60 degrees the right-corner tet (54.7) counts as a sliver too; the regular one (70.5) not.
  EXPECT_EQ(mesh_quality(x, tets, 60.0).slivers, 2);
  EXPECT_EQ(mesh_quality(x, tets, 0.0).slivers, 0);
}

TEST(TetQuality, KuhnBoxHasAnglesBetween45And90) {
  const TetMesh box = testing::box_mesh(3, 2, 2);
  const MeshQuality quality = mesh_quality(box.rest, box.tets);
  EXPECT_NEAR(quality.min_dihedral_deg, 45.0, 1e-9);
  EXPECT_NEAR(quality.max_dihedral_deg, 90.0, 1e-9);
  EXPECT_EQ(quality.slivers, 0);
  EXPECT_GE(quality.worst_tet, 0);
  EXPECT_LT(quality.worst_tet, box.num_tets());
  // All Kuhn tets are congruent: the mean is the worst.
  EXPECT_NEAR(quality.mean_radius_ratio, quality.worst_radius_ratio, 1e-12);
}

TEST(TetQuality, EmptyMeshKeepsTheDefaults) {
  const MeshQuality quality = mesh_quality(Positions(0, 3), Tets(0, 4));
  EXPECT_EQ(quality.worst_tet, -1);
  EXPECT_EQ(quality.slivers, 0);
  EXPECT_EQ(quality.mean_radius_ratio, 0.0);
}

}  // namespace
}  // namespace sinew::mesh
