#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {
namespace {

using ::testing::HasSubstr;

TEST(BoundaryTriangles, SingleTetFacesPointAwayFromItsCentroid) {
  Positions x(4, 3);
  x << 0.1, 0.2, 0.3, 1.4, 0.1, 0.2, 0.3, 1.2, 0.1, 0.2, 0.4, 0.9;
  Tets tets(1, 4);
  tets << 0, 1, 2, 3;
  orient_positively(x, tets);
  const Triangles boundary = boundary_triangles(tets);
  ASSERT_EQ(boundary.rows(), 4);
  const Vector3 tet_centroid = x.colwise().mean().transpose();
  for (Index f = 0; f < 4; ++f) {
    Vector3 face_centroid = Vector3::Zero();
    for (int k = 0; k < 3; ++k) face_centroid += x.row(boundary(f, k)).transpose() / 3.0;
    EXPECT_GT(testing::triangle_area_vector(x, boundary, f).dot(face_centroid - tet_centroid), 0);
  }
}

TEST(BoundaryTriangles, BoxSurfaceIsClosedOutwardAndEnclosesTheVolume) {
  for (const unsigned seed : {0u, 1u}) {
    const TetMesh box = testing::shuffled(testing::box_mesh(4, 3, 2, 0.25), seed);
    const Triangles boundary = boundary_triangles(box.tets);
    // Each unit square of the surface is two triangles.
    EXPECT_EQ(boundary.rows(), 2 * 2 * (4 * 3 + 3 * 2 + 4 * 2));
    EXPECT_EQ(testing::euler_characteristic(boundary), 2);
    EXPECT_TRUE(testing::is_closed_oriented_surface(boundary));
    const double volume = testing::total_volume(box.rest, box.tets);
    EXPECT_NEAR(volume, 1.0 * 0.75 * 0.5, 1e-12);
    EXPECT_NEAR(testing::enclosed_volume(box.rest, boundary), volume, 1e-12);
    EXPECT_NEAR(testing::total_area(box.rest, boundary), 2 * (0.75 + 0.375 + 0.5), 1e-12);
  }
}

TEST(BoundaryTriangles, EmptyTetsGiveNoTriangles) {
  EXPECT_EQ(boundary_triangles(Tets(0, 4)).rows(), 0);
}

/// A 4 x 2 x 2 box whose left half (x < 2) is region 0 and right half region 1.
TetMesh two_region_box() {
  TetMesh box = testing::shuffled(testing::box_mesh(4, 2, 2), 7);
  box.region_names = {"left", "right"};
  for (Index t = 0; t < box.num_tets(); ++t) {
    double centroid_x = 0;
    for (int k = 0; k < 4; ++k) centroid_x += box.rest(box.tets(t, k), 0) / 4;
    box.region(t) = centroid_x < 2 ? 0 : 1;
  }
  return box;
}

TEST(InterfaceTriangles, PlaneBetweenTwoRegionsOrientedOutOfTheFirst) {
  const TetMesh box = two_region_box();
  const Triangles left_to_right = interface_triangles(box, 0, 1);
  ASSERT_EQ(left_to_right.rows(), 2 * 2 * 2);
  for (Index f = 0; f < left_to_right.rows(); ++f) {
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(box.rest(left_to_right(f, k), 0), 2.0);
    const Vector3 area = testing::triangle_area_vector(box.rest, left_to_right, f);
    EXPECT_NEAR(area.x(), 0.5, 1e-12);  // +x: out of the left region
  }
  const Triangles right_to_left = interface_triangles(box, 1, 0);
  ASSERT_EQ(right_to_left.rows(), left_to_right.rows());
  for (Index f = 0; f < right_to_left.rows(); ++f) {
    EXPECT_NEAR(testing::triangle_area_vector(box.rest, right_to_left, f).x(), -0.5, 1e-12);
  }
}

TEST(InterfaceTriangles, RejectsBadRegionIds) {
  const TetMesh box = two_region_box();
  EXPECT_THROW(interface_triangles(box, 0, 0), InputError);
  try {
    interface_triangles(box, 0, 2);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("region id 2 is out of range"));
  }
}

TEST(InterfaceTriangles, RegionsThatDoNotTouchHaveNone) {
  TetMesh box = two_region_box();
  box.region_names.push_back("unused");
  EXPECT_EQ(interface_triangles(box, 0, 2).rows(), 0);
}

}  // namespace
}  // namespace sinew::mesh
