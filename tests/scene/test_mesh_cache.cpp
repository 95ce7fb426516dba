/// @file test_mesh_cache.cpp
/// The mesh cache (scene/mesh_cache.hpp): entries round-trip, a wrong, corrupt or invalid entry
/// is a miss that says why, the key follows the mesh section, the element size and the surface
/// files' bytes, and build_problem meshes once, then reads the entry.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "sinew/core/error.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/mesh_cache.hpp"
#include "support/contact_scenes.hpp"
#include "support/temp_dir.hpp"

namespace sinew::scene {
namespace {

using ::testing::HasSubstr;

/// Two positively oriented tets sharing a face, in two regions, with a node set and a face set.
mesh::TetMesh two_tets() {
  mesh::TetMesh mesh;
  mesh.rest.resize(5, 3);
  mesh.rest << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1;
  mesh.tets.resize(2, 4);
  mesh.tets << 0, 1, 2, 3, 0, 2, 1, 4;
  mesh.region.resize(2);
  mesh.region << 0, 1;
  mesh.region_names = {"upper", "lower"};
  mesh.node_sets["apex"] = {3};
  mesh.face_sets["base"] = (Triangles(1, 3) << 0, 1, 2).finished();
  return mesh;
}

std::vector<std::filesystem::path> entries(const std::filesystem::path& directory) {
  std::vector<std::filesystem::path> found;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) found.push_back(entry.path());
  return found;
}

TEST(MeshCache, AnEntryGivesBackTheMeshItHolds) {
  sinew::testing::TempDir dir;
  const std::string file = mesh_cache_file(dir.file("cache"), "key");
  EXPECT_THAT(file, HasSubstr(".sinew-mesh"));
  std::string problem = "stale";
  EXPECT_FALSE(read_cached_mesh(file, "key", problem));
  EXPECT_EQ(problem, "");  // no entry: a plain miss
  const mesh::TetMesh mesh = two_tets();
  write_cached_mesh(file, "key", mesh);  // creates the directory
  const auto read = read_cached_mesh(file, "key", problem);
  ASSERT_TRUE(read) << problem;
  EXPECT_EQ(read->rest, mesh.rest);
  EXPECT_EQ(read->tets, mesh.tets);
  EXPECT_EQ(read->region, mesh.region);
  EXPECT_EQ(read->region_names, mesh.region_names);
  EXPECT_EQ(read->node_sets, mesh.node_sets);
  ASSERT_EQ(read->face_sets.count("base"), 1u);
  EXPECT_EQ(read->face_sets.at("base"), mesh.face_sets.at("base"));
}

TEST(MeshCache, AnEntryOfAnotherKeyIsAMiss) {
  sinew::testing::TempDir dir;
  const std::string file = dir.file("entry.sinew-mesh");
  write_cached_mesh(file, "one key", two_tets());
  std::string problem;
  EXPECT_FALSE(read_cached_mesh(file, "another key", problem));
  EXPECT_THAT(problem, HasSubstr("another key"));
}

TEST(MeshCache, ACorruptTruncatedOrForeignFileIsAMissThatSaysWhy) {
  sinew::testing::TempDir dir;
  std::string problem;
  EXPECT_FALSE(read_cached_mesh(dir.write("garbage.sinew-mesh", "not CBOR at all"), "key", problem));
  EXPECT_THAT(problem, HasSubstr("not a sinew mesh cache entry"));
  const std::string file = dir.file("truncated.sinew-mesh");
  write_cached_mesh(file, "key", two_tets());
  std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
  EXPECT_FALSE(read_cached_mesh(file, "key", problem));
  EXPECT_THAT(problem, HasSubstr("unreadable entry"));
  EXPECT_FALSE(read_cached_mesh(dir.path().string(), "key", problem));  // a directory
  EXPECT_THAT(problem, HasSubstr("not a regular file"));
}

TEST(MeshCache, AnEntryWithAnInvertedTetOrAnIndexOutOfRangeIsAMiss) {
  sinew::testing::TempDir dir;
  mesh::TetMesh inverted = two_tets();
  std::swap(inverted.tets(0, 0), inverted.tets(0, 1));
  const std::string file = dir.file("inverted.sinew-mesh");
  write_cached_mesh(file, "key", inverted);
  std::string problem;
  EXPECT_FALSE(read_cached_mesh(file, "key", problem));
  EXPECT_THAT(problem, HasSubstr("inverted"));
  mesh::TetMesh out_of_range = two_tets();
  out_of_range.region[1] = 7;
  write_cached_mesh(file, "key", out_of_range);
  EXPECT_FALSE(read_cached_mesh(file, "key", problem));
  EXPECT_THAT(problem, HasSubstr("region is out of range"));
  out_of_range = two_tets();
  out_of_range.node_sets["apex"] = {99};
  write_cached_mesh(file, "key", out_of_range);
  EXPECT_FALSE(read_cached_mesh(file, "key", problem));
  EXPECT_THAT(problem, HasSubstr("node set \"apex\""));
}

TEST(MeshCache, TakesAPinchedBoundaryEdgeAsTheSurfaceMesherLeavesItButNotACrowdedFace) {
  sinew::testing::TempDir dir;
  const std::string file = dir.file("entry.sinew-mesh");
  std::string problem;
  // Two tets that share the edge (0, 1) and nothing else: that edge joins four boundary triangles.
  mesh::TetMesh pinched;
  pinched.rest.resize(6, 3);
  pinched.rest << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, 0.3, 1, 0.5, -1, 0, 0.5, -0.3, -1;
  pinched.tets.resize(2, 4);
  pinched.tets << 0, 1, 2, 3, 0, 1, 4, 5;
  for (Index t = 0; t < 2; ++t)
    if (mesh::signed_volume(pinched.rest, pinched.tets, t) < 0) std::swap(pinched.tets(t, 2), pinched.tets(t, 3));
  pinched.region = IndexVector::Zero(2);
  pinched.region_names = {"solid"};
  EXPECT_THROW(mesh::validate(pinched, "pinched"), InputError);  // a mesh file is held to more
  write_cached_mesh(file, "key", pinched);
  EXPECT_TRUE(read_cached_mesh(file, "key", problem)) << problem;
  // Three tets on one face.
  mesh::TetMesh crowded = two_tets();
  crowded.rest.conservativeResize(6, 3);
  crowded.rest.row(5) << 0.2, 0.2, 2;
  crowded.tets.conservativeResize(3, 4);
  crowded.tets.row(2) << 0, 1, 2, 5;
  crowded.region.conservativeResize(3);
  crowded.region[2] = 0;
  write_cached_mesh(file, "key", crowded);
  EXPECT_FALSE(read_cached_mesh(file, "key", problem));
  EXPECT_THAT(problem, HasSubstr("shared by more than two"));
}

TEST(MeshCacheKey, FollowsTheSectionTheElementSizeAndTheSurfaceFilesBytes) {
  MeshSourceConfig generated;
  generated.cache_key = R"({"parts":[]})";
  generated.generate.element_size = 1.0;
  const std::string base = *mesh_cache_key(generated, "");
  EXPECT_EQ(*mesh_cache_key(generated, ""), base);
  MeshSourceConfig finer = generated;
  finer.generate.element_size = 0.5;
  EXPECT_NE(*mesh_cache_key(finer, ""), base);
  MeshSourceConfig other = generated;
  other.cache_key = R"({"parts":[1]})";
  EXPECT_NE(*mesh_cache_key(other, ""), base);

  sinew::testing::TempDir dir;
  dir.write("bone.stl", "solid bone\nendsolid bone\n");
  MeshSourceConfig surfaces;
  surfaces.cache_key = R"({"parts":[]})";
  surfaces.surfaces.emplace();
  surfaces.surfaces->options.element_size = 1.0;
  surfaces.surfaces->surfaces["bone"].file = "bone.stl";  // relative to the data directory
  const std::string before = *mesh_cache_key(surfaces, dir.path().string());
  dir.write("bone.stl", "solid bone\nendsolid bone \n");
  EXPECT_NE(*mesh_cache_key(surfaces, dir.path().string()), before);
  std::filesystem::remove(dir.file("bone.stl"));
  EXPECT_FALSE(mesh_cache_key(surfaces, dir.path().string()));  // the mesher reports the missing file
}

TEST(MeshCacheBuild, MeshesOnceThenReadsTheSameMeshAndRepairsABadEntry) {
  sinew::testing::TempDir dir;
  SceneConfig scene = parse_scene(sinew::testing::box_on_plate_scene(), "");
  const fem::Problem plain = build_problem(scene);
  scene.mesh_cache_directory = dir.file("cache");
  const fem::Problem first = build_problem(scene);
  const auto stored = entries(dir / "cache");
  ASSERT_EQ(stored.size(), 2u);  // the box and the plate
  const fem::Problem second = build_problem(scene);
  for (const fem::Problem* p : {&first, &second}) {
    EXPECT_EQ(p->mesh.rest, plain.mesh.rest);
    EXPECT_EQ(p->mesh.tets, plain.mesh.tets);
    EXPECT_EQ(p->mesh.region, plain.mesh.region);
  }
  // A bad entry is meshed anew and replaced.
  dir.write(std::filesystem::relative(stored[0], dir.path()).string(), "garbage");
  const fem::Problem third = build_problem(scene);
  EXPECT_EQ(third.mesh.rest, plain.mesh.rest);
  EXPECT_GT(std::filesystem::file_size(stored[0]), 100u);
  // Another element size is another entry.
  SceneConfig finer = scene;
  finer.bodies[0].mesh.generate.element_size = 0.2;
  build_problem(finer);
  EXPECT_EQ(entries(dir / "cache").size(), 3u);
}

TEST(MeshCacheBuild, AnUnwritableCacheIsAWarningNotAFailure) {
  sinew::testing::TempDir dir;
  SceneConfig scene = parse_scene(sinew::testing::box_on_plate_scene(), "");
  scene.mesh_cache_directory = dir.write("a-file", "x") + "/cache";  // below a regular file
  const fem::Problem problem = build_problem(scene);
  EXPECT_GT(problem.mesh.num_tets(), 0);
}

}  // namespace
}  // namespace sinew::scene
