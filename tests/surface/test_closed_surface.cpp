/// @file test_closed_surface.cpp
/// ClosedSurface: inside and signed distance on a cube and a sphere, inward surfaces turned
/// outward, and the messages for surfaces that bound no region.

#include "sinew/surface/closed_surface.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "sinew/core/error.hpp"
#include "sinew/surface/surface_checks.hpp"
#include "surface/closed_fixtures.hpp"

namespace sinew::surface {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using sinew::testing::box_surface;
using sinew::testing::icosphere;

/// The message ClosedSurface throws for `mesh`, or "" when it accepts it.
std::string rejection(const SurfaceMesh& mesh) {
  try {
    ClosedSurface surface(mesh, "surface \"bone\"");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ClosedSurface, CubeContainsAndSignedDistance) {
  const ClosedSurface cube(box_surface(), "cube");
  EXPECT_NEAR(cube.volume(), 1.0, 1e-14);
  EXPECT_TRUE(cube.bounds().min.isApprox(Vector3::Zero()));
  EXPECT_TRUE(cube.bounds().max.isApprox(Vector3::Ones()));
  EXPECT_TRUE(cube.contains(Vector3(0.5, 0.5, 0.5)));
  EXPECT_TRUE(cube.contains(Vector3(0.01, 0.99, 0.5)));
  EXPECT_TRUE(cube.contains(Vector3(1.0, 0.5, 0.5)));  // on the surface counts as inside
  EXPECT_FALSE(cube.contains(Vector3(1.01, 0.5, 0.5)));
  EXPECT_FALSE(cube.contains(Vector3(-0.5, 0.5, 0.5)));
  EXPECT_FALSE(cube.contains(Vector3(5, 5, 5)));
  EXPECT_NEAR(cube.signed_distance(Vector3(0.5, 0.5, 0.5)), -0.5, 1e-12);
  EXPECT_NEAR(cube.signed_distance(Vector3(0.5, 0.5, 0.2)), -0.2, 1e-12);
  EXPECT_NEAR(cube.signed_distance(Vector3(3.0, 0.5, 0.5)), 2.0, 1e-12);
  EXPECT_NEAR(cube.signed_distance(Vector3(2, 2, 2)), std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(cube.signed_distance(Vector3(-1, 0.5, -1)), std::sqrt(2.0), 1e-12);
}

TEST(ClosedSurface, SphereContainsAndSignedDistance) {
  const double r = 2.0;
  const Vector3 center(1, -2, 3);
  const SurfaceMesh mesh = icosphere(r, 3, center);
  EXPECT_GT(enclosed_volume(mesh), 0);  // the fixture faces outward
  const ClosedSurface sphere(mesh, "sphere");
  const double ball = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(sphere.volume(), enclosed_volume(mesh), 1e-12);
  EXPECT_LT(sphere.volume(), ball);
  EXPECT_GT(sphere.volume(), 0.98 * ball);
  EXPECT_NEAR(sphere.signed_distance(center), -r, 0.01 * r);
  // Away from the surface the polyhedron and the sphere agree (the gap is < 0.5% of r at 3
  // subdivisions).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.6 * r, 1.6 * r);
  int inside = 0, outside = 0;
  for (int i = 0; i < 400; ++i) {
    const Vector3 offset(coordinate(random), coordinate(random), coordinate(random));
    const double rho = offset.norm();
    if (std::abs(rho - r) < 0.02 * r) continue;
    const Vector3 x = center + offset;
    SCOPED_TRACE(::testing::Message() << "offset " << offset.transpose());
    EXPECT_EQ(sphere.contains(x), rho < r);
    EXPECT_NEAR(sphere.signed_distance(x), rho - r, 0.01 * r);
    ++(rho < r ? inside : outside);
  }
  EXPECT_GT(inside, 50);
  EXPECT_GT(outside, 50);
}

TEST(ClosedSurface, InwardSurfaceIsTurnedOutward) {
  SurfaceMesh inward = box_surface(Vector3(-1, -1, -1), Vector3(1, 2, 3));
  inward.triangles.col(1).swap(inward.triangles.col(2));
  ASSERT_LT(enclosed_volume(inward), 0);
  const ClosedSurface box(inward, "inward box");
  EXPECT_NEAR(box.volume(), 2.0 * 3.0 * 4.0, 1e-12);
  EXPECT_GT(enclosed_volume(box.mesh()), 0);
  EXPECT_TRUE(box.contains(Vector3(0, 0.5, 1)));
  EXPECT_FALSE(box.contains(Vector3(0, 2.5, 1)));
  EXPECT_NEAR(box.signed_distance(Vector3(0, 0.5, 1)), -1.0, 1e-12);
  EXPECT_NEAR(box.signed_distance(Vector3(0, 0.5, 5)), 2.0, 1e-12);
}

TEST(ClosedSurface, MovedSurfaceKeepsItsAnswers) {
  ClosedSurface first(icosphere(1.0, 2), "sphere");
  ClosedSurface moved = std::move(first);
  EXPECT_TRUE(moved.contains(Vector3::Zero()));
  EXPECT_FALSE(moved.contains(Vector3(1.1, 0, 0)));
}

TEST(ClosedSurface, RejectsAnEmptySurface) {
  SurfaceMesh empty;
  empty.vertices.resize(0, 3);
  empty.triangles.resize(0, 3);
  EXPECT_THAT(rejection(empty), AllOf(HasSubstr("surface \"bone\""), HasSubstr("no triangles")));
}

TEST(ClosedSurface, RejectsANanOrInfiniteVertex) {
  SurfaceMesh mesh = box_surface();
  mesh.vertices(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(rejection(mesh), AllOf(HasSubstr("surface \"bone\""), HasSubstr("NaN")));
  mesh.vertices(3, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THAT(rejection(mesh), HasSubstr("infinite"));
}

TEST(ClosedSurface, RejectsAnOpenSurfaceAndSuggestsFillingHoles) {
  const SurfaceMesh open = sinew::testing::without_triangle(box_surface(), 4);
  EXPECT_THAT(rejection(open), AllOf(HasSubstr("surface \"bone\""), HasSubstr("open"), HasSubstr("3 boundary edges"),
                                     HasSubstr("one at ("), HasSubstr("fill_holes")));
}

TEST(ClosedSurface, RejectsANonManifoldEdge) {
  // A fin on an edge of the cube: the edge (0, 1) is used by three triangles.
  SurfaceMesh mesh = box_surface();
  mesh.vertices.conservativeResize(9, 3);
  mesh.vertices.row(8) << 0.5, -1, -1;
  mesh.triangles.conservativeResize(13, 3);
  mesh.triangles.row(12) << 0, 1, 8;
  EXPECT_THAT(rejection(mesh), AllOf(HasSubstr("surface \"bone\""), HasSubstr("not a manifold"),
                                     HasSubstr("1 edges are shared by three or more triangles")));
}

TEST(ClosedSurface, RejectsInconsistentlyOrientedTriangles) {
  SurfaceMesh mesh = box_surface();
  std::swap(mesh.triangles(2, 1), mesh.triangles(2, 2));  // one triangle of the top face flipped
  EXPECT_THAT(rejection(mesh), AllOf(HasSubstr("surface \"bone\""), HasSubstr("inconsistently oriented")));
}

TEST(ClosedSurface, RejectsASurfaceEnclosingNoVolume) {
  // One triangle glued back to back with itself: closed, but flat.
  SurfaceMesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  mesh.triangles.resize(2, 3);
  mesh.triangles << 0, 1, 2, 0, 2, 1;
  EXPECT_THAT(rejection(mesh), HasSubstr("encloses no volume"));
}

}  // namespace
}  // namespace sinew::surface
