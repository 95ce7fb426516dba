/// @file test_tetrahedralize.cpp
/// tetrahedralize (CGAL Mesh_3 on solids): volumes against the input, orientation, validity and
/// quality, precedence of overlapping parts, conforming interfaces, determinism, and the
/// messages for parts it cannot mesh. Each case meshes a few thousand tets (seconds in Release).

#include "sinew/surface/tetrahedralize.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <iterator>
#include <numbers>

#include "sinew/core/error.hpp"
#include "sinew/surface/surface_checks.hpp"
#include "surface/closed_fixtures.hpp"

namespace sinew::surface {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using Kind = Solid::Kind;

/// The message tetrahedralize throws, or "" when it meshes.
std::string rejection(const std::vector<SolidPart>& parts, const SurfaceLibrary& library, const TetrahedralizeOptions& options) {
  try {
    tetrahedralize(parts, library, options);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

/// A capsule (radius 2.5, axis 4) in the middle of the block [0,12]^3.
const Solid kCapsule{.kind = Kind::Capsule, .a = Vector3(4, 6, 6), .b = Vector3(8, 6, 6), .radius = 2.5};
const Solid kBlock{.kind = Kind::Box, .min = Vector3::Zero(), .max = Vector3::Constant(12)};
const double kCapsuleVolume = std::numbers::pi * 2.5 * 2.5 * 4 + 4.0 / 3.0 * std::numbers::pi * 2.5 * 2.5 * 2.5;

void print(const std::string& what, const mesh::TetMesh& mesh, const TetrahedralizeReport& report) {
  std::cout << what << ": " << mesh.num_nodes() << " nodes, " << mesh.num_tets() << " tets, min dihedral "
            << report.quality.min_dihedral_deg << " deg, worst radius ratio " << report.quality.worst_radius_ratio
            << ", " << report.seconds << " s\n";
}

TEST(Tetrahedralize, SphereVolumeOrientationValidityAndQuality) {
  SurfaceLibrary library;
  const SurfaceMesh sphere = sinew::testing::icosphere(10.0, 4);
  library.emplace("sphere", ClosedSurface(sphere, "sphere"));
  TetrahedralizeReport report;
  const mesh::TetMesh mesh = tetrahedralize({{"ball", {.kind = Kind::Surface, .surfaces = {"sphere"}}}}, library,
                                            {.element_size = 3, .facet_distance = 0.05, .what = "sphere"}, &report);
  print("sphere r 10, element_size 3, facet_distance 0.05", mesh, report);
  ASSERT_GT(mesh.num_tets(), 100);
  EXPECT_EQ(mesh.region_names, std::vector<std::string>{"ball"});
  ASSERT_EQ(report.region_volumes.size(), 1u);
  ASSERT_EQ(report.tets_per_region, std::vector<Index>{mesh.num_tets()});
  EXPECT_NEAR(report.region_volumes[0], enclosed_volume(sphere), 0.01 * enclosed_volume(sphere));
  double volume = 0;
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    const double v = mesh::signed_volume(mesh.rest, mesh.tets, t);
    EXPECT_GT(v, 0) << "tet " << t;
    volume += v;
  }
  EXPECT_NEAR(volume, report.region_volumes[0], 1e-9 * volume);
  EXPECT_NO_THROW(mesh::validate(mesh, "sphere"));
  EXPECT_GT(report.quality.min_dihedral_deg, 1.0);
  const mesh::MeshQuality quality = mesh::mesh_quality(mesh.rest, mesh.tets);
  EXPECT_EQ(report.quality.min_dihedral_deg, quality.min_dihedral_deg);
  EXPECT_EQ(report.quality.worst_tet, quality.worst_tet);
  // Every node lies in the ball (the boundary nodes on the input surface).
  for (Index v = 0; v < mesh.num_nodes(); ++v) EXPECT_LE(mesh.rest.row(v).norm(), 10.0 + 1e-6) << "node " << v;
  ASSERT_EQ(mesh.face_sets.count("ball.surface"), 1u);
  EXPECT_GT(mesh.face_sets.at("ball.surface").rows(), 50);
  for (const Index v : mesh.node_sets.at("ball.surface")) EXPECT_NEAR(mesh.rest.row(v).norm(), 10.0, 0.05) << "node " << v;
}

TEST(Tetrahedralize, FirstListedPartWinsAndInterfacesConform) {
  TetrahedralizeReport report;
  const mesh::TetMesh mesh = tetrahedralize({{"capsule", kCapsule}, {"block", kBlock}}, {}, {.element_size = 1.5, .facet_distance = 0.03}, &report);
  print("capsule in block, element_size 1.5, facet_distance 0.03", mesh, report);
  EXPECT_EQ(mesh.region_names, (std::vector<std::string>{"capsule", "block"}));
  ASSERT_EQ(report.region_volumes.size(), 2u);
  EXPECT_NEAR(report.region_volumes[0], kCapsuleVolume, 0.02 * kCapsuleVolume);
  EXPECT_NEAR(report.region_volumes[1], 1728 - kCapsuleVolume, 0.02 * (1728 - kCapsuleVolume));
  EXPECT_GT(report.tets_per_region[0], 0);
  EXPECT_GT(report.tets_per_region[1], 0);
  EXPECT_NO_THROW(mesh::validate(mesh, "capsule in block"));
  // Every capsule tet is in the capsule, up to the boundary's approximation.
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    if (mesh.region(t) != 0) continue;
    Vector3 centroid = Vector3::Zero();
    for (int k = 0; k < 4; ++k) centroid += 0.25 * mesh.rest.row(mesh.tets(t, k)).transpose();
    EXPECT_TRUE(solid_contains({.kind = Kind::Capsule, .a = kCapsule.a, .b = kCapsule.b, .radius = 2.6}, {}, centroid)) << t;
  }
  // Conforming: the capsule's boundary is all interface, so its nodes are all on the block's
  // boundary too, and its triangles are the interface's.
  ASSERT_EQ(mesh.node_sets.count("capsule.surface"), 1u);
  ASSERT_EQ(mesh.node_sets.count("block.surface"), 1u);
  const std::vector<Index>& capsule_nodes = mesh.node_sets.at("capsule.surface");
  const std::vector<Index>& block_nodes = mesh.node_sets.at("block.surface");
  std::vector<Index> shared;
  std::set_intersection(capsule_nodes.begin(), capsule_nodes.end(), block_nodes.begin(), block_nodes.end(), std::back_inserter(shared));
  EXPECT_GT(shared.size(), 0u);
  EXPECT_EQ(shared.size(), capsule_nodes.size());
  EXPECT_EQ(mesh::interface_triangles(mesh, 0, 1).rows(), mesh.face_sets.at("capsule.surface").rows());
}

TEST(Tetrahedralize, SameInputGivesTheSameMesh) {
  const std::vector<SolidPart> parts{{"capsule", kCapsule}, {"block", kBlock}};
  const mesh::TetMesh first = tetrahedralize(parts, {}, {.element_size = 2.5});
  const mesh::TetMesh second = tetrahedralize(parts, {}, {.element_size = 2.5});
  ASSERT_EQ(first.rest.rows(), second.rest.rows());
  ASSERT_EQ(first.tets.rows(), second.tets.rows());
  EXPECT_EQ(first.rest, second.rest);
  EXPECT_EQ(first.tets, second.tets);
  EXPECT_EQ(first.region, second.region);
}

TEST(Tetrahedralize, TinyPartIsReported) {
  // A ball of radius 0.1 between the seeding grid's points, in a block meshed at 3.
  const Solid tiny{.kind = Kind::Capsule, .a = Vector3(3.3, 4.4, 5.2), .b = Vector3(3.3, 4.4, 5.2), .radius = 0.1};
  EXPECT_THAT(rejection({{"grain", tiny}, {"block", kBlock}}, {}, {.element_size = 3, .what = "body \"leg\""}),
              AllOf(HasSubstr("body \"leg\""), HasSubstr("part \"grain\""), HasSubstr("got no elements")));
}

TEST(Tetrahedralize, HiddenPartIsReported) {
  EXPECT_THAT(rejection({{"block", kBlock}, {"capsule", kCapsule}}, {}, {.element_size = 3}),
              AllOf(HasSubstr("part \"capsule\""), HasSubstr("got no elements"), HasSubstr("hidden by earlier parts")));
}

TEST(Tetrahedralize, UnboundedPartIsRejected) {
  const Solid floor{.kind = Kind::HalfSpace, .point = Vector3(0, 0, 6), .normal = Vector3::UnitZ()};
  EXPECT_THAT(rejection({{"floor", floor}}, {}, {.element_size = 1}), AllOf(HasSubstr("part \"floor\""), HasSubstr("unbounded")));
  // Intersected with the block, it meshes: the block's lower half.
  const Solid slab{.kind = Kind::Intersection, .children = {floor, kBlock}};
  TetrahedralizeReport report;
  tetrahedralize({{"slab", slab}}, {}, {.element_size = 3}, &report);
  std::cout << "slab volume " << report.region_volumes[0] << "\n";
  EXPECT_NEAR(report.region_volumes[0], 12 * 12 * 6, 0.03 * 12 * 12 * 6);
}

TEST(Tetrahedralize, UnreachableQualityBoundIsRejected) {
  EXPECT_THAT(rejection({{"block", kBlock}}, {}, {.element_size = 4, .min_dihedral_deg = 89}),
              AllOf(HasSubstr("dihedral"), HasSubstr("min_dihedral_deg")));
}

TEST(Tetrahedralize, CapsuleSizeZoneRefinesItsInsideAndGradesAway) {
  // The block at element_size 4 with a capsule zone of size 1 round the segment (3,6,6)-(9,6,6),
  // radius 1.5: the tets in the capsule are a fraction of the plain mesh's, and they grow with the
  // distance from it (1 + 0.3 d: 2.5 to 3.1 more than 5 away, where Mesh_3 makes them smaller
  // than asked, near the block's faces).
  TetrahedralizeOptions options{.element_size = 4, .what = "block"};
  const ZoneCapsule capsule{.a = Vector3(3, 6, 6), .b = Vector3(9, 6, 6), .radius = 1.5};
  options.size_zones.push_back({.capsule = capsule, .size = 1, .grading = 0.3});
  TetrahedralizeReport report;
  const mesh::TetMesh fine = tetrahedralize({{"block", kBlock}}, {}, options, &report);
  print("block 12, element_size 4, capsule zone 1", fine, report);
  const mesh::TetMesh plain = tetrahedralize({{"block", kBlock}}, {}, {.element_size = 4, .what = "block"});
  EXPECT_GT(fine.num_tets(), 2 * plain.num_tets());
  // Mean first-edge length of the tets whose centroid is at a distance from the capsule in [lo, hi).
  const auto mean_edge = [&](const mesh::TetMesh& m, double lo, double hi) {
    double sum = 0;
    int count = 0;
    for (Index t = 0; t < m.num_tets(); ++t) {
      Vector3 centroid = Vector3::Zero();
      for (int k = 0; k < 4; ++k) centroid += m.rest.row(m.tets(t, k)).transpose() / 4;
      const double d = capsule_distance(capsule, centroid);
      if (d < lo || d >= hi) continue;
      sum += (m.rest.row(m.tets(t, 0)) - m.rest.row(m.tets(t, 1))).norm();
      ++count;
    }
    EXPECT_GT(count, 4) << "no tets at distance " << lo << " to " << hi;
    return sum / std::max(count, 1);
  };
  const double inside = mean_edge(fine, 0, 1e-12), far = mean_edge(fine, 5, 1e9);
  std::cout << "mean edge in the capsule " << inside << ", more than 5 away " << far << ", plain mesh "
            << mean_edge(plain, 0, 1e9) << "\n";
  EXPECT_LT(inside, 0.6 * mean_edge(plain, 0, 1e9));  // measured 1.34 against 2.65
  EXPECT_GT(far, 1.2 * inside);                        // measured 1.78: the grading
  EXPECT_NEAR(report.region_volumes.at(0), 12 * 12 * 12, 0.01 * 12 * 12 * 12);  // the box's edges are rounded
}

TEST(Tetrahedralize, CapsuleDistanceIsZeroInsideAndToTheSurfaceOutside) {
  const ZoneCapsule c{.a = Vector3(0, 0, 0), .b = Vector3(10, 0, 0), .radius = 2};
  EXPECT_EQ(capsule_distance(c, Vector3(5, 1, 1)), 0);
  EXPECT_DOUBLE_EQ(capsule_distance(c, Vector3(5, 0, 5)), 3);   // beside the axis
  EXPECT_DOUBLE_EQ(capsule_distance(c, Vector3(-4, 0, 0)), 2);  // beyond an end: the round cap
  EXPECT_DOUBLE_EQ(capsule_distance(c, Vector3(13, 4, 0)), 3);
  const ZoneCapsule ball{.a = Vector3(1, 1, 1), .b = Vector3(1, 1, 1), .radius = 1};  // a = b: a ball
  EXPECT_DOUBLE_EQ(capsule_distance(ball, Vector3(1, 1, 4)), 2);
}

TEST(Tetrahedralize, BadOptionsAndPartsAreRejected) {
  EXPECT_THAT(rejection({}, {}, {.element_size = 1, .what = "knee"}), AllOf(HasSubstr("knee"), HasSubstr("no parts")));
  TetrahedralizeOptions empty_zone{.element_size = 4, .what = "knee"};
  empty_zone.size_zones.push_back({.size = 1});
  EXPECT_THAT(rejection({{"block", kBlock}}, {}, empty_zone), AllOf(HasSubstr("knee"), HasSubstr("needs surfaces or a capsule")));
  TetrahedralizeOptions flat_capsule{.element_size = 4};
  flat_capsule.size_zones.push_back({.capsule = ZoneCapsule{.radius = 0}, .size = 1});
  EXPECT_THAT(rejection({{"block", kBlock}}, {}, flat_capsule), HasSubstr("capsule needs a radius > 0"));
  EXPECT_THAT(rejection({{"block", kBlock}}, {}, {.element_size = 0}), HasSubstr("element_size must be > 0"));
  EXPECT_THAT(rejection({{"bone", {.kind = Kind::Surface, .surfaces = {"femur"}}}}, {}, {.element_size = 1}),
              AllOf(HasSubstr("part \"bone\""), HasSubstr("unknown surface \"femur\"")));
}

}  // namespace
}  // namespace sinew::surface
