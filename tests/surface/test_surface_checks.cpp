/// @file test_surface_checks.cpp
/// surface_topology and enclosed_volume on hand-made surfaces.

#include "sinew/surface/surface_checks.hpp"

#include <gtest/gtest.h>

namespace sinew::surface {
namespace {

SurfaceMesh tet() {
  SurfaceMesh mesh;
  mesh.vertices.resize(4, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  mesh.triangles.resize(4, 3);
  mesh.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  return mesh;
}

TEST(SurfaceChecks, ClosedTetrahedron) {
  const SurfaceMesh mesh = tet();
  const SurfaceTopology topology = surface_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 0);
  EXPECT_EQ(topology.non_manifold_edges, 0);
  EXPECT_TRUE(topology.closed());
  EXPECT_NEAR(enclosed_volume(mesh), 1.0 / 6, 1e-15);
}

TEST(SurfaceChecks, InwardOrientationGivesNegativeVolume) {
  SurfaceMesh mesh = tet();
  mesh.triangles.col(1).swap(mesh.triangles.col(2));
  EXPECT_NEAR(enclosed_volume(mesh), -1.0 / 6, 1e-15);
  EXPECT_TRUE(surface_topology(mesh).closed());
}

TEST(SurfaceChecks, VolumeDoesNotDependOnTheOrigin) {
  SurfaceMesh mesh = tet();
  mesh.vertices.rowwise() += Eigen::RowVector3d(100, -50, 7);
  EXPECT_NEAR(enclosed_volume(mesh), 1.0 / 6, 1e-11);
}

TEST(SurfaceChecks, OpenSurfaceHasBoundaryEdges) {
  SurfaceMesh mesh = tet();
  mesh.triangles.conservativeResize(3, 3);  // one face removed: its three edges are open
  const SurfaceTopology topology = surface_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 3);
  EXPECT_EQ(topology.non_manifold_edges, 0);
  EXPECT_FALSE(topology.closed());
}

TEST(SurfaceChecks, ThreeTrianglesOnOneEdgeAreNonManifold) {
  SurfaceMesh mesh;
  mesh.vertices.resize(5, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1;
  mesh.triangles.resize(3, 3);
  mesh.triangles << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  const SurfaceTopology topology = surface_topology(mesh);
  EXPECT_EQ(topology.non_manifold_edges, 1);
  EXPECT_EQ(topology.boundary_edges, 6);
  EXPECT_FALSE(topology.closed());
}

}  // namespace
}  // namespace sinew::surface
