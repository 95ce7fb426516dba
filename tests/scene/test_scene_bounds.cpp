/// @file test_scene_bounds.cpp
/// Every number of a scene is bounded so that nothing downstream wraps or overflows: integers
/// within the type they are read into, physical parameters within ranges that keep every
/// product finite; and names hold no control characters.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/schema.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using testing::minimal_scene;
using testing::parse_error;
using ::testing::HasSubstr;

TEST(SceneBounds, FormatNumberNeverWritesHugeNumbersOut) {
  EXPECT_EQ(format_number(1e300), "1e+300");
  EXPECT_EQ(format_number(-1e300), "-1e+300");
  EXPECT_EQ(format_number(2147483648.0), "2147483648");
  EXPECT_EQ(format_number(1e6), "1e+06");
  EXPECT_EQ(format_number(25), "25");
}

// increments 2147483648 wrapped to a negative int and ran "increment 1/1"; max_iterations
// 2^32 wrapped to 0 ("no convergence in 0 Newton iterations").
TEST(SceneBounds, IntegersThatWouldWrapAreRefused) {
  json scene = minimal_scene();
  scene["solver"]["increments"] = 2147483648LL;
  EXPECT_EQ(parse_error(scene), "solver.increments: must be <= 1e+06, got 2147483648");
  scene["solver"]["increments"] = 10;
  scene["solver"]["newton"]["max_iterations"] = 4294967296LL;
  EXPECT_EQ(parse_error(scene), "solver.newton.max_iterations: must be <= 1e+05, got 4294967296");
  scene["solver"]["newton"]["max_iterations"] = 25;
  scene["output"]["every"] = 1e300;  // an integral double
  EXPECT_EQ(parse_error(scene), "output.every: must be <= 1e+06, got 1e+300");
}

TEST(SceneBounds, AnIntegerWithoutBoundsIsBoundedByInt) {
  Schema schema;
  SchemaNode count;
  count.type = SchemaType::Integer;
  count.key = "count";
  schema.root.properties = {count};
  EXPECT_TRUE(validate_and_complete(schema, json{{"count", 2147483647}}).errors.empty());
  EXPECT_TRUE(validate_and_complete(schema, json{{"count", -2147483648LL}}).errors.empty());
  EXPECT_EQ(validate_and_complete(schema, json{{"count", 2147483648LL}}).errors,
            std::vector<std::string>{"count: must be <= 2147483647, got 2147483648"});
  EXPECT_EQ(validate_and_complete(schema, json{{"count", -2147483649LL}}).errors,
            std::vector<std::string>{"count: must be >= -2147483648, got -2147483649"});
  // A node may allow a wider range of its own.
  schema.root.properties[0].maximum = SchemaBound{1e12, false};
  EXPECT_TRUE(validate_and_complete(schema, json{{"count", 4294967296LL}}).errors.empty());
}

/// The minimal scene with a rigid region and contact, to reach every key the issue names.
json scene_with_contact() {
  json scene = minimal_scene();
  scene["contact"] = json::object();
  return scene;
}

// Each of these ran and produced inf residuals (or "an element is inverted") before.
TEST(SceneBounds, ValuesThatOverflowAreRefusedWithTheirPath) {
  {
    json scene = scene_with_contact();
    scene["contact"]["penalty"] = 1e300;
    EXPECT_EQ(parse_error(scene), "contact.penalty: must be <= 1e+15, got 1e+300");
    scene["contact"]["penalty"] = 1e30;
    EXPECT_EQ(parse_error(scene), "contact.penalty: must be <= 1e+15, got 1e+30");
  }
  {
    json scene = minimal_scene();
    scene["bodies"][0]["regions"]["*"]["contact_penalty_scale"] = 1e300;
    EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"].contact_penalty_scale: must be <= 1e+06, got 1e+300");
  }
  {
    json scene = minimal_scene();
    scene["materials"]["gel"] = {{"law", "mooney-rivlin"}, {"C1", 1e300}, {"a", 1e300}};
    const std::string message = parse_error(scene);
    EXPECT_THAT(message, HasSubstr("materials.gel.C1: must be <= 1e+12, got 1e+300"));
    EXPECT_THAT(message, HasSubstr("materials.gel.a: must be <= 1e+12, got 1e+300"));
  }
  {
    json scene = minimal_scene();
    scene["bodies"][0]["regions"]["*"]["density"] = 1e300;
    scene["loads"]["gravity"] = {0, 0, -1e300};
    const std::string message = parse_error(scene);
    EXPECT_THAT(message, HasSubstr("bodies[0].regions[\"*\"].density: must be <= 1e+12, got 1e+300"));
    EXPECT_THAT(message, HasSubstr("loads.gravity[2]: must be >= -1e+12, got -1e+300"));
  }
  {
    json scene = minimal_scene();
    scene["bodies"][0]["mesh"]["generate"]["parts"][0]["shape"]["box"]["max"] = {1e20, 1, 1};
    EXPECT_EQ(parse_error(scene),
              "bodies[0].mesh.generate.parts[0].shape.box.max[0]: must be <= 1e+06, got 1e+20");
  }
  {
    json scene = minimal_scene();
    scene["solver"]["min_step"] = 1e-300;  // halving down to it never ended
    EXPECT_EQ(parse_error(scene), "solver.min_step: must be >= 1e-12, got 1e-300");
  }
  {
    json scene = minimal_scene();
    scene["solver"]["newton"]["residual_tolerance"] = 1e-300;
    EXPECT_EQ(parse_error(scene), "solver.newton.residual_tolerance: must be >= 1e-16, got 1e-300");
  }
}

TEST(SceneBounds, TooManyDynamicOutputsAreRefused) {
  json scene = minimal_scene();
  scene["dynamics"] = {{"end_time", 1e6}, {"output_interval", 1e-6}};
  EXPECT_EQ(parse_error(scene), "dynamics.output_interval: gives 1e+12 outputs over end_time; at most 1e+06 are allowed");
}

// A NUL in a name cut the message that named it.
TEST(SceneBounds, NamesWithControlCharactersAreRefused) {
  json scene = minimal_scene();
  scene["bodies"][0]["name"] = std::string("a\0b", 3);
  EXPECT_EQ(parse_error(scene),
            "bodies[0].name: names may not contain control characters (codes below 0x20), got \"a\\u0000b\"");
  scene["bodies"][0]["name"] = "cube";
  scene["materials"][std::string("g\nel")] = scene["materials"]["gel"];
  EXPECT_THAT(parse_error(scene), HasSubstr("materials[\"g\\nel\"]: names may not contain control characters"));
  scene["materials"].erase(std::string("g\nel"));
  scene["description"] = "two lines\nof free text";
  EXPECT_NO_THROW(parse_scene(scene, ""));
}

}  // namespace
}  // namespace sinew::scene
