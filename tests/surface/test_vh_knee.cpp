/// @file test_vh_knee.cpp
/// The Visible Human Male knee and skin (HRA 3D reference organs, /work/shared/data/vh-knee,
/// never copied into the repository): mesh names, counts and closedness as the data's README
/// states them. Skipped, with a message, when the files are absent.

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <gtest/gtest.h>

#include "sinew/core/stopwatch.hpp"
#include "sinew/surface/read_surface.hpp"
#include "sinew/surface/surface_checks.hpp"

namespace sinew::surface {
namespace {

const std::string kDataDir = SINEW_SOURCE_DIR "/../shared/data/vh-knee";

std::string data_file(const std::string& name) {
  const std::string path = kDataDir + "/" + name;
  return std::filesystem::exists(path) ? path : "";
}

TEST(VhKnee, MeshNames) {
  const std::string path = data_file("VH_M_Knee_R.glb");
  if (path.empty()) GTEST_SKIP() << "VH knee data not found at " << kDataDir << "/VH_M_Knee_R.glb";
  const std::vector<std::string> names = surface_mesh_names(path);
  for (const char* bone : {"VH_M_femur_R", "VH_M_tibia_R", "VH_M_fibula_R", "VH_M_patella_R"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), bone), names.end()) << bone;
  }
}

TEST(VhKnee, PatellaIsClosed) {
  const std::string path = data_file("VH_M_Knee_R.glb");
  if (path.empty()) GTEST_SKIP() << "VH knee data not found at " << kDataDir << "/VH_M_Knee_R.glb";
  const auto start = std::chrono::steady_clock::now();
  const SurfaceMesh patella = read_surface(path, {.mesh_name = "VH_M_patella_R", .unit_scale = 1000});
  std::cout << "VH_M_Knee_R.glb (all meshes imported, the patella kept) read in " << seconds_since(start) << " s\n";
  EXPECT_EQ(patella.vertices.rows(), 454);
  EXPECT_EQ(patella.triangles.rows(), 904);
  EXPECT_TRUE(surface_topology(patella).closed());
  EXPECT_GT(enclosed_volume(patella), 0);
}

TEST(VhKnee, BonesAsTheReadmeCountsThem) {
  const std::string path = data_file("VH_M_Knee_R.glb");
  if (path.empty()) GTEST_SKIP() << "VH knee data not found at " << kDataDir << "/VH_M_Knee_R.glb";
  struct Expected {
    const char* name;
    Index vertices, triangles;
  };
  for (const Expected& bone : {Expected{"VH_M_femur_R", 6053, 11974}, Expected{"VH_M_tibia_R", 1758, 3512},
                               Expected{"VH_M_fibula_R", 1577, 3150}}) {
    SCOPED_TRACE(bone.name);
    const SurfaceMesh mesh = read_surface(path, {.mesh_name = bone.name});
    EXPECT_EQ(mesh.vertices.rows(), bone.vertices);
    EXPECT_EQ(mesh.triangles.rows(), bone.triangles);
    const SurfaceTopology topology = surface_topology(mesh);
    if (std::string(bone.name) == "VH_M_femur_R") {
      EXPECT_EQ(topology.boundary_edges, 134);
    } else {
      EXPECT_TRUE(topology.closed());
      EXPECT_GT(enclosed_volume(mesh), 0);
    }
  }
}

TEST(VhKnee, SkinIsClosed) {
  const std::string path = data_file("VH_M_Skin.glb");
  if (path.empty()) GTEST_SKIP() << "VH skin data not found at " << kDataDir << "/VH_M_Skin.glb";
  const auto start = std::chrono::steady_clock::now();
  const SurfaceMesh skin = read_surface(path);
  std::cout << "VH_M_Skin.glb read in " << seconds_since(start) << " s\n";
  EXPECT_EQ(skin.vertices.rows(), 53669);
  EXPECT_EQ(skin.triangles.rows(), 107334);
  EXPECT_TRUE(surface_topology(skin).closed());
  EXPECT_GT(enclosed_volume(skin), 0);
}

}  // namespace
}  // namespace sinew::surface
