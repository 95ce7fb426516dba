/// @file test_read_surface_errors.cpp
/// Every bad input to read_surface is an InputError naming the file (docs/surface-input.md).

#include <sys/stat.h>

#include <cmath>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <limits>

#include "sinew/core/error.hpp"
#include "sinew/surface/read_surface.hpp"
#include "support/temp_dir.hpp"
#include "surface/surface_fixtures.hpp"

namespace sinew::surface {
namespace {

using sinew::testing::TempDir;
using ::testing::HasSubstr;
namespace fx = sinew::testing;

/// The message of the InputError read_surface throws (fails the test when there is none).
std::string error_of(const std::string& path, const SurfaceReadOptions& options = {}) {
  try {
    read_surface(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << path;
  return "";
}

TEST(ReadSurfaceErrors, MissingFile) {
  TempDir dir;
  const std::string message = error_of(dir.file("none.stl"));
  EXPECT_THAT(message, HasSubstr("none.stl"));
  EXPECT_THAT(message, HasSubstr("does not exist"));
}

TEST(ReadSurfaceErrors, Directory) {
  TempDir dir;
  std::filesystem::create_directory(dir / "folder.stl");
  EXPECT_THAT(error_of(dir.file("folder.stl")), HasSubstr("is a directory, not a regular file"));
}

TEST(ReadSurfaceErrors, FifoIsRefusedWithoutOpening) {
  TempDir dir;
  const std::string path = dir.file("pipe.stl");
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  EXPECT_THAT(error_of(path), HasSubstr("FIFO"));  // returns: opening it would block
}

TEST(ReadSurfaceErrors, WrongExtension) {
  TempDir dir;
  const std::string message = error_of(dir.write("cube.step", fx::ascii_stl(fx::unit_cube())));
  EXPECT_THAT(message, HasSubstr("cube.step"));
  EXPECT_THAT(message, HasSubstr("unknown extension '.step'"));
  EXPECT_THAT(message, HasSubstr(".stl, .obj, .ply, .gltf, .glb"));
}

TEST(ReadSurfaceErrors, EmptyFile) {
  TempDir dir;
  EXPECT_THAT(error_of(dir.write("empty.obj", "")), HasSubstr("'" + dir.file("empty.obj") + "' is empty"));
}

TEST(ReadSurfaceErrors, TruncatedBinaryStl) {
  TempDir dir;
  std::string bytes = fx::binary_stl(fx::unit_cube());
  bytes.resize(bytes.size() - 30);
  const std::string message = error_of(dir.write("cut.stl", bytes));
  EXPECT_THAT(message, HasSubstr("cut.stl"));
  EXPECT_THAT(message, HasSubstr("cannot be read as .stl"));
}

TEST(ReadSurfaceErrors, TruncatedGlb) {
  TempDir dir;
  std::string bytes = fx::glb({{"cube", fx::unit_cube()}});
  bytes.resize(bytes.size() / 2);
  EXPECT_THAT(error_of(dir.write("cut.glb", bytes)), HasSubstr("cannot be read as .glb"));
}

TEST(ReadSurfaceErrors, NanVertex) {
  TempDir dir;
  std::string text = fx::ascii_stl(fx::unit_cube());
  text.replace(text.find("vertex 0 0 0"), 12, "vertex 0 nan 0");
  const std::string message = error_of(dir.write("nan.stl", text));
  EXPECT_THAT(message, HasSubstr("nan.stl"));
  EXPECT_THAT(message, HasSubstr("not finite"));
}

TEST(ReadSurfaceErrors, GarbageText) {
  TempDir dir;
  for (const char* name : {"junk.stl", "junk.obj", "junk.ply", "junk.gltf", "junk.glb"}) {
    SCOPED_TRACE(name);
    const std::string message = error_of(dir.write(name, "this is not a mesh at all\n\x01\x02 {[ 17"));
    EXPECT_THAT(message, HasSubstr(name));
  }
}

TEST(ReadSurfaceErrors, IndexOutOfRange) {
  TempDir dir;
  std::string text = fx::ascii_ply(fx::unit_tet());
  text.replace(text.rfind("3 1 2 3"), 7, "3 1 2 9");
  // Checked before Assimp's post-processing reads vertices through the indices.
  const std::string message = error_of(dir.write("bad.ply", text));
  EXPECT_THAT(message, HasSubstr("bad.ply"));
  EXPECT_THAT(message, HasSubstr("face 3 refers to vertex 9 of 4"));
  EXPECT_THAT(error_of(dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")), HasSubstr("bad.obj"));
}

TEST(ReadSurfaceErrors, NoTriangles) {
  TempDir dir;
  const std::string message = error_of(dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"));
  EXPECT_THAT(message, HasSubstr("points.obj"));
  EXPECT_THAT(message, HasSubstr("has no triangles"));
}

TEST(ReadSurfaceErrors, BadScale) {
  TempDir dir;
  const std::string path = dir.write("cube.stl", fx::binary_stl(fx::unit_cube()));
  for (double s : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    SCOPED_TRACE(s);
    const std::string message = error_of(path, {.unit_scale = s});
    EXPECT_THAT(message, HasSubstr("cube.stl"));
    EXPECT_THAT(message, HasSubstr("unit_scale must be positive and finite"));
  }
}

TEST(ReadSurfaceErrors, BadRotationOrTranslation) {
  TempDir dir;
  const std::string path = dir.write("cube.stl", fx::binary_stl(fx::unit_cube()));
  Matrix3 stretched = Matrix3::Identity();
  stretched(0, 0) = 1.01;
  Matrix3 mirror = Matrix3::Identity();
  mirror(2, 2) = -1;
  for (const Matrix3& r : {stretched, mirror}) {
    EXPECT_THAT(error_of(path, {.rotation = r}), HasSubstr("proper rotation"));
  }
  EXPECT_THAT(error_of(path, {.translation = Vector3(0, std::nan(""), 0)}), HasSubstr("translation must be finite"));
}

TEST(ReadSurfaceErrors, AssimpPrintsNothing) {
  TempDir dir;
  const std::string good = dir.write("cube.obj", "mtllib missing.mtl\n" + fx::obj(fx::unit_cube()));
  const std::string bad = dir.write("junk.glb", "glTF not really");
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  read_surface(good);
  const std::string message = error_of(bad);
  const std::string out = ::testing::internal::GetCapturedStdout();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(message, HasSubstr("junk.glb"));
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
}

TEST(ReadSurfaceErrors, MeshNamesOfABadFile) {
  TempDir dir;
  EXPECT_THROW(surface_mesh_names(dir.file("none.glb")), InputError);
  EXPECT_THROW(surface_mesh_names(dir.write("junk.glb", "glTF")), InputError);
}

}  // namespace
}  // namespace sinew::surface
