#include "sinew/mesh/generate.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
              HasSubstr("only unions and differences have children"));
  EXPECT_THAT(
      generate_error(
          {Part{"gone", combine(Shape::Kind::Difference,
                                {unit_box(), box(Vector3::Constant(-1), Vector3::Constant(2))})}}),
      AllOf(HasSubstr("part \"gone\""), HasSubstr("empty")));
  EXPECT_THAT(generate_error({Part{
                  "deep", combine(Shape::Kind::Union, {unit_box(), sphere(Vector3::Zero(), 0)})}}),
              HasSubstr("sphere at children[1]"));
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
