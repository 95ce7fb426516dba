/// @file test_element_size.cpp
/// set_element_size: one size for every generated mesh; surface meshes keep their grading.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "sinew/core/error.hpp"
#include "sinew/scene/element_size.hpp"

namespace sinew::scene {
namespace {

SceneConfig three_bodies() {
  SceneConfig config;
  BodyConfig generated;
  generated.mesh.generate.element_size = 4;
  BodyConfig from_file;
  from_file.mesh.file = "block.msh";
  from_file.mesh.generate.element_size = 4;
  BodyConfig from_surfaces;
  SurfaceMeshConfig surfaces;
  surfaces.options.element_size = 10;
  surfaces.options.facet_distance = 0.5;
  surfaces.options.size_zones.push_back(surface::SizeZone{});
  surfaces.options.size_zones.back().size = 4;
  from_surfaces.mesh.surfaces = surfaces;
  config.bodies = {generated, from_file, from_surfaces};
  return config;
}

TEST(ElementSize, GeneratedMeshesTakeTheSizeAndSurfaceMeshesKeepTheirGrading) {
  SceneConfig config = three_bodies();
  set_element_size(config, 20);
  EXPECT_EQ(config.bodies[0].mesh.generate.element_size, 20);
  EXPECT_EQ(config.bodies[1].mesh.generate.element_size, 4) << "a mesh read from a file is not remeshed";
  const surface::TetrahedralizeOptions& options = config.bodies[2].mesh.surfaces->options;
  EXPECT_DOUBLE_EQ(options.element_size, 20);
  EXPECT_DOUBLE_EQ(options.facet_distance, 1.0);
  EXPECT_DOUBLE_EQ(options.size_zones.at(0).size, 8);
}

TEST(ElementSize, RefusesSizesThatAreNotFinitePositiveLengths) {
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    SceneConfig config = three_bodies();
    EXPECT_THROW(
        {
          try {
            set_element_size(config, bad);
          } catch (const InputError& error) {
            EXPECT_THAT(error.what(), ::testing::HasSubstr("the element size must be a finite length > 0"));
            throw;
          }
        },
        InputError);
    EXPECT_EQ(config.bodies[0].mesh.generate.element_size, 4) << "nothing changed";
  }
}

}  // namespace
}  // namespace sinew::scene
