/// @file test_vh_knee_mesh.cpp
/// The Visible Human Male knee bones (/work/shared/data/vh-knee, never copied into the
/// repository) repaired and meshed: the evidence that scanned surfaces become regions. Prints
/// the mesh's size, quality and time. Skipped, with a message, when the files are absent.

#include <filesystem>
#include <iostream>
#include <gtest/gtest.h>

#include "sinew/surface/closed_surface.hpp"
#include "sinew/surface/read_surface.hpp"
#include "sinew/surface/repair_surface.hpp"
#include "sinew/surface/surface_checks.hpp"
#include "sinew/surface/tetrahedralize.hpp"

namespace sinew::surface {
namespace {

const std::string kKnee = SINEW_SOURCE_DIR "/../shared/data/vh-knee/VH_M_Knee_R.glb";

SurfaceMesh bone(const std::string& name) { return read_surface(kKnee, {.mesh_name = name, .unit_scale = 1000}); }

TEST(VhKneeMesh, RepairClosesEveryBone) {
  if (!std::filesystem::exists(kKnee)) GTEST_SKIP() << "VH knee data not found at " << kKnee;
  for (const char* name : {"VH_M_patella_R", "VH_M_tibia_R", "VH_M_fibula_R"}) {
    SCOPED_TRACE(name);
    const SurfaceMesh surface = bone(name);
    RepairReport report;
    const SurfaceMesh repaired = repair_surface(surface, {}, &report);
    EXPECT_EQ(report.holes_filled, 0);
    EXPECT_TRUE(surface_topology(repaired).closed());
    EXPECT_NO_THROW(ClosedSurface(repaired, name));
  }
  // The femur is open: three holes, 134 boundary edges.
  const SurfaceMesh femur = bone("VH_M_femur_R");
  ASSERT_EQ(surface_topology(femur).boundary_edges, 134);
  RepairReport report;
  const SurfaceMesh repaired = repair_surface(femur, {}, &report);
  std::cout << "VH_M_femur_R: " << report.holes_filled << " holes filled with " << report.triangles_added
            << " triangles; dropped " << report.degenerate_dropped << " degenerate, " << report.duplicates_dropped
            << " duplicate, " << report.non_manifold_dropped << " non-manifold\n";
  EXPECT_EQ(report.holes_filled, 3);
  EXPECT_EQ(surface_topology(repaired).boundary_edges, 0);
  EXPECT_TRUE(surface_topology(repaired).closed());
  const ClosedSurface closed(repaired, "VH_M_femur_R");
  EXPECT_GT(closed.volume(), 0);
}

TEST(VhKneeMesh, PatellaMeshesToItsVolume) {
  if (!std::filesystem::exists(kKnee)) GTEST_SKIP() << "VH knee data not found at " << kKnee;
  SurfaceLibrary library;
  library.emplace("patella", ClosedSurface(repair_surface(bone("VH_M_patella_R"), {}), "patella"));
  const double volume = library.at("patella").volume();
  TetrahedralizeReport report;
  const mesh::TetMesh mesh = tetrahedralize({{"patella", {.kind = Solid::Kind::Surface, .surfaces = {"patella"}}}}, library,
                                            {.element_size = 4, .facet_distance = 0.05, .what = "patella"}, &report);
  std::cout << "VH_M_patella_R (mm) at element_size 4, facet_distance 0.05: " << mesh.num_nodes() << " nodes, "
            << mesh.num_tets() << " tets, min dihedral " << report.quality.min_dihedral_deg << " deg, worst radius ratio "
            << report.quality.worst_radius_ratio << ", mean radius ratio " << report.quality.mean_radius_ratio << ", "
            << report.quality.slivers << " tets below 5 deg, region volume " << report.region_volumes[0]
            << " mm^3 vs surface " << volume << " mm^3 (" << 100 * (report.region_volumes[0] / volume - 1) << " %), "
            << report.seconds << " s\n";
  EXPECT_NEAR(report.region_volumes[0], volume, 0.01 * volume);
  EXPECT_NO_THROW(mesh::validate(mesh, "patella"));
  EXPECT_GT(report.quality.min_dihedral_deg, 1.0);
}

}  // namespace
}  // namespace sinew::surface
