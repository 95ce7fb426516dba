/// @file test_read_surface_fuzz.cpp
/// Mutated surface files (bytes flipped, inserted, cut) of every format: read_surface returns a
/// mesh or throws InputError, never anything else (docs/surface-input.md: errors).

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <random>

#include "sinew/core/error.hpp"
#include "sinew/surface/read_surface.hpp"
#include "support/temp_dir.hpp"
#include "surface/surface_fixtures.hpp"

namespace sinew::surface {
namespace {

namespace fx = sinew::testing;

std::string mutate(std::string bytes, std::mt19937& rng) {
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits && !bytes.empty(); ++e) {
    const std::size_t at = rng() % bytes.size();
    switch (rng() % 4) {
      case 0: bytes[at] = static_cast<char>(rng() % 256); break;
      case 1: bytes.insert(at, 1, "0123456789-.e nan\n{}[]\""[rng() % 24]); break;
      case 2: bytes.erase(at, 1 + rng() % 8); break;
      default: bytes.resize(at); break;
    }
  }
  return bytes;
}

TEST(ReadSurfaceFuzz, MutatedFilesGiveAMeshOrAnInputError) {
  const fx::Shape cube = fx::unit_cube();
  const std::vector<std::pair<std::string, std::string>> seeds = {
      {".stl", fx::ascii_stl(cube)}, {".stl", fx::binary_stl(cube)}, {".obj", fx::obj(cube)},
      {".ply", fx::ascii_ply(cube)}, {".gltf", fx::gltf_embedded({{"cube", cube}, {"tet", fx::unit_tet()}})},
      {".glb", fx::glb({{"cube", cube}, {"tet", fx::unit_tet()}})}};
  fx::TempDir dir;
  const char* seed_text = std::getenv("SINEW_FUZZ_SEED");
  const char* cases_text = std::getenv("SINEW_FUZZ_CASES");
  std::mt19937 rng(seed_text != nullptr ? static_cast<unsigned>(std::strtoul(seed_text, nullptr, 10)) : 18u);
  const int cases = cases_text != nullptr ? std::atoi(cases_text) : 60;
  int errors = 0, meshes = 0;
  const bool verbose = std::getenv("SINEW_FUZZ_VERBOSE") != nullptr;
  for (const auto& [extension, seed] : seeds) {
    for (int c = 0; c < cases; ++c) {
      const std::string path = dir.write("case" + extension, mutate(seed, rng));
      if (verbose) std::cerr << "case " << extension << " " << c << std::endl;
      try {
        const SurfaceMesh mesh = read_surface(path, {.mesh_name = extension == ".gltf" || extension == ".glb" ? "cube" : ""});
        EXPECT_GT(mesh.triangles.rows(), 0);
        EXPECT_TRUE(mesh.vertices.allFinite());
        EXPECT_TRUE((mesh.triangles.array() >= 0).all() && (mesh.triangles.array() < mesh.vertices.rows()).all());
        ++meshes;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        ++errors;
      }
    }
  }
  std::cout << meshes << " meshes read, " << errors << " input errors\n";
  EXPECT_GT(errors, 0);
}

}  // namespace
}  // namespace sinew::surface
