#include "sinew/mesh/generate.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/core/error.hpp"

namespace sinew::mesh {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi;

Shape box(const Vector3& min, const Vector3& max) {
  Shape shape;
  shape.kind = Shape::Kind::Box;
  shape.min = min;
  shape.max = max;
  return shape;
}

Shape unit_box() { return box(Vector3::Zero(), Vector3::Ones()); }

Shape sphere(const Vector3& center, double radius) {
  Shape shape;
  shape.kind = Shape::Kind::Sphere;
  shape.center = center;
  shape.radius = radius;
  return shape;
}

Shape cylinder(const Vector3& base_center, const Vector3& axis, double radius) {
  Shape shape;
  shape.kind = Shape::Kind::Cylinder;
  shape.center = base_center;
  shape.axis = axis;
  shape.radius = radius;
  return shape;
}

Shape torus(const Vector3& center, const Vector3& axis, double radius, double minor_radius,
            double angle_deg = 360) {
  Shape shape;
  shape.kind = Shape::Kind::Torus;
  shape.center = center;
  shape.axis = axis;
  shape.radius = radius;
  shape.minor_radius = minor_radius;
  shape.angle_deg = angle_deg;
  return shape;
}

/// `shape` rotated by `angle_deg` about the axis through `center`, then translated.
Shape transformed(Shape shape, const Vector3& axis, double angle_deg,
                  const Vector3& center = Vector3::Zero(),
                  const Vector3& translation = Vector3::Zero()) {
  shape.rotation_axis = axis;
  shape.rotation_angle_deg = angle_deg;
  shape.rotation_center = center;
  shape.translation = translation;
  return shape;
}

Shape combine(Shape::Kind kind, std::vector<Shape> children) {
  Shape shape;
  shape.kind = kind;
  shape.children = std::move(children);
  return shape;
}

TetMesh mesh_one(const Shape& shape, double element_size) {
  GenerateOptions options;
  options.element_size = element_size;
  return generate_mesh({Part{"body", shape}}, options);
}

std::vector<Index> nodes_of(const Triangles& triangles) {
  std::vector<Index> nodes(triangles.data(), triangles.data() + triangles.size());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

double volume_of(const TetMesh& mesh) { return testing::total_volume(mesh.rest, mesh.tets); }

double region_volume(const TetMesh& mesh, Index region) {
  double volume = 0;
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    if (mesh.region(t) == region) volume += signed_volume(mesh.rest, mesh.tets, t);
  }
  return volume;
}

struct Bounds {
  Vector3 min, max;
};

Bounds bounds_of(const TetMesh& mesh) {
  return {mesh.rest.colwise().minCoeff().transpose(), mesh.rest.colwise().maxCoeff().transpose()};
}

void expect_bounds(const TetMesh& mesh, const Vector3& min, const Vector3& max, double tolerance) {
  const Bounds bounds = bounds_of(mesh);
  EXPECT_TRUE((bounds.min - min).cwiseAbs().maxCoeff() <= tolerance)
      << "min " << bounds.min.transpose() << ", expected " << min.transpose();
  EXPECT_TRUE((bounds.max - max).cwiseAbs().maxCoeff() <= tolerance)
      << "max " << bounds.max.transpose() << ", expected " << max.transpose();
}

/// Distance from `point` to the nearest mesh node.
double distance_to_nearest_node(const TetMesh& mesh, const Vector3& point) {
  return (mesh.rest.rowwise() - point.transpose()).rowwise().norm().minCoeff();
}

std::string generate_error(const std::vector<Part>& parts, double element_size = 0.25) {
  GenerateOptions options;
  options.element_size = element_size;
  try {
    generate_mesh(parts, options);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

/// Closed, outward, consistent boundary enclosing the mesh volume; face set of the part.
void expect_closed_outward_boundary(const TetMesh& mesh) {
  const Triangles boundary = boundary_triangles(mesh.tets);
  EXPECT_TRUE(testing::is_closed_oriented_surface(boundary));
  EXPECT_NEAR(testing::enclosed_volume(mesh.rest, boundary), volume_of(mesh),
              1e-9 * volume_of(mesh));
  EXPECT_GT(volume_of(mesh), 0);
}

TEST(GenerateMesh, BoxVolumeIsExactAndItsSurfaceAClosedSphere) {
  const TetMesh mesh = mesh_one(box(Vector3(-1, 0, 0.5), Vector3(1, 1, 1)), 0.2);
  EXPECT_NEAR(volume_of(mesh), 2.0 * 1.0 * 0.5, 1e-12);
  EXPECT_EQ(mesh.region_names, std::vector<std::string>{"body"});
  expect_closed_outward_boundary(mesh);
  const Triangles boundary = boundary_triangles(mesh.tets);
  EXPECT_EQ(testing::euler_characteristic(boundary), 2);
  EXPECT_EQ(referenced_nodes(mesh.tets).size(), static_cast<std::size_t>(mesh.num_nodes()));
  // The part's surface face set and node set.
  ASSERT_TRUE(mesh.face_sets.count("body.surface"));
  EXPECT_EQ(mesh.face_sets.at("body.surface").rows(), boundary.rows());
  EXPECT_NEAR(testing::total_area(mesh.rest, mesh.face_sets.at("body.surface")),
              2 * (2.0 + 1.0 + 0.5), 1e-12);
  EXPECT_EQ(mesh.node_sets.at("body.surface"), nodes_of(boundary));
}

TEST(GenerateMesh, CylinderAndSphereVolumesNearAnalytic) {
  const double radius = 0.5;
  const Vector3 axis = Vector3(1, 1, 0.5).normalized() * 1.5;  // not along a coordinate axis
  const TetMesh tilted_cylinder = mesh_one(cylinder(Vector3(0.2, 0, 0), axis, radius), 0.12);
  EXPECT_NEAR(volume_of(tilted_cylinder) / (kPi * radius * radius * 1.5), 1.0, 0.03);
  expect_closed_outward_boundary(tilted_cylinder);

  const TetMesh ball = mesh_one(sphere(Vector3(1, 2, 3), radius), 0.12);
  EXPECT_NEAR(volume_of(ball) / (4.0 / 3.0 * kPi * std::pow(radius, 3)), 1.0, 0.03);
  expect_closed_outward_boundary(ball);
  EXPECT_EQ(testing::euler_characteristic(boundary_triangles(ball.tets)), 2);
}

TEST(GenerateMesh, FewerElementsPerTurnMeshAThinRodWithFarFewerTets) {
  // A rod of radius 0.05 with element_size 0.05: 12 elements per turn refine the surface to about
  // 0.026, 6 per turn to about 0.05 (element_size decides), 0 switches curvature refinement off.
  const Shape rod = cylinder(Vector3(0, 0, 0), Vector3(1, 0, 0), 0.05);
  GenerateOptions options;
  options.element_size = 0.05;
  const TetMesh fine = generate_mesh({Part{"rod", rod}}, options);
  options.elements_per_turn = 6;
  const TetMesh coarse = generate_mesh({Part{"rod", rod}}, options);
  options.elements_per_turn = 0;
  const TetMesh plain = generate_mesh({Part{"rod", rod}}, options);
  EXPECT_LT(3 * coarse.num_tets(), fine.num_tets());
  EXPECT_LE(plain.num_tets(), coarse.num_tets() * 3 / 2);
  const double exact = kPi * 0.05 * 0.05;
  EXPECT_NEAR(volume_of(coarse) / exact, 1.0, 0.2);  // a hexagon-like cross-section: about 17 % less
  options.elements_per_turn = -1;
  EXPECT_THROW(generate_mesh({Part{"rod", rod}}, options), InputError);
}

TEST(GenerateMesh, ThinHoleIsResolvedByCurvatureRefinement) {
  // A hole of radius 0.05 through a unit box meshed at size 0.25.
  const double radius = 0.05;
  const TetMesh mesh =
      mesh_one(combine(Shape::Kind::Difference,
                       {unit_box(), cylinder(Vector3(0.5, 0.5, -0.5), Vector3(0, 0, 2), radius)}),
               0.25);
  const double hole = kPi * radius * radius;
  EXPECT_NEAR((1.0 - volume_of(mesh)) / hole, 1.0, 0.1);
  expect_closed_outward_boundary(mesh);
  EXPECT_EQ(testing::euler_characteristic(boundary_triangles(mesh.tets)), 0);  // a torus
}

struct BooleanCase {
  std::string name;
  Shape shape;
  double exact_volume;
};

void PrintTo(const BooleanCase& boolean_case, std::ostream* out) { *out << boolean_case.name; }

class GenerateBoolean : public ::testing::TestWithParam<BooleanCase> {};

TEST_P(GenerateBoolean, MeshesWithTheAnalyticVolume) {
  const TetMesh mesh = mesh_one(GetParam().shape, 0.1);
  EXPECT_NEAR(volume_of(mesh) / GetParam().exact_volume, 1.0, 0.03);
  expect_closed_outward_boundary(mesh);
}

double ball_volume(double radius) { return 4.0 / 3.0 * kPi * std::pow(radius, 3); }

INSTANTIATE_TEST_SUITE_P(
    Shapes, GenerateBoolean,
    ::testing::Values(
        // The case that defeats a plain fuse in Gmsh 4.8: sphere centred on a box corner.
        BooleanCase{"box_union_sphere_on_corner",
                    combine(Shape::Kind::Union, {unit_box(), sphere(Vector3::Zero(), 0.5)}),
                    1 + 7.0 / 8.0 * ball_volume(0.5)},
        BooleanCase{"box_union_sphere_on_far_corner",
                    combine(Shape::Kind::Union, {unit_box(), sphere(Vector3(1, 0, 1), 0.5)}),
                    1 + 7.0 / 8.0 * ball_volume(0.5)},
        // A sphere bulging out of all six faces: a plain fuse leaves a broken face.
        BooleanCase{"box_union_centred_sphere_through_faces",
                    combine(Shape::Kind::Union, {unit_box(), sphere(Vector3::Constant(0.5), 0.6)}),
                    // box + 6 caps of height 0.1
                    1 + 6 * kPi * 0.1 * 0.1 * (3 * 0.6 - 0.1) / 3},
        BooleanCase{"box_minus_sphere_on_corner",
                    combine(Shape::Kind::Difference, {unit_box(), sphere(Vector3::Zero(), 0.5)}),
                    1 - 1.0 / 8.0 * ball_volume(0.5)},
        BooleanCase{"box_minus_cylinder_through",
                    combine(Shape::Kind::Difference,
                            {unit_box(), cylinder(Vector3(0.5, 0.5, 0), Vector3(0, 0, 1), 0.3)}),
                    1 - kPi * 0.09},
        BooleanCase{"box_union_cylinder_along_edge",
                    combine(Shape::Kind::Union,
                            {unit_box(), cylinder(Vector3::Zero(), Vector3(0, 0, 1), 0.3)}),
                    1 + 0.75 * kPi * 0.09},
        BooleanCase{"capsule_with_tangent_caps",
                    combine(Shape::Kind::Union,
                            {cylinder(Vector3::Zero(), Vector3(1, 0, 0), 0.3),
                             sphere(Vector3::Zero(), 0.3), sphere(Vector3(1, 0, 0), 0.3)}),
                    kPi * 0.09 + ball_volume(0.3)},
        BooleanCase{"box_minus_two_tools_and_a_disjoint_one",
                    combine(Shape::Kind::Difference,
                            {unit_box(), box(Vector3(0.5, 0.5, 0.5), Vector3(2, 2, 2)),
                             cylinder(Vector3(0, 0.2, 0.2), Vector3(1, 0, 0), 0.1),
                             sphere(Vector3(5, 5, 5), 0.5)}),
                    1 - 0.125 - kPi * 0.01},
        BooleanCase{"nested_difference_of_unions",
                    combine(Shape::Kind::Difference,
                            {combine(Shape::Kind::Union,
                                     {unit_box(), box(Vector3(1, 0, 0), Vector3(2, 1, 1))}),
                             combine(Shape::Kind::Union, {sphere(Vector3(0.5, 0.5, 1), 0.3),
                                                          sphere(Vector3(1.5, 0.5, 1), 0.3)})}),
                    2 - ball_volume(0.3)}),
    [](const auto& info) { return info.param.name; });

TEST(GenerateMesh, TwoBoxesSideBySideShareTheirInterface) {
  GenerateOptions options;
  options.element_size = 0.2;
  const TetMesh mesh = generate_mesh(
      {Part{"left", unit_box()}, Part{"right", box(Vector3(1, 0, 0), Vector3(2, 1, 1))}}, options);
  EXPECT_EQ(mesh.region_names, (std::vector<std::string>{"left", "right"}));
  EXPECT_NEAR(region_volume(mesh, 0), 1.0, 1e-12);
  EXPECT_NEAR(region_volume(mesh, 1), 1.0, 1e-12);
  // Conforming: the union's boundary is the outer surface only.
  const Triangles boundary = boundary_triangles(mesh.tets);
  EXPECT_NEAR(testing::total_area(mesh.rest, boundary), 10.0, 1e-12);
  EXPECT_EQ(testing::euler_characteristic(boundary), 2);
  expect_closed_outward_boundary(mesh);

  const Triangles interface = interface_triangles(mesh, 0, 1);
  ASSERT_GT(interface.rows(), 0);
  EXPECT_NEAR(testing::total_area(mesh.rest, interface), 1.0, 1e-12);
  for (Index f = 0; f < interface.rows(); ++f) {
    EXPECT_NEAR(testing::triangle_area_vector(mesh.rest, interface, f).normalized().x(), 1.0,
                1e-12);
  }
  // Each part's surface includes the interface: 6 unit faces each.
  EXPECT_NEAR(testing::total_area(mesh.rest, mesh.face_sets.at("left.surface")), 6.0, 1e-12);
  EXPECT_NEAR(testing::total_area(mesh.rest, mesh.face_sets.at("right.surface")), 6.0, 1e-12);
}

TEST(GenerateMesh, CylinderInsideBoxIsConformingAndTheFirstPartTakesTheOverlap) {
  GenerateOptions options;
  options.element_size = 0.12;
  const double radius = 0.25;
  const Shape core = cylinder(Vector3(0.5, 0.5, 0.25), Vector3(0, 0, 0.5), radius);
  const TetMesh mesh = generate_mesh({Part{"core", core}, Part{"shell", unit_box()}}, options);
  const double core_volume = kPi * radius * radius * 0.5;
  EXPECT_NEAR(region_volume(mesh, 0) / core_volume, 1.0, 0.03);
  EXPECT_NEAR(region_volume(mesh, 0) + region_volume(mesh, 1), 1.0, 1e-12);

  // Conforming: the mesh boundary is just the box surface, and core nodes on the interface are
  // shared with shell tets.
  const Triangles boundary = boundary_triangles(mesh.tets);
  EXPECT_NEAR(testing::total_area(mesh.rest, boundary), 6.0, 1e-12);
  EXPECT_EQ(testing::euler_characteristic(boundary), 2);
  const Triangles interface = interface_triangles(mesh, 0, 1);
  const double core_area = 2 * kPi * radius * 0.5 + 2 * kPi * radius * radius;
  EXPECT_NEAR(testing::total_area(mesh.rest, interface) / core_area, 1.0, 0.03);
  EXPECT_NEAR(testing::enclosed_volume(mesh.rest, interface), region_volume(mesh, 0), 1e-9);
  EXPECT_EQ(mesh.face_sets.at("core.surface").rows(), interface.rows());
}

TEST(GenerateMesh, OverlappingPartsGiveTheOverlapToTheFirst) {
  GenerateOptions options;
  options.element_size = 0.2;
  const TetMesh mesh = generate_mesh(
      {Part{"a", unit_box()}, Part{"b", box(Vector3(0.5, 0, 0), Vector3(1.5, 1, 1))}}, options);
  EXPECT_NEAR(region_volume(mesh, 0), 1.0, 1e-12);
  EXPECT_NEAR(region_volume(mesh, 1), 0.5, 1e-12);
  EXPECT_NEAR(testing::total_area(mesh.rest, interface_triangles(mesh, 0, 1)), 1.0, 1e-12);
}

TEST(GenerateMesh, ElementSizeControlsTheTetCount) {
  const TetMesh coarse = mesh_one(unit_box(), 0.2);
  const TetMesh fine = mesh_one(unit_box(), 0.1);
  const double ratio = static_cast<double>(fine.num_tets()) / coarse.num_tets();
  EXPECT_GT(ratio, 5.0);
  EXPECT_LT(ratio, 11.0);
}

TEST(GenerateMesh, IsDeterministic) {
  const Shape shape = combine(Shape::Kind::Union, {unit_box(), sphere(Vector3(1, 1, 1), 0.4)});
  const TetMesh first = mesh_one(shape, 0.15);
  const TetMesh second = mesh_one(shape, 0.15);
  EXPECT_EQ(first.tets, second.tets);
  EXPECT_EQ(first.rest, second.rest);
}

TEST(GenerateMesh, RejectsBadShapesWithMessagesNamingThePart) {
  EXPECT_THAT(generate_error({Part{"wheel", sphere(Vector3::Zero(), -1)}}),
              AllOf(HasSubstr("part \"wheel\""), HasSubstr("sphere"), HasSubstr("radius")));
  EXPECT_THAT(generate_error({Part{"block", box(Vector3::Ones(), Vector3::Zero())}}),
              AllOf(HasSubstr("part \"block\""), HasSubstr("must exceed min")));
  EXPECT_THAT(generate_error({Part{"rod", cylinder(Vector3::Zero(), Vector3::Zero(), 1)}}),
              HasSubstr("axis"));
  EXPECT_THAT(generate_error({Part{"empty", combine(Shape::Kind::Union, {})}}),
              HasSubstr("at least one child"));
  Shape box_with_child = unit_box();
  box_with_child.children.push_back(unit_box());
  EXPECT_THAT(generate_error({Part{"odd", box_with_child}}),
              HasSubstr("only unions, differences and intersections have children"));
  EXPECT_THAT(
      generate_error(
          {Part{"gone", combine(Shape::Kind::Difference,
                                {unit_box(), box(Vector3::Constant(-1), Vector3::Constant(2))})}}),
      AllOf(HasSubstr("part \"gone\""), HasSubstr("empty")));
  EXPECT_THAT(generate_error({Part{
                  "deep", combine(Shape::Kind::Union, {unit_box(), sphere(Vector3::Zero(), 0)})}}),
              HasSubstr("sphere at children[1]"));
}

// ---------------------------------------------------------------- transforms

TEST(GenerateTransform, BoxRotated45DegreesKeepsItsVolumeAndItsCornersGoWhereTheRotationPuts) {
  // Unit square base, height 0.5, turned 45 degrees about the vertical line through (0.5, 0.5).
  const Vector3 center(0.5, 0.5, 0);
  const Shape slab =
      transformed(box(Vector3::Zero(), Vector3(1, 1, 0.5)), Vector3(0, 0, 2), 45, center);
  const TetMesh mesh = mesh_one(slab, 0.25);
  EXPECT_NEAR(volume_of(mesh), 0.5, 1e-12);
  expect_closed_outward_boundary(mesh);
  const double half_diagonal = std::sqrt(0.5);
  expect_bounds(mesh, Vector3(0.5 - half_diagonal, 0.5 - half_diagonal, 0),
                Vector3(0.5 + half_diagonal, 0.5 + half_diagonal, 0.5), 1e-9);
  const Eigen::AngleAxisd rotation(kPi / 4, Vector3::UnitZ());
  for (int corner = 0; corner < 8; ++corner) {
    const Vector3 rest((corner & 1) ? 1.0 : 0.0, (corner & 2) ? 1.0 : 0.0,
                       (corner & 4) ? 0.5 : 0.0);
    const Vector3 expected = rotation * (rest - center) + center;
    EXPECT_LT(distance_to_nearest_node(mesh, expected), 1e-9) << "corner " << rest.transpose();
  }
}

TEST(GenerateTransform, RotationComesBeforeTranslation) {
  // (1, 0, 0) turns to (0, 1, 0), then moves to (10, 1, 0); translating first would give
  // (0, 11, 0).
  const Shape moved = transformed(box(Vector3::Zero(), Vector3(1, 1, 0.5)), Vector3::UnitZ(), 90,
                                  Vector3::Zero(), Vector3(10, 0, 0));
  const TetMesh mesh = mesh_one(moved, 0.25);
  EXPECT_NEAR(volume_of(mesh), 0.5, 1e-12);
  expect_bounds(mesh, Vector3(9, 0, 0), Vector3(10, 1, 0.5), 1e-9);
  EXPECT_LT(distance_to_nearest_node(mesh, Vector3(10, 1, 0)), 1e-9);
}

TEST(GenerateTransform, NestedTransformsComposeFromTheInsideOut) {
  // The child turns 90 degrees about z: (x, y, z) -> (-y, x, z); then its parent turns 90
  // degrees about x: (x, y, z) -> (x, -z, y), then moves by (0, 0, 3).
  const Shape child = transformed(box(Vector3::Zero(), Vector3(2, 1, 0.5)), Vector3::UnitZ(), 90);
  const Shape parent = transformed(combine(Shape::Kind::Union, {child}), Vector3::UnitX(), 90,
                                   Vector3::Zero(), Vector3(0, 0, 3));
  const TetMesh mesh = mesh_one(parent, 0.25);
  EXPECT_NEAR(volume_of(mesh), 1.0, 1e-12);
  expect_bounds(mesh, Vector3(-1, -0.5, 3), Vector3(0, 0, 5), 1e-9);
  // The corner (2, 0, 0): child -> (0, 2, 0), parent -> (0, 0, 2) + (0, 0, 3).
  EXPECT_LT(distance_to_nearest_node(mesh, Vector3(0, 0, 5)), 1e-9);
}

TEST(GenerateTransform, ChildrenTransformBeforeTheBoolean) {
  // A unit cube minus a copy of itself turned 45 degrees about its vertical centre line leaves
  // four corner prisms, each of height 1 on a right triangle with legs 1 - 1/sqrt(2).
  const Vector3 center(0.5, 0.5, 0);
  const Shape turned = transformed(unit_box(), Vector3::UnitZ(), 45, center);
  const TetMesh mesh = mesh_one(combine(Shape::Kind::Difference, {unit_box(), turned}), 0.25);
  const double leg = 1 - std::sqrt(0.5);
  EXPECT_NEAR(volume_of(mesh), 4 * 0.5 * leg * leg, 1e-12);
  expect_closed_outward_boundary(mesh);
}

TEST(GenerateTransform, SlantedSlabOnAGroundPartIsConformingAndTheFirstPartTakesTheOverlap) {
  // The falling-rods foundation: a slab turned 45 degrees about y, half of it sunk into the
  // ground block (central symmetry about the origin), listed first so it keeps the overlap.
  GenerateOptions options;
  options.element_size = 0.25;
  const Shape slab =
      transformed(box(Vector3(-1, -0.5, -0.1), Vector3(1, 0.5, 0.1)), Vector3::UnitY(), 45);
  const TetMesh mesh = generate_mesh(
      {Part{"slab", slab}, Part{"ground", box(Vector3(-2, -1, -1), Vector3(2, 1, 0))}}, options);
  EXPECT_NEAR(region_volume(mesh, 0), 0.4, 1e-12);
  EXPECT_NEAR(region_volume(mesh, 1), 8.0 - 0.2, 1e-12);
  const Triangles boundary = boundary_triangles(mesh.tets);
  EXPECT_EQ(testing::euler_characteristic(boundary), 2);
  expect_closed_outward_boundary(mesh);
  // The buried half of the slab shares its faces with the ground: of the two 2 x 1 faces, area 2
  // in all (by the central symmetry); half of each 2 x 0.2 side; the 0.2 x 1 end at x = 1.
  EXPECT_NEAR(testing::total_area(mesh.rest, interface_triangles(mesh, 0, 1)), 2.0 + 2 * 0.2 + 0.2,
              1e-12);
}

// ---------------------------------------------------------------- intersections

TEST(GenerateIntersection, TwoOverlappingBoxesGiveTheOverlapBox) {
  const TetMesh mesh =
      mesh_one(combine(Shape::Kind::Intersection,
                       {unit_box(), box(Vector3(0.5, 0.25, -1), Vector3(1.5, 1.25, 0.5))}),
               0.2);
  EXPECT_NEAR(volume_of(mesh), 0.5 * 0.75 * 0.5, 1e-12);
  expect_bounds(mesh, Vector3(0.5, 0.25, 0), Vector3(1, 1, 0.5), 1e-12);
  expect_closed_outward_boundary(mesh);
  EXPECT_EQ(testing::euler_characteristic(boundary_triangles(mesh.tets)), 2);
}

TEST(GenerateIntersection, ThreeChildrenAndAChildOfSeveralVolumes) {
  // Two cubes side by side (a union of two volumes), a box across both, and a cube turned 90
  // degrees about y through its own centre (the same cube, with faces subject to round-off):
  // [0, 2] x [0, 1]^2 ∩ [0.5, 1.5] x [-1, 2] x [-1, 0.5] ∩ [0.5, 1.5] x [0, 1]^2.
  const Shape pair =
      combine(Shape::Kind::Union, {unit_box(), box(Vector3(1, 0, 0), Vector3(2, 1, 1))});
  const Shape across = box(Vector3(0.5, -1, -1), Vector3(1.5, 2, 0.5));
  const Shape turned = transformed(box(Vector3(0.5, 0, 0), Vector3(1.5, 1, 1)), Vector3::UnitY(),
                                   90, Vector3(1, 0.5, 0.5));
  const TetMesh mesh = mesh_one(combine(Shape::Kind::Intersection, {pair, across, turned}), 0.2);
  EXPECT_NEAR(volume_of(mesh), 0.5, 1e-12);
  expect_bounds(mesh, Vector3(0.5, 0, 0), Vector3(1.5, 1, 0.5), 1e-9);
  expect_closed_outward_boundary(mesh);
}

TEST(GenerateIntersection, BoxAndSphereGiveASphericalCap) {
  // A ball of radius 0.5 cut by the box z >= 0.3: a cap of height 0.2.
  const double radius = 0.5, height = 0.2;
  const TetMesh mesh = mesh_one(
      combine(Shape::Kind::Intersection, {sphere(Vector3::Zero(), radius),
                                          box(Vector3(-1, -1, radius - height), Vector3(1, 1, 1))}),
      0.1);
  EXPECT_NEAR(volume_of(mesh) / (kPi * height * height * (3 * radius - height) / 3), 1.0, 0.03);
  expect_closed_outward_boundary(mesh);
}

// ---------------------------------------------------------------- tori

TEST(GenerateTorus, QuarterTurnHasAQuarterOfTheTorusVolumeAndStartsAlongX) {
  const double major = 1, minor = 0.25;
  const TetMesh mesh = mesh_one(torus(Vector3::Zero(), Vector3::UnitZ(), major, minor, 90), 0.1);
  const double quarter_torus = kPi * minor * minor * 2 * kPi * major / 4;
  EXPECT_NEAR(volume_of(mesh) / quarter_torus, 1.0, 0.03);
  expect_closed_outward_boundary(mesh);
  EXPECT_EQ(testing::euler_characteristic(boundary_triangles(mesh.tets)), 2);
  // Flat ends in the planes y = 0 (start, on +x) and x = 0 (after a right-hand quarter turn
  // about +z); the curved surface stays within the torus's extent.
  expect_bounds(mesh, Vector3(0, 0, -minor), Vector3(major + minor, major + minor, minor), 0.02);
  EXPECT_NEAR(bounds_of(mesh).min.x(), 0, 1e-9);
  EXPECT_NEAR(bounds_of(mesh).min.y(), 0, 1e-9);
}

TEST(GenerateTorus, AxisStartDirectionAndCenterPlaceTheBentRod) {
  // Axis +y, starting towards +z: the sweep runs from +z towards y x z = +x.
  const double major = 0.8, minor = 0.2;
  Shape rod = torus(Vector3(1, 2, 3), Vector3(0, 3, 0), major, minor, 90);
  rod.start_direction = Vector3(0, 1, 1);  // only the part perpendicular to the axis counts
  const TetMesh mesh = mesh_one(rod, 0.1);
  EXPECT_NEAR(volume_of(mesh) / (kPi * minor * minor * 2 * kPi * major / 4), 1.0, 0.03);
  const Bounds bounds = bounds_of(mesh);
  EXPECT_NEAR(bounds.min.x(), 1, 1e-9);
  EXPECT_NEAR(bounds.min.z(), 3, 1e-9);
  expect_bounds(mesh, Vector3(1, 2 - minor, 3),
                Vector3(1 + major + minor, 2 + minor, 3 + major + minor), 0.02);
}

TEST(GenerateTorus, DefaultStartForAnAxisAlongXIsY) {
  // Axis -x: the default start is +y, the sweep runs towards (-x) x y = -z.
  const double major = 0.8, minor = 0.2;
  const TetMesh mesh = mesh_one(torus(Vector3::Zero(), Vector3(-1, 0, 0), major, minor, 90), 0.1);
  const Bounds bounds = bounds_of(mesh);
  EXPECT_NEAR(bounds.min.y(), 0, 1e-9);
  EXPECT_NEAR(bounds.max.z(), 0, 1e-9);
  expect_bounds(mesh, Vector3(-minor, 0, -major - minor), Vector3(minor, major + minor, 0), 0.02);
}

TEST(GenerateTorus, FullTorusVolumeAndGenus) {
  const double major = 1, minor = 0.3;
  const TetMesh mesh = mesh_one(torus(Vector3(0, 0, 1), Vector3(1, 1, 1), major, minor), 0.1);
  EXPECT_NEAR(volume_of(mesh) / (2 * kPi * kPi * major * minor * minor), 1.0, 0.03);
  expect_closed_outward_boundary(mesh);
  EXPECT_EQ(testing::euler_characteristic(boundary_triangles(mesh.tets)), 0);
}

TEST(GenerateTorus, BentRodRestingOnABoxIsConforming) {
  // A half-turn arch standing on a box, both in one part: the rod's flat ends sit on the top
  // face (the falling-rods curved bar).
  const double major = 0.6, minor = 0.15;
  Shape arch = torus(Vector3(0, 0, 0), Vector3(0, -1, 0), major, minor, 180);
  // Axis -y, default start +x, sweep towards (-y) x x = +z: an arch over the box top z = 0.
  const TetMesh mesh = mesh_one(
      combine(Shape::Kind::Union, {box(Vector3(-1, -0.5, -0.3), Vector3(1, 0.5, 0)), arch}), 0.1);
  const double expected = 2 * 1 * 0.3 + kPi * minor * minor * kPi * major;
  EXPECT_NEAR(volume_of(mesh) / expected, 1.0, 0.03);
  expect_closed_outward_boundary(mesh);
  expect_bounds(mesh, Vector3(-1, -0.5, -0.3), Vector3(1, 0.5, major + minor), 0.02);
}

TEST(GenerateShapeErrors, TorusTransformAndIntersectionInputs) {
  EXPECT_THAT(generate_error({Part{"ring", torus(Vector3::Zero(), Vector3::UnitZ(), 1, 1)}}),
              AllOf(HasSubstr("part \"ring\", torus"), HasSubstr("minor radius"),
                    HasSubstr("less than the radius 1, got 1")));
  EXPECT_THAT(generate_error({Part{"ring", torus(Vector3::Zero(), Vector3::UnitZ(), 1, 0.2, 0)}}),
              HasSubstr("angle must be in (0, 360] degrees, got 0"));
  EXPECT_THAT(generate_error({Part{"ring", torus(Vector3::Zero(), Vector3::UnitZ(), 1, 0.2, 361)}}),
              HasSubstr("angle must be in (0, 360] degrees, got 361"));
  EXPECT_THAT(generate_error({Part{"ring", torus(Vector3::Zero(), Vector3::Zero(), 1, 0.2)}}),
              HasSubstr("axis a finite non-zero vector"));
  Shape parallel = torus(Vector3::Zero(), Vector3::UnitZ(), 1, 0.2, 90);
  parallel.start_direction = Vector3(0, 0, -2);
  EXPECT_THAT(generate_error({Part{"ring", parallel}}),
              HasSubstr("start direction (0, 0, -2) must not be parallel to the axis"));

  EXPECT_THAT(
      generate_error({Part{"slab", transformed(unit_box(), Vector3::Zero(), 45)}}),
      AllOf(HasSubstr("part \"slab\", box"), HasSubstr("rotation axis must be a finite non-zero")));
  EXPECT_THAT(
      generate_error({Part{"slab", transformed(unit_box(), Vector3::UnitZ(), std::nan(""))}}),
      HasSubstr("rotation angle must be finite"));
  EXPECT_THAT(generate_error({Part{"slab", transformed(unit_box(), Vector3::UnitZ(), 0,
                                                       Vector3::Zero(), Vector3(0, INFINITY, 0))}}),
              HasSubstr("translation must be finite"));
  // A zero axis with no rotation is the identity, not an error.
  EXPECT_EQ(generate_error({Part{"slab", transformed(unit_box(), Vector3::Zero(), 0)}}), "");

  EXPECT_THAT(
      generate_error({Part{"cap", combine(Shape::Kind::Intersection, {unit_box()})}}),
      AllOf(HasSubstr("part \"cap\", intersection"), HasSubstr("at least two child shapes")));
  EXPECT_THAT(generate_error({Part{
                  "cap", combine(Shape::Kind::Intersection,
                                 {unit_box(), box(Vector3::Constant(2), Vector3::Constant(3))})}}),
              HasSubstr("empty (the shapes have no volume in common)"));
  EXPECT_THAT(generate_error({Part{
                  "deep", combine(Shape::Kind::Intersection,
                                  {unit_box(), transformed(unit_box(), Vector3::Zero(), 10)})}}),
              HasSubstr("box at children[1]: the rotation axis"));
}

TEST(GenerateMesh, RejectsBadPartListsAndOptions) {
  EXPECT_THAT(generate_error({}), HasSubstr("no parts"));
  EXPECT_THAT(generate_error({Part{"a", unit_box()}, Part{"a", unit_box()}}),
              HasSubstr("two parts are named \"a\""));
  EXPECT_THAT(generate_error({Part{"", unit_box()}}), HasSubstr("empty region name"));
  EXPECT_THAT(generate_error({Part{"a", unit_box()}}, 0.0), HasSubstr("element_size"));
  EXPECT_THAT(generate_error({Part{"outer", unit_box()},
                              Part{"inner", box(Vector3::Constant(0.2), Vector3::Constant(0.8))}}),
              AllOf(HasSubstr("part \"inner\""), HasSubstr("no volume of its own")));
}

}  // namespace
}  // namespace sinew::mesh
