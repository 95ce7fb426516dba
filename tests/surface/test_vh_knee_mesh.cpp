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

/// The four bones as four regions of one mesh (they do not overlap), at the VH knee scene's
/// element size 10 mm and a facet distance of 0.1 mm: every region's volume within 1 % of
/// the volume its closed surface encloses.
TEST(VhKneeMesh, FourBonesMeshToTheirVolumes) {
  if (!std::filesystem::exists(kKnee)) GTEST_SKIP() << "VH knee data not found at " << kKnee;
#ifdef SINEW_SANITIZER_BUILD
  GTEST_SKIP() << "about a minute in Release; the patella test covers the same code instrumented";
#endif
  SurfaceLibrary library;
  std::vector<SolidPart> parts;
  for (const char* name : {"femur", "tibia", "fibula", "patella"}) {
    library.emplace(name, ClosedSurface(repair_surface(bone(std::string("VH_M_") + name + "_R"), {}), name));
    parts.push_back({name, {.kind = Solid::Kind::Surface, .surfaces = {name}}});
  }
  TetrahedralizeReport report;
  const mesh::TetMesh mesh =
      tetrahedralize(parts, library, {.element_size = 10, .facet_distance = 0.1, .what = "VH bones"}, &report);
  std::cout << "VH bones (mm) at element_size 10, facet_distance 0.1: " << mesh.num_nodes() << " nodes, " << mesh.num_tets()
            << " tets in " << report.seconds << " s; min dihedral " << report.quality.min_dihedral_deg
            << " deg, worst radius ratio " << report.quality.worst_radius_ratio << ", " << report.quality.slivers
            << " tets below 5 deg\n";
  for (std::size_t r = 0; r < parts.size(); ++r) {
    const double surface_volume = library.at(parts[r].region).volume();
    std::cout << "  " << parts[r].region << ": " << report.tets_per_region[r] << " tets, volume " << report.region_volumes[r]
              << " mm^3 vs surface " << surface_volume << " mm^3 (" << 100 * (report.region_volumes[r] / surface_volume - 1)
              << " %)\n";
    EXPECT_NEAR(report.region_volumes[r], surface_volume, 0.01 * surface_volume) << parts[r].region;
  }
  EXPECT_NO_THROW(mesh::validate(mesh, "VH bones"));
}

}  // namespace
}  // namespace sinew::surface
