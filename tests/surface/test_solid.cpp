/// @file test_solid.cpp
/// Solids as point sets: solid_contains for every kind, solid_bounds containing the solid, and
/// check_solid's messages.

#include "sinew/surface/solid.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sinew/core/error.hpp"
#include "surface/closed_fixtures.hpp"

namespace sinew::surface {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using Kind = Solid::Kind;

/// "cube": [0,2]^3; "ball": radius 1 about (5,1,1).
SurfaceLibrary library() {
  SurfaceLibrary surfaces;
  surfaces.emplace("cube", ClosedSurface(sinew::testing::box_surface(Vector3::Zero(), Vector3::Constant(2)), "cube"));
  surfaces.emplace("ball", ClosedSurface(sinew::testing::icosphere(1.0, 3, Vector3(5, 1, 1)), "ball"));
  return surfaces;
}

Solid surface(const std::string& name) { return {.kind = Kind::Surface, .surfaces = {name}}; }
Solid offset(std::vector<std::string> names, double distance) {
  return {.kind = Kind::Offset, .surfaces = std::move(names), .distance = distance};
}
Solid box(const Vector3& min, const Vector3& max) { return {.kind = Kind::Box, .min = min, .max = max}; }
Solid capsule(const Vector3& a, const Vector3& b, double radius) { return {.kind = Kind::Capsule, .a = a, .b = b, .radius = radius}; }
Solid half_space(const Vector3& point, const Vector3& normal) { return {.kind = Kind::HalfSpace, .point = point, .normal = normal}; }
Solid boolean(Kind kind, std::vector<Solid> children) { return {.kind = kind, .children = std::move(children)}; }

/// Semi-axes (3, 1, 0.5) about (1, 2, 3), the long axis along (1, 1, 0); axis_v is given with a
/// component along axis_u, which the solid removes.
Solid rotated_ellipsoid() {
  const Vector3 u = Vector3(1, 1, 0).normalized();
  return {.kind = Kind::Ellipsoid, .a = Vector3(1, 2, 3), .semi_axes = Vector3(3, 1, 0.5), .axis_u = 2 * u,
          .axis_v = Vector3(-1, 1, 0) + 5 * u};
}

class SolidTest : public ::testing::Test {
 protected:
  bool in(const Solid& solid, const Vector3& x) const { return solid_contains(solid, library_, x); }
  /// Every point of the solid sampled in its bounds grown by 1 lies in its bounds.
  void expect_bounds_contain(const Solid& solid) const {
    const Bounds bounds = solid_bounds(solid, library_);
    ASSERT_TRUE(bounds.min.allFinite() && bounds.max.allFinite());
    const Vector3 lo = bounds.min - Vector3::Ones(), hi = bounds.max + Vector3::Ones();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0, 1);
    int inside = 0;
    for (int i = 0; i < 4000; ++i) {
      const Vector3 x = lo + (hi - lo).cwiseProduct(Vector3(unit(random), unit(random), unit(random)));
      if (!in(solid, x)) continue;
      ++inside;
      EXPECT_TRUE((x.array() >= bounds.min.array()).all() && (x.array() <= bounds.max.array()).all()) << x.transpose();
    }
    EXPECT_GT(inside, 20);
  }
  std::string rejection(const Solid& solid) const {
    try {
      check_solid(solid, library_, "part \"bone\"");
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }
  SurfaceLibrary library_ = library();
};

TEST_F(SolidTest, SurfaceIsItsInside) {
  EXPECT_TRUE(in(surface("cube"), Vector3(1, 1, 1)));
  EXPECT_TRUE(in(surface("cube"), Vector3(2, 1, 1)));  // on the boundary
  EXPECT_FALSE(in(surface("cube"), Vector3(3, 1, 1)));
  EXPECT_TRUE(in(surface("ball"), Vector3(5.5, 1, 1)));
  EXPECT_FALSE(in(surface("ball"), Vector3(1, 1, 1)));
}

TEST_F(SolidTest, PositiveOffsetGrowsTheUnion) {
  const Solid grown = offset({"cube"}, 0.5);
  EXPECT_TRUE(in(grown, Vector3(1, 1, 1)));
  EXPECT_TRUE(in(grown, Vector3(2.4, 1, 1)));
  EXPECT_FALSE(in(grown, Vector3(2.6, 1, 1)));
  EXPECT_TRUE(in(grown, Vector3(2.3, 2.3, 1)));   // 0.42 from the edge
  EXPECT_FALSE(in(grown, Vector3(2.4, 2.4, 1)));  // 0.57 from it
  const Solid hull = offset({"cube", "ball"}, 0.5);
  EXPECT_TRUE(in(hull, Vector3(3.7, 1, 1)));  // 0.3 from the ball
  EXPECT_FALSE(in(hull, Vector3(3.0, 1, 1)));  // 1 from each
  EXPECT_TRUE(in(hull, Vector3(5, 1, 1)));
}

TEST_F(SolidTest, NegativeOffsetShrinks) {
  const Solid core = offset({"cube"}, -0.5);
  EXPECT_TRUE(in(core, Vector3(1, 1, 1)));
  EXPECT_TRUE(in(core, Vector3(0.6, 1, 1)));
  EXPECT_FALSE(in(core, Vector3(0.4, 1, 1)));
  EXPECT_FALSE(in(core, Vector3(1, 1.6, 1.6)));
  EXPECT_FALSE(in(core, Vector3(3, 1, 1)));
}

TEST_F(SolidTest, BoxCapsuleAndHalfSpace) {
  const Solid b = box(Vector3(-1, 0, 0), Vector3(1, 2, 3));
  EXPECT_TRUE(in(b, Vector3(0, 1, 1.5)));
  EXPECT_TRUE(in(b, Vector3(1, 2, 3)));  // a corner
  EXPECT_FALSE(in(b, Vector3(0, 1, 3.01)));
  const Solid c = capsule(Vector3::Zero(), Vector3(2, 0, 0), 0.5);
  EXPECT_TRUE(in(c, Vector3(1, 0.4, 0)));
  EXPECT_FALSE(in(c, Vector3(1, 0.6, 0)));
  EXPECT_TRUE(in(c, Vector3(2.4, 0, 0)));        // the end cap
  EXPECT_TRUE(in(c, Vector3(-0.3, 0.3, 0)));     // 0.42 from the end
  EXPECT_FALSE(in(c, Vector3(2.3, 0.3, 0.3)));   // 0.52 from the end
  const Solid h = half_space(Vector3(0, 0, 1), Vector3(0, 0, 2));
  EXPECT_TRUE(in(h, Vector3(100, -100, -1e6)));
  EXPECT_TRUE(in(h, Vector3(5, 5, 1)));
  EXPECT_FALSE(in(h, Vector3(0, 0, 1.01)));
}

TEST_F(SolidTest, RotatedEllipsoidFollowsItsAxes) {
  const Solid e = rotated_ellipsoid();
  const Vector3 c(1, 2, 3), u = Vector3(1, 1, 0).normalized(), v = Vector3(-1, 1, 0).normalized(), w = u.cross(v);
  for (const auto& [axis, semi] : {std::pair{u, 3.0}, std::pair{v, 1.0}, std::pair{w, 0.5}}) {
    SCOPED_TRACE(::testing::Message() << "axis " << axis.transpose());
    EXPECT_TRUE(in(e, c + 0.97 * semi * axis));
    EXPECT_TRUE(in(e, c - 0.97 * semi * axis));
    EXPECT_FALSE(in(e, c + 1.03 * semi * axis));
  }
  EXPECT_FALSE(in(e, c + Vector3(2.5, 0, 0)));  // along x the ellipsoid is narrower: sqrt(1.8)
  EXPECT_TRUE(in(e, c + Vector3(1.3, 0, 0)));
}

TEST_F(SolidTest, BooleansCombineTheirChildren) {
  const Solid capsule_through_cube = capsule(Vector3(-1, 1, 1), Vector3(7, 1, 1), 0.3);
  const Solid both = boolean(Kind::Union, {surface("cube"), surface("ball")});
  EXPECT_TRUE(in(both, Vector3(1, 1, 1)));
  EXPECT_TRUE(in(both, Vector3(5, 1, 1)));
  EXPECT_FALSE(in(both, Vector3(3, 1, 1)));
  // The cube, minus the capsule and minus z <= 0.5.
  const Solid drilled =
      boolean(Kind::Difference, {surface("cube"), capsule_through_cube, half_space(Vector3(0, 0, 0.5), Vector3::UnitZ())});
  EXPECT_FALSE(in(drilled, Vector3(1, 1, 1)));      // in the capsule
  EXPECT_TRUE(in(drilled, Vector3(1, 1.5, 1)));
  EXPECT_FALSE(in(drilled, Vector3(1, 1.5, 0.2)));  // in the half-space
  EXPECT_FALSE(in(drilled, Vector3(5, 1, 1)));      // in the capsule, not the cube
  const Solid lower_half = boolean(Kind::Intersection, {surface("cube"), half_space(Vector3(0, 0, 1), Vector3::UnitZ())});
  EXPECT_TRUE(in(lower_half, Vector3(1, 1, 0.5)));
  EXPECT_FALSE(in(lower_half, Vector3(1, 1, 1.5)));
  EXPECT_FALSE(in(lower_half, Vector3(1, 1, -0.5)));
}

TEST_F(SolidTest, BoundsContainEverySolid) {
  const Solid c = capsule(Vector3(-1, 0, 1), Vector3(2, 3, 1), 0.7);
  for (const Solid& solid : {surface("cube"), surface("ball"), offset({"cube", "ball"}, 0.5), offset({"cube"}, -0.5),
                             box(Vector3(-1, 0, 0), Vector3(1, 2, 3)), c, rotated_ellipsoid(),
                             boolean(Kind::Union, {c, surface("ball")}), boolean(Kind::Difference, {surface("cube"), c}),
                             boolean(Kind::Intersection, {surface("cube"), c})}) {
    SCOPED_TRACE(std::string(name_of(solid.kind)));
    expect_bounds_contain(solid);
  }
  // Tight where they can be.
  const Bounds b = solid_bounds(c, library_);
  EXPECT_TRUE(b.min.isApprox(Vector3(-1.7, -0.7, 0.3)));
  EXPECT_TRUE(b.max.isApprox(Vector3(2.7, 3.7, 1.7)));
  const Bounds e = solid_bounds(rotated_ellipsoid(), library_);
  const double half_xy = std::sqrt((9.0 + 1.0) / 2.0);  // sqrt(3^2/2 + 1^2/2)
  EXPECT_TRUE((e.max - Vector3(1, 2, 3)).isApprox(Vector3(half_xy, half_xy, 0.5))) << e.max.transpose();
  const Bounds grown = solid_bounds(offset({"cube"}, 0.5), library_);
  EXPECT_TRUE(grown.min.isApprox(Vector3::Constant(-0.5)));
  EXPECT_TRUE(grown.max.isApprox(Vector3::Constant(2.5)));
}

TEST_F(SolidTest, HalfSpaceIsUnboundedUntilIntersected) {
  const Solid h = half_space(Vector3(0, 0, 1), Vector3::UnitZ());
  EXPECT_FALSE(solid_bounds(h, library_).max.allFinite());
  EXPECT_FALSE(solid_bounds(boolean(Kind::Union, {surface("cube"), h}), library_).max.allFinite());
  const Solid cut = boolean(Kind::Intersection, {h, surface("ball")});
  const Bounds bounds = solid_bounds(cut, library_);
  EXPECT_TRUE(bounds.min.allFinite() && bounds.max.allFinite());
  EXPECT_FALSE(bounds.empty());
  expect_bounds_contain(cut);
  // A difference is bounded by its first child.
  EXPECT_TRUE(solid_bounds(boolean(Kind::Difference, {surface("cube"), h}), library_).max.allFinite());
}

TEST_F(SolidTest, UnionSignedDistanceIsTheNearest) {
  EXPECT_NEAR(union_signed_distance({"cube", "ball"}, library_, Vector3(3.5, 1, 1)), 0.5, 1e-2);
  EXPECT_NEAR(union_signed_distance({"cube", "ball"}, library_, Vector3(1, 1, 1)), -1.0, 1e-12);
  EXPECT_NEAR(union_signed_distance({"cube"}, library_, Vector3(3.5, 1, 1)), 1.5, 1e-12);
}

TEST_F(SolidTest, CheckAcceptsValidSolids) {
  for (const Solid& solid : {surface("cube"), offset({"cube", "ball"}, -0.2), capsule(Vector3::Zero(), Vector3::Zero(), 1),
                             rotated_ellipsoid(), boolean(Kind::Difference, {surface("cube"), surface("ball")})}) {
    EXPECT_EQ(rejection(solid), "") << name_of(solid.kind);
  }
}

TEST_F(SolidTest, CheckNamesWhatIsWrong) {
  EXPECT_THAT(rejection(surface("femur")), AllOf(HasSubstr("part \"bone\""), HasSubstr("unknown surface \"femur\"")));
  EXPECT_THAT(rejection(offset({"cube", "tibia"}, 1)), HasSubstr("offset names an unknown surface \"tibia\""));
  EXPECT_THAT(rejection(offset({}, 1)), HasSubstr("at least one surface"));
  EXPECT_THAT(rejection(offset({"cube"}, std::numeric_limits<double>::quiet_NaN())), HasSubstr("finite"));
  EXPECT_THAT(rejection({.kind = Kind::Surface, .surfaces = {"cube", "ball"}}), HasSubstr("exactly one surface"));
  EXPECT_THAT(rejection(capsule(Vector3::Zero(), Vector3::UnitX(), 0)), HasSubstr("radius must be > 0"));
  EXPECT_THAT(rejection(half_space(Vector3::Zero(), Vector3::Zero())), HasSubstr("normal must be non-zero"));
  EXPECT_THAT(rejection(box(Vector3::Zero(), Vector3(1, 0, 1))), HasSubstr("max must exceed its min"));
  Solid parallel = rotated_ellipsoid();
  parallel.axis_v = -3 * parallel.axis_u;
  EXPECT_THAT(rejection(parallel), HasSubstr("not parallel"));
  Solid flat = rotated_ellipsoid();
  flat.semi_axes.z() = 0;
  EXPECT_THAT(rejection(flat), HasSubstr("semi-axes must be > 0"));
  EXPECT_THAT(rejection(boolean(Kind::Union, {})), HasSubstr("union needs at least one solid"));
  EXPECT_THAT(rejection(boolean(Kind::Intersection, {})), HasSubstr("intersection needs at least one solid"));
  // A nested error says where it is.
  EXPECT_THAT(rejection(boolean(Kind::Difference, {surface("cube"), boolean(Kind::Union, {surface("knee")})})),
              AllOf(HasSubstr("part \"bone\"/difference[1]/union[0]"), HasSubstr("unknown surface \"knee\"")));
}

}  // namespace
}  // namespace sinew::surface
