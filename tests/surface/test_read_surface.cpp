/// @file test_read_surface.cpp
/// read_surface on each format (ASCII and binary STL, OBJ, PLY, glTF, GLB), mesh selection by
/// name, node transforms, unit scale and rigid transform (docs/surface-input.md).

#include "sinew/surface/read_surface.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sinew/core/error.hpp"
#include "sinew/surface/surface_checks.hpp"
#include "support/temp_dir.hpp"
#include "surface/surface_fixtures.hpp"

namespace sinew::surface {
namespace {

using sinew::testing::TempDir;
using ::testing::HasSubstr;
namespace fx = sinew::testing;

void expect_closed_cube(const SurfaceMesh& mesh) {
  EXPECT_EQ(mesh.vertices.rows(), 8);
  EXPECT_EQ(mesh.triangles.rows(), 12);
  EXPECT_TRUE(surface_topology(mesh).closed());
  EXPECT_NEAR(enclosed_volume(mesh), 1.0, 1e-12);
}

TEST(ReadSurface, AsciiStl) {
  TempDir dir;
  const SurfaceMesh mesh = read_surface(dir.write("cube.stl", fx::ascii_stl(fx::unit_cube())));
  expect_closed_cube(mesh);
}

TEST(ReadSurface, BinaryStl) {
  TempDir dir;
  expect_closed_cube(read_surface(dir.write("cube.stl", fx::binary_stl(fx::unit_cube()))));
  const SurfaceMesh tet = read_surface(dir.write("tet.stl", fx::binary_stl(fx::unit_tet())));
  EXPECT_EQ(tet.vertices.rows(), 4);
  EXPECT_EQ(tet.triangles.rows(), 4);
  EXPECT_NEAR(enclosed_volume(tet), 1.0 / 6, 1e-12);
}

TEST(ReadSurface, Obj) {
  TempDir dir;
  expect_closed_cube(read_surface(dir.write("cube.obj", fx::obj(fx::unit_cube()))));
}

TEST(ReadSurface, AsciiPly) {
  TempDir dir;
  expect_closed_cube(read_surface(dir.write("cube.ply", fx::ascii_ply(fx::unit_cube()))));
}

TEST(ReadSurface, GltfWithDataUri) {
  TempDir dir;
  const std::string path = dir.write("shapes.gltf", fx::gltf_embedded({{"cube", fx::unit_cube()}}));
  const SurfaceMesh mesh = read_surface(path);
  EXPECT_EQ(mesh.name, "cube");
  expect_closed_cube(mesh);
}

TEST(ReadSurface, GlbByName) {
  TempDir dir;
  const std::string path = dir.write("shapes.glb", fx::glb({{"cube", fx::unit_cube()}, {"tet", fx::unit_tet()}}));
  EXPECT_EQ(surface_mesh_names(path), (std::vector<std::string>{"cube", "tet"}));
  expect_closed_cube(read_surface(path, {.mesh_name = "cube"}));
  const SurfaceMesh tet = read_surface(path, {.mesh_name = "tet"});
  EXPECT_EQ(tet.name, "tet");
  EXPECT_EQ(tet.vertices.rows(), 4);
  EXPECT_EQ(tet.triangles.rows(), 4);
  EXPECT_TRUE(surface_topology(tet).closed());
  EXPECT_NEAR(enclosed_volume(tet), 1.0 / 6, 1e-12);
}

TEST(ReadSurface, SameSurfaceFromEveryFormat) {
  TempDir dir;
  const fx::Shape cube = fx::unit_cube();
  const SurfaceMesh reference = read_surface(dir.write("a.stl", fx::ascii_stl(cube)));
  const std::vector<std::string> others = {
      dir.write("b.stl", fx::binary_stl(cube)), dir.write("c.obj", fx::obj(cube)),
      dir.write("d.ply", fx::ascii_ply(cube)), dir.write("e.gltf", fx::gltf_embedded({{"cube", cube}})),
      dir.write("f.glb", fx::glb({{"cube", cube}}))};
  for (const std::string& path : others) {
    SCOPED_TRACE(path);
    const SurfaceMesh mesh = read_surface(path);
    EXPECT_EQ(fx::sorted_vertices(mesh), fx::sorted_vertices(reference));
    EXPECT_EQ(fx::sorted_triangles(mesh), fx::sorted_triangles(reference));  // same winding too
  }
}

TEST(ReadSurface, UpperCaseExtension) {
  TempDir dir;
  expect_closed_cube(read_surface(dir.write("CUBE.STL", fx::binary_stl(fx::unit_cube()))));
}

TEST(ReadSurface, UnknownNameListsTheNames) {
  TempDir dir;
  const std::string path = dir.write("shapes.glb", fx::glb({{"cube", fx::unit_cube()}, {"tet", fx::unit_tet()}}));
  try {
    read_surface(path, {.mesh_name = "femur"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("shapes.glb"));
    EXPECT_THAT(e.what(), HasSubstr("no mesh 'femur'"));
    EXPECT_THAT(e.what(), HasSubstr("'cube', 'tet'"));
  }
}

TEST(ReadSurface, SeveralMeshesNeedAName) {
  TempDir dir;
  const std::string path = dir.write("shapes.gltf", fx::gltf_embedded({{"cube", fx::unit_cube()}, {"tet", fx::unit_tet()}}));
  try {
    read_surface(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("shapes.gltf"));
    EXPECT_THAT(e.what(), HasSubstr("has 2 meshes ('cube', 'tet')"));
    EXPECT_THAT(e.what(), HasSubstr("choose one by name"));
  }
}

TEST(ReadSurface, NodeTransformsPlaceTheMesh) {
  TempDir dir;
  const std::string path =
      dir.write("moved.glb", fx::glb({{"cube", fx::unit_cube()}, {"tet", fx::unit_tet()}}, {{0, 0, 0}, {10, -2, 3}}));
  const SurfaceMesh tet = read_surface(path, {.mesh_name = "tet"});
  EXPECT_EQ(tet.vertices.colwise().minCoeff(), Eigen::RowVector3d(10, -2, 3));
  EXPECT_EQ(tet.vertices.colwise().maxCoeff(), Eigen::RowVector3d(11, -1, 4));
  EXPECT_NEAR(enclosed_volume(tet), 1.0 / 6, 1e-12);
}

TEST(ReadSurface, UnitScaleAndRigidTransform) {
  TempDir dir;
  const std::string path = dir.write("cube.stl", fx::binary_stl(fx::unit_cube()));
  const SurfaceMesh scaled = read_surface(path, {.unit_scale = 1000});
  EXPECT_NEAR(enclosed_volume(scaled), 1e9, 1e-3);  // s^3
  EXPECT_EQ(scaled.vertices.colwise().maxCoeff(), Eigen::RowVector3d(1000, 1000, 1000));

  const Matrix3 quarter_turn_z = Eigen::AngleAxisd(EIGEN_PI / 2, Vector3::UnitZ()).toRotationMatrix();
  const SurfaceMesh moved =
      read_surface(path, {.unit_scale = 2, .rotation = quarter_turn_z, .translation = Vector3(5, 0, -1)});
  EXPECT_NEAR(enclosed_volume(moved), 8.0, 1e-12);  // a rotation keeps the orientation
  EXPECT_TRUE(moved.vertices.colwise().minCoeff().isApprox(Eigen::RowVector3d(3, 0, -1), 1e-12));
  EXPECT_TRUE(moved.vertices.colwise().maxCoeff().isApprox(Eigen::RowVector3d(5, 2, 1), 1e-12));
}

TEST(ReadSurface, ExternalBufferIsRefused) {
  // The choice (docs/surface-input.md): every external URI is refused, even one beside the file.
  TempDir dir;
  const fx::Gltf g = fx::gltf({{"cube", fx::unit_cube()}}, "cube.bin");
  dir.write("cube.bin", g.bin);
  const std::string path = dir.write("cube.gltf", g.json);
  try {
    read_surface(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cube.gltf"));
    EXPECT_THAT(e.what(), HasSubstr("cube.bin"));
    EXPECT_THAT(e.what(), HasSubstr("external files are refused"));
  }
}

TEST(ReadSurface, ObjMaterialLibraryIsNotRead) {
  TempDir dir;
  dir.write("look.mtl", "newmtl red\nKd 1 0 0\n");
  const std::string path = dir.write("cube.obj", "mtllib look.mtl\n" + fx::obj(fx::unit_cube()));
  expect_closed_cube(read_surface(path));  // the surface is read; the library beside it is not opened
}

}  // namespace
}  // namespace sinew::surface
