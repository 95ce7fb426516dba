/// @file test_fiber_path.cpp
/// Per-element fiber fields (a region's "fiber_path"): each tet takes the direction of the path
/// segment nearest its centroid; the errors a path can make.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/build_problem.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using testing::data_directory;
using testing::parse_error;
using ::testing::HasSubstr;

/// A 2 x 1 x 0.5 slab of fiber-reinforced rubber with an L-shaped fiber path: along x over
/// x < 1, then along y.
json slab_with_path() {
  return json::parse(R"({
    "units": "m, N, Pa, s",
    "materials": {"rubber": {"law": "mooney-rivlin", "C1": 1, "a": 5,
                             "fiber": {"alpha": 10, "beta": 2, "direction": [0, 0, 1]}}},
    "bodies": [{"name": "slab",
      "mesh": {"generate": {"element_size": 0.25, "parts": [
        {"region": "slab", "shape": {"box": {"min": [0, 0, 0], "max": [2, 1, 0.5]}}}]}},
      "regions": {"slab": {"material": "rubber", "fiber_path": [[-10, 0.5, 0.25], [1, 0.5, 0.25], [1, 10.5, 0.25]]}}}]
  })");
}

/// Energy density of a 10 % stretch along `d`: largest along the fibers.
double stretch_energy(const material::Material& law, const Vector3& d) {
  // Built in place: GCC 12 at -O1 takes Identity() + ... for a read of uninitialized memory.
  Matrix3 F = 0.1 * d * d.transpose();
  F.diagonal().array() += 1.0;
  return law.energy_density(F);
}

TEST(FiberPath, EachTetTakesTheDirectionOfTheNearestSegment) {
  const fem::Problem problem = build_problem(parse_scene(slab_with_path(), data_directory()));
  ASSERT_EQ(static_cast<Index>(problem.element_material.size()), problem.mesh.num_tets());
  int along_x = 0, along_y = 0;
  for (const auto& [t, law] : problem.element_material) {
    Vector3 centroid = Vector3::Zero();
    for (int k = 0; k < 4; ++k) centroid += problem.mesh.rest.row(problem.mesh.tets(t, k)).transpose() / 4.0;
    const double ex = stretch_energy(*law, Vector3::UnitX()), ey = stretch_energy(*law, Vector3::UnitY());
    // Tets clearly nearer the first segment (the line y = 0.5, x < 1) or the second (x = 1, y > 0.5).
    const double to_first = std::hypot(std::max(centroid.x() - 1, 0.0), centroid.y() - 0.5);
    const double to_second = std::hypot(centroid.x() - 1, std::max(0.5 - centroid.y(), 0.0));
    if (to_first < to_second - 0.05) {
      EXPECT_GT(ex, 2 * ey) << "tet " << t << " at " << centroid.transpose();
      ++along_x;
    } else if (to_second < to_first - 0.05) {
      EXPECT_GT(ey, 2 * ex) << "tet " << t << " at " << centroid.transpose();
      ++along_y;
    }
  }
  EXPECT_GT(along_x, 10);
  EXPECT_GT(along_y, 10);
  // Segments share one law each: two laws for the whole region.
  std::set<const material::Material*> laws;
  for (const auto& [t, law] : problem.element_material) laws.insert(law.get());
  EXPECT_EQ(laws.size(), 2u);
}

TEST(FiberPath, ErrorsNameTheRegion) {
  json both = slab_with_path();
  both["bodies"][0]["regions"]["slab"]["fiber_direction"] = {1, 0, 0};
  EXPECT_THAT(parse_error(both), HasSubstr("bodies[0].regions.slab.fiber_path: give fiber_direction or fiber_path, not both"));

  json repeated = slab_with_path();
  repeated["bodies"][0]["regions"]["slab"]["fiber_path"] = {{0, 0, 0}, {0, 0, 0}};
  EXPECT_THAT(parse_error(repeated), HasSubstr("bodies[0].regions.slab.fiber_path[1]: repeats the point before it"));

  json no_fiber = slab_with_path();
  no_fiber["materials"]["rubber"].erase("fiber");
  EXPECT_THAT(parse_error(no_fiber), HasSubstr("bodies[0].regions.slab.fiber_path: material \"rubber\" has no \"fiber\" to orient"));

  json rigid = slab_with_path();
  rigid["bodies"][0]["regions"]["slab"] = {{"rigid", "fixed"}, {"fiber_path", {{0, 0, 0}, {1, 0, 0}}}};
  EXPECT_THAT(parse_error(rigid), HasSubstr("bodies[0].regions.slab.fiber_path: a rigid region has no fibers"));

  json one_point = slab_with_path();
  one_point["bodies"][0]["regions"]["slab"]["fiber_path"] = {{0, 0, 0}};
  EXPECT_THAT(parse_error(one_point), HasSubstr("fiber_path"));
}

}  // namespace
}  // namespace sinew::scene
