/// @file test_repair_surface.cpp
/// repair_surface (degenerate and duplicate triangles dropped, holes filled) and
/// find_self_intersections on hand-made surfaces.

#include "sinew/surface/repair_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sinew/surface/closed_surface.hpp"
#include "sinew/surface/surface_checks.hpp"
#include "surface/closed_fixtures.hpp"

namespace sinew::surface {
namespace {

using sinew::testing::box_surface;
using sinew::testing::icosphere;
using sinew::testing::without_triangle;

/// The unit cube with a repeated-vertex triangle, a zero-area one (on a new vertex in the middle
/// of an edge), and two copies of existing triangles (one rotated, one with the other winding).
SurfaceMesh cube_with_junk() {
  SurfaceMesh mesh = box_surface();
  mesh.vertices.conservativeResize(9, 3);
  mesh.vertices.row(8) << 0.5, 0, 0;
  mesh.triangles.conservativeResize(16, 3);
  mesh.triangles.row(12) << 0, 0, 1;  // repeated vertex
  mesh.triangles.row(13) << 0, 8, 1;  // collinear: zero area
  mesh.triangles.row(14) << 5, 4, 0;  // row 5 (0 5 4), rotated
  mesh.triangles.row(15) << 1, 2, 0;  // row 0 (0 2 1), reversed
  return mesh;
}

TEST(RepairSurface, DropsDegenerateAndDuplicateTriangles) {
  RepairReport report;
  const SurfaceMesh repaired = repair_surface(cube_with_junk(), {}, &report);
  EXPECT_EQ(report.degenerate_dropped, 2);
  EXPECT_EQ(report.duplicates_dropped, 2);
  EXPECT_EQ(report.holes_filled, 0);
  EXPECT_EQ(report.triangles_added, 0);
  EXPECT_EQ(report.non_manifold_dropped, 0);
  EXPECT_EQ(repaired.triangles.rows(), 12);
  EXPECT_TRUE(surface_topology(repaired).closed());
  EXPECT_NEAR(enclosed_volume(repaired), 1.0, 1e-14);
  EXPECT_EQ(repaired.name, "box");
}

TEST(RepairSurface, KeepsWhatTheOptionsSayToKeep) {
  // Without the drops, the copies reach CGAL, which refuses each as a non-manifold face.
  RepairReport report;
  const SurfaceMesh mesh = cube_with_junk();
  const SurfaceMesh kept =
      repair_surface(mesh, {.drop_degenerate = true, .drop_duplicates = false, .fill_holes = false}, &report);
  EXPECT_EQ(report.degenerate_dropped, 2);
  EXPECT_EQ(report.duplicates_dropped, 0);
  EXPECT_EQ(report.non_manifold_dropped, 2);
  EXPECT_TRUE(surface_topology(kept).closed());
}

TEST(RepairSurface, CleanSurfaceIsUnchanged) {
  RepairReport report;
  const SurfaceMesh sphere = icosphere(3.0, 2);
  const SurfaceMesh repaired = repair_surface(sphere, {}, &report);
  EXPECT_EQ(report.degenerate_dropped + report.duplicates_dropped + report.holes_filled + report.non_manifold_dropped, 0);
  EXPECT_EQ(repaired.vertices, sphere.vertices);
  EXPECT_EQ(repaired.triangles, sphere.triangles);
  EXPECT_EQ(report.triangles_remeshed, 0);  // remeshing is off by default
}

/// Mean edge length of a surface's triangles (each interior edge counted twice).
double mean_edge_length(const SurfaceMesh& mesh) {
  double sum = 0;
  for (Index t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      sum += (mesh.vertices.row(mesh.triangles(t, (k + 1) % 3)) - mesh.vertices.row(mesh.triangles(t, k))).norm();
  return sum / (3.0 * static_cast<double>(mesh.triangles.rows()));
}

TEST(RepairSurface, RemeshesFinerAndCoarserTowardTheTargetEdgeLength) {
  for (const auto& [subdivisions, target] : {std::pair{1, 1.5}, std::pair{4, 3.0}}) {
    const SurfaceMesh sphere = icosphere(10.0, subdivisions);
    const double edge_before = mean_edge_length(sphere);
    RepairReport report;
    const SurfaceMesh remeshed = repair_surface(sphere, {.remesh_edge_length = target}, &report);
    const double edge_after = mean_edge_length(remeshed);
    std::printf("[ remesh   ] icosphere %d: %td triangles, mean edge %.3f -> %td triangles, mean edge %.3f "
                "(target %.1f), volume %.2f -> %.2f\n",
                subdivisions, sphere.triangles.rows(), edge_before, remeshed.triangles.rows(), edge_after, target,
                enclosed_volume(sphere), enclosed_volume(remeshed));
    EXPECT_EQ(report.triangles_remeshed, remeshed.triangles.rows());
    EXPECT_TRUE(report.closed_before_remesh);
    EXPECT_NEAR(report.volume_before_remesh, enclosed_volume(sphere), 1e-9 * enclosed_volume(sphere));
    EXPECT_NEAR(report.volume_after_remesh, enclosed_volume(remeshed), 1e-9 * enclosed_volume(sphere));
    EXPECT_NEAR(edge_after, target, 0.25 * target);
    EXPECT_TRUE(surface_topology(remeshed).closed());
    EXPECT_NO_THROW(ClosedSurface(remeshed, "remeshed sphere"));
    EXPECT_TRUE(find_self_intersections(remeshed).empty());
    // The vertices stay on the input polyhedron; coarser chords of the curved surface cut off a
    // little volume (2.7 % from 5120 triangles to 448).
    EXPECT_NEAR(enclosed_volume(remeshed), enclosed_volume(sphere), 0.04 * enclosed_volume(sphere));
    for (Index v = 0; v < remeshed.vertices.rows(); ++v)
      ASSERT_LE(remeshed.vertices.row(v).norm(), 10.0 + 1e-9) << "vertex " << v << " off the sphere";
  }
}

TEST(RepairSurface, FillsTheMissingFaceOfACube) {
  // Both triangles of the top face (z = 1) removed: one hole of four edges.
  const SurfaceMesh open = without_triangle(without_triangle(box_surface(), 3), 2);
  ASSERT_EQ(surface_topology(open).boundary_edges, 4);
  RepairReport report;
  const SurfaceMesh closed = repair_surface(open, {}, &report);
  EXPECT_EQ(report.holes_filled, 1);
  EXPECT_GE(report.triangles_added, 2);
  EXPECT_EQ(closed.triangles.rows(), 10 + report.triangles_added);
  EXPECT_TRUE(surface_topology(closed).closed());
  EXPECT_NEAR(enclosed_volume(closed), 1.0, 1e-9);
  EXPECT_NO_THROW(ClosedSurface(closed, "filled cube"));
}

TEST(RepairSurface, FillsEveryHoleOfASphere) {
  const SurfaceMesh sphere = icosphere(5.0, 2);
  const double volume = enclosed_volume(sphere);
  // Two triangles far apart (the first and the last of the subdivision) removed: two holes.
  const SurfaceMesh open = without_triangle(without_triangle(sphere, sphere.triangles.rows() - 1), 0);
  ASSERT_EQ(surface_topology(open).boundary_edges, 6);
  RepairReport report;
  const SurfaceMesh closed = repair_surface(open, {}, &report);
  EXPECT_EQ(report.holes_filled, 2);
  EXPECT_EQ(report.triangles_added, 2);  // a triangular hole takes one triangle
  EXPECT_TRUE(surface_topology(closed).closed());
  EXPECT_NEAR(enclosed_volume(closed), volume, 1e-9 * volume);
  // Off, the holes stay.
  RepairReport off;
  const SurfaceMesh still_open = repair_surface(open, {.fill_holes = false}, &off);
  EXPECT_EQ(off.holes_filled, 0);
  EXPECT_EQ(surface_topology(still_open).boundary_edges, 6);
}

TEST(RepairSurface, EmptySurfaceGivesAnEmptySurface) {
  SurfaceMesh empty;
  empty.vertices.resize(0, 3);
  empty.triangles.resize(0, 3);
  RepairReport report;
  const SurfaceMesh repaired = repair_surface(empty, {}, &report);
  EXPECT_EQ(repaired.triangles.rows(), 0);
  EXPECT_EQ(report.holes_filled, 0);
}

TEST(FindSelfIntersections, TwoCrossingBoxesCrossInTheirOverlap) {
  // [0,2]^3 and [1,3]^3 as one surface: their faces cross inside the overlap [1,2]^3.
  const SurfaceMesh boxes = sinew::testing::merged(box_surface(Vector3::Zero(), Vector3::Constant(2)),
                                                   box_surface(Vector3::Ones(), Vector3::Constant(3)));
  const std::vector<SelfIntersection> all = find_self_intersections(boxes, 0);
  ASSERT_FALSE(all.empty());
  for (const SelfIntersection& hit : all) {
    SCOPED_TRACE(::testing::Message() << "triangles " << hit.triangle_a << ", " << hit.triangle_b << " at "
                                      << hit.location.transpose());
    // One triangle of each box (each box alone is clean).
    EXPECT_EQ(std::min(hit.triangle_a, hit.triangle_b) < 12, std::max(hit.triangle_a, hit.triangle_b) >= 12);
    EXPECT_LT(std::max(hit.triangle_a, hit.triangle_b), 24);
    // Inside the overlap, and on the surface of both boxes: some coordinate is 2 (a face of
    // the first box there) and some is 1 (the second's).
    EXPECT_TRUE((hit.location.array() >= 1 - 1e-9).all() && (hit.location.array() <= 2 + 1e-9).all());
    EXPECT_TRUE(((hit.location.array() - 2).abs() < 1e-9).any());
    EXPECT_TRUE(((hit.location.array() - 1).abs() < 1e-9).any());
  }
  EXPECT_EQ(find_self_intersections(boxes, 1).size(), 1u);
  EXPECT_EQ(find_self_intersections(boxes).size(), std::min<std::size_t>(10, all.size()));
}

TEST(FindSelfIntersections, CleanSurfacesHaveNone) {
  EXPECT_TRUE(find_self_intersections(box_surface()).empty());
  EXPECT_TRUE(find_self_intersections(icosphere(1.0, 3)).empty());
  // Two boxes apart, one surface: still none.
  EXPECT_TRUE(find_self_intersections(sinew::testing::merged(box_surface(), box_surface(Vector3::Constant(2), Vector3::Constant(3))), 0)
                  .empty());
}

}  // namespace
}  // namespace sinew::surface
