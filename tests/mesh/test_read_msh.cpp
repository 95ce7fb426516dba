#include "sinew/mesh/read_msh.hpp"

#include <gmock/gmock.h>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/gmsh_session.hpp"

namespace sinew::mesh {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using testing::read_msh_error;
using testing::write_text;
namespace occ = gmsh::model::occ;

struct MshFormat {
  std::string name;
  double version;
  bool binary;
};

/// Writes a meshed model to `path`: the box [0, 2] x [0, 1] x [0, 1] as two unit cubes with
/// physical groups "left" (tag 1, x < 1) and "right" (tag 2); "bottom" (the z = 0 faces);
/// an unnamed group of tag 7 (the x = 0 face); "edge" (the 4 edges at x = 2); "corner" (the
/// point (0, 0, 0)); and "far_point", a point away from the box that no tet uses.
/// Returns Gmsh's tet count.
std::size_t write_two_cube_model(const std::string& path, const MshFormat& format) {
  GmshSession session;
  return session.run("writing " + path, [&] {
    gmsh::vectorpair out;
    std::vector<gmsh::vectorpair> out_map;
    occ::fragment({{3, occ::addBox(0, 0, 0, 1, 1, 1)}}, {{3, occ::addBox(1, 0, 0, 1, 1, 1)}}, out,
                  out_map);
    const int far_point = occ::addPoint(5, 5, 5);
    occ::synchronize();
    const auto entities_in = [](int dim, double x0, double y0, double z0, double x1, double y1,
                                double z1) {
      gmsh::vectorpair found;
      const double eps = 1e-6;
      gmsh::model::getEntitiesInBoundingBox(x0 - eps, y0 - eps, z0 - eps, x1 + eps, y1 + eps,
                                            z1 + eps, found, dim);
      std::vector<int> tags;
      for (const auto& [d, tag] : found) tags.push_back(tag);
      return tags;
    };
    gmsh::model::setPhysicalName(
        3, gmsh::model::addPhysicalGroup(3, entities_in(3, 0, 0, 0, 1, 1, 1), 1), "left");
    gmsh::model::setPhysicalName(
        3, gmsh::model::addPhysicalGroup(3, entities_in(3, 1, 0, 0, 2, 1, 1), 2), "right");
    gmsh::model::setPhysicalName(
        2, gmsh::model::addPhysicalGroup(2, entities_in(2, 0, 0, 0, 2, 1, 0), 3), "bottom");
    gmsh::model::addPhysicalGroup(2, entities_in(2, 0, 0, 0, 0, 1, 1), 7);
    gmsh::model::setPhysicalName(
        1, gmsh::model::addPhysicalGroup(1, entities_in(1, 2, 0, 0, 2, 1, 1), 4), "edge");
    gmsh::model::setPhysicalName(
        0, gmsh::model::addPhysicalGroup(0, entities_in(0, 0, 0, 0, 0, 0, 0), 5), "corner");
    gmsh::model::setPhysicalName(0, gmsh::model::addPhysicalGroup(0, {far_point}, 6), "far_point");
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.3);
    gmsh::model::mesh::generate(3);
    gmsh::option::setNumber("Mesh.MshFileVersion", format.version);
    gmsh::option::setNumber("Mesh.Binary", format.binary ? 1 : 0);
    gmsh::write(path);
    std::vector<std::size_t> tags;
    std::vector<std::size_t> nodes;
    gmsh::model::mesh::getElementsByType(4, tags, nodes);
    return tags.size();
  });
}

void PrintTo(const MshFormat& format, std::ostream* out) { *out << format.name; }

class ReadMshFormat : public ::testing::TestWithParam<MshFormat> {};

TEST_P(ReadMshFormat, RegionsFaceSetsAndNodeSets) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file(GetParam().name + ".msh");
  const std::size_t gmsh_tets = write_two_cube_model(path, GetParam());

  const TetMesh mesh = read_msh(path);
  EXPECT_EQ(static_cast<std::size_t>(mesh.num_tets()), gmsh_tets);
  EXPECT_EQ(mesh.region_names, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(referenced_nodes(mesh.tets).size(), static_cast<std::size_t>(mesh.num_nodes()));
  EXPECT_NEAR(testing::total_volume(mesh.rest, mesh.tets), 2.0, 1e-12);
  for (Index r = 0; r < 2; ++r) {
    double volume = 0;
    for (Index t = 0; t < mesh.num_tets(); ++t) {
      if (mesh.region(t) != r) continue;
      volume += signed_volume(mesh.rest, mesh.tets, t);
      double centroid_x = 0;
      for (int k = 0; k < 4; ++k) centroid_x += mesh.rest(mesh.tets(t, k), 0) / 4;
      EXPECT_EQ(centroid_x < 1.0, r == 0) << "tet " << t;
    }
    EXPECT_NEAR(volume, 1.0, 1e-12) << mesh.region_names[r];
  }

  // Face sets: triangles mapped to the new numbering, oriented outward on the boundary.
  ASSERT_TRUE(mesh.face_sets.count("bottom"));
  const Triangles& bottom = mesh.face_sets.at("bottom");
  EXPECT_NEAR(testing::total_area(mesh.rest, bottom), 2.0, 1e-12);
  for (Index f = 0; f < bottom.rows(); ++f) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.rest(bottom(f, k), 2), 0.0);
    EXPECT_LT(testing::triangle_area_vector(mesh.rest, bottom, f).z(), 0);  // outward: -z
  }
  ASSERT_TRUE(mesh.face_sets.count("group_7"));  // unnamed group, named by its tag
  EXPECT_NEAR(testing::total_area(mesh.rest, mesh.face_sets.at("group_7")), 1.0, 1e-12);
  EXPECT_EQ(mesh.face_sets.size(), 2u);  // dimension 0/1 groups make no face sets

  // Node sets: dimension 0, 1 and 2 groups.
  const auto& bottom_nodes = mesh.node_sets.at("bottom");
  for (const Index v : bottom_nodes) EXPECT_EQ(mesh.rest(v, 2), 0.0);
  std::vector<Index> bottom_triangle_nodes(bottom.data(), bottom.data() + bottom.size());
  std::sort(bottom_triangle_nodes.begin(), bottom_triangle_nodes.end());
  bottom_triangle_nodes.erase(
      std::unique(bottom_triangle_nodes.begin(), bottom_triangle_nodes.end()),
      bottom_triangle_nodes.end());
  EXPECT_EQ(bottom_nodes, bottom_triangle_nodes);
  EXPECT_TRUE(mesh.node_sets.count("group_7"));
  const auto& edge_nodes = mesh.node_sets.at("edge");
  EXPECT_GE(edge_nodes.size(), 8u);
  for (const Index v : edge_nodes) EXPECT_EQ(mesh.rest(v, 0), 2.0);
  const auto& corner = mesh.node_sets.at("corner");
  ASSERT_EQ(corner.size(), 1u);
  EXPECT_EQ(mesh.rest.row(corner[0]).norm(), 0.0);
  // The far point is no tet's node: dropped, along with its set's entry.
  EXPECT_TRUE(mesh.node_sets.at("far_point").empty());
  EXPECT_LE(mesh.rest.maxCoeff(), 2.0);
}

/// f(x, y, z) = 1 + x + 2y + 3z, the "depth" field of the node data tests.
double linear_field(double x, double y, double z) { return 1 + x + 2 * y + 3 * z; }

/// Appends node data views to the .msh file at `path` (written by write_two_cube_model):
/// "depth" = linear_field at every node of the file (unused ones included), "velocity" (3
/// components), "left_only" (the nodes with x <= 1), and an element data view "cell".
void append_node_data(const std::string& path, const MshFormat& format) {
  GmshSession session;
  session.run("appending node data to " + path, [&] {
    gmsh::open(path);
    std::string model;
    gmsh::model::getCurrent(model);
    std::vector<std::size_t> tags;
    std::vector<double> coordinates;
    std::vector<double> unused_parametric;
    gmsh::model::mesh::getNodes(tags, coordinates, unused_parametric);
    std::vector<double> depth;
    std::vector<double> velocity;
    std::vector<std::size_t> left_tags;
    std::vector<double> left;
    for (std::size_t i = 0; i < tags.size(); ++i) {
      const double x = coordinates[3 * i], y = coordinates[3 * i + 1], z = coordinates[3 * i + 2];
      depth.push_back(linear_field(x, y, z));
      velocity.insert(velocity.end(), {x, y, z});
      if (x <= 1) {
        left_tags.push_back(tags[i]);
        left.push_back(x);
      }
    }
    std::vector<std::size_t> tet_tags;
    std::vector<std::size_t> tet_nodes;
    gmsh::model::mesh::getElementsByType(4, tet_tags, tet_nodes);
    gmsh::option::setNumber("Mesh.MshFileVersion", format.version);
    gmsh::option::setNumber("Mesh.Binary", format.binary ? 1 : 0);
    gmsh::option::setNumber("PostProcessing.SaveMesh", 0);  // the file has it already
    const auto add_view = [&](const std::string& name, const std::string& type,
                              const std::vector<std::size_t>& view_tags, const std::vector<double>& data,
                              int components) {
      const int view = gmsh::view::add(name);
      gmsh::view::addHomogeneousModelData(view, 0, model, type, view_tags, data, 0.0, components);
      gmsh::view::write(view, path, /*append=*/true);
    };
    add_view("depth", "NodeData", tags, depth, 1);
    add_view("velocity", "NodeData", tags, velocity, 3);
    add_view("left_only", "NodeData", left_tags, left, 1);
    add_view("cell", "ElementData", tet_tags, std::vector<double>(tet_tags.size(), 1.0), 1);
  });
}

TEST_P(ReadMshFormat, ScalarNodeDataBecomeNodeFields) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file(GetParam().name + "_fields.msh");
  write_two_cube_model(path, GetParam());
  append_node_data(path, GetParam());

  const TetMesh mesh = read_msh(path);
  ASSERT_EQ(mesh.node_fields.size(), 1u);
  ASSERT_TRUE(mesh.node_fields.count("depth"));
  const VectorX& depth = mesh.node_fields.at("depth");
  ASSERT_EQ(depth.size(), mesh.num_nodes());
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    EXPECT_NEAR(depth[v], linear_field(mesh.rest(v, 0), mesh.rest(v, 1), mesh.rest(v, 2)), 1e-12)
        << "node " << v;
  }
  EXPECT_THAT(mesh.skipped_node_fields.at("velocity"), HasSubstr("3 components per node, not 1"));
  EXPECT_THAT(mesh.skipped_node_fields.at("left_only"), HasSubstr("no value at"));
  EXPECT_THAT(mesh.skipped_node_fields.at("cell"), HasSubstr("ElementData, not node data"));
  EXPECT_EQ(mesh.skipped_node_fields.size(), 3u);
}

INSTANTIATE_TEST_SUITE_P(Formats, ReadMshFormat,
                         ::testing::Values(MshFormat{"v22_ascii", 2.2, false},
                                           MshFormat{"v22_binary", 2.2, true},
                                           MshFormat{"v41_ascii", 4.1, false},
                                           MshFormat{"v41_binary", 4.1, true}),
                         [](const auto& info) { return info.param.name; });

TEST(ReadMsh, HandWrittenV22WithSparseTagsInvertedTetAndUnusedNode) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("hand.msh");
  // Two tets without physical groups, the second written with negative orientation; node 99
  // is used by no tet.
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$Nodes\n6\n"
             "10 0 0 0\n20 1 0 0\n30 0 1 0\n40 0 0 1\n99 7 7 7\n50 1 1 1\n"
             "$EndNodes\n"
             "$Elements\n2\n"
             "1 4 2 0 1 10 20 30 40\n"
             "2 4 2 0 1 20 30 40 50\n"
             "$EndElements\n");
  const TetMesh mesh = read_msh(path);
  EXPECT_EQ(mesh.num_nodes(), 5);
  EXPECT_EQ(mesh.num_tets(), 2);
  EXPECT_EQ(mesh.region_names, std::vector<std::string>{"default"});
  EXPECT_EQ(mesh.region, IndexVector::Zero(2));
  // Renumbered in ascending tag order: 10, 20, 30, 40, 50 -> 0..4.
  EXPECT_EQ(mesh.rest.row(4), (Eigen::RowVector3d(1, 1, 1)));
  for (Index t = 0; t < 2; ++t) EXPECT_GT(signed_volume(mesh.rest, mesh.tets, t), 0);
  EXPECT_NEAR(testing::total_volume(mesh.rest, mesh.tets), 1.0 / 6 + 1.0 / 3, 1e-12);
}

TEST(ReadMsh, NodeDataFollowTheNodeTagsAndTheFirstTimeStep) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("fields.msh");
  // Sparse tags listed out of order; node 99 is used by no tet. "depth" = 1 + x + 2y + 3z is
  // given in tag order 99, 50, ..., 10 at time step 3 (steps 0-2 are empty) and again, with
  // other values, at step 5; "gappy" misses node 30; "with_nan" holds a NaN (kept: what a
  // field may hold is its user's business).
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$Nodes\n6\n"
             "40 0 0 1\n10 0 0 0\n30 0 1 0\n20 1 0 0\n99 7 7 7\n50 1 1 1\n"
             "$EndNodes\n"
             "$Elements\n2\n"
             "1 4 2 0 1 10 20 30 40\n"
             "2 4 2 0 1 20 30 40 50\n"
             "$EndElements\n"
             "$NodeData\n1\n\"depth\"\n1\n0.5\n3\n3\n1\n6\n"
             "99 43\n50 7\n40 4\n30 3\n20 2\n10 1\n$EndNodeData\n"
             "$NodeData\n1\n\"depth\"\n1\n1.0\n3\n5\n1\n5\n"
             "50 -1\n40 -1\n30 -1\n20 -1\n10 -1\n$EndNodeData\n"
             "$NodeData\n1\n\"gappy\"\n1\n0\n3\n0\n1\n4\n"
             "10 0\n20 0\n40 0\n50 0\n$EndNodeData\n"
             "$NodeData\n1\n\"with_nan\"\n1\n0\n3\n0\n1\n5\n"
             "10 0\n20 nan\n30 0\n40 0\n50 0\n$EndNodeData\n");
  const TetMesh mesh = read_msh(path);
  ASSERT_EQ(mesh.num_nodes(), 5);
  const VectorX& depth = mesh.node_fields.at("depth");
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    EXPECT_EQ(depth[v], linear_field(mesh.rest(v, 0), mesh.rest(v, 1), mesh.rest(v, 2))) << "node " << v;
  }
  EXPECT_TRUE(std::isnan(mesh.node_fields.at("with_nan")[1]));  // tag 20
  EXPECT_EQ(mesh.node_fields.size(), 2u);
  EXPECT_EQ(mesh.skipped_node_fields.at("gappy"),
            "no value at 1 of the mesh's 5 nodes, e.g. node 2 (Gmsh node tag 30) at (0, 1, 0)");
}

TEST(ReadMsh, WithoutNodeDataThereAreNoNodeFields) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("plain.msh");
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
             "$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n");
  const TetMesh mesh = read_msh(path);
  EXPECT_TRUE(mesh.node_fields.empty());
  EXPECT_TRUE(mesh.skipped_node_fields.empty());
}

TEST(ReadMsh, TetsOutsideEveryGroupFormTheDefaultRegion) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("partial.msh");
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$PhysicalNames\n1\n3 5 \"body\"\n$EndPhysicalNames\n"
             "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n"
             "$Elements\n2\n"
             "1 4 2 5 1 1 2 3 4\n"
             "2 4 2 0 2 2 3 5 4\n"
             "$EndElements\n");
  const TetMesh mesh = read_msh(path);
  EXPECT_EQ(mesh.region_names, (std::vector<std::string>{"body", "default"}));
  EXPECT_EQ(mesh.region(0), 0);
  EXPECT_EQ(mesh.region(1), 1);
}

TEST(ReadMsh, MissingFileNamesThePath) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("nowhere.msh");
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("does not exist")));
  EXPECT_THAT(read_msh_error(directory.file("")), HasSubstr("not a regular file"));
}

TEST(ReadMsh, GarbageFileNamesThePath) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("garbage.msh");
  write_text(path, "this is not a mesh\n\x01\x02\x03 at all\n");
  // Never handed to Gmsh, which would parse it as a script.
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr("mesh file \"" + path + "\""), HasSubstr("is not a Gmsh MSH file")));
}

TEST(ReadMsh, TruncatedFileNamesThePath) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("truncated.msh");
  write_text(path, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n");
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr("mesh file \"" + path + "\""), HasSubstr("truncated"),
                    HasSubstr("$Nodes")));
}

TEST(ReadMsh, EmptyFileIsNotAnMshFile) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("empty.msh");
  write_text(path, "");
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("is not a Gmsh MSH file")));
}

TEST(ReadMsh, OtherVolumeElementsAreRejectedRatherThanDropped) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("hex.msh");
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$Nodes\n9\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
             "5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n9 0 0 2\n$EndNodes\n"
             "$Elements\n2\n1 5 2 0 1 1 2 3 4 5 6 7 8\n2 4 2 0 2 5 6 8 9\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr(path), HasSubstr("other than linear tetrahedra (Hexahedron 8)")));
}

TEST(ReadMsh, SecondOrderTetsAreRejected) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("quadratic.msh");
  {
    GmshSession session;
    session.run("writing " + path, [&] {
      occ::addBox(0, 0, 0, 1, 1, 1);
      occ::synchronize();
      gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
      gmsh::option::setNumber("Mesh.ElementOrder", 2);
      gmsh::model::mesh::generate(3);
      gmsh::write(path);
    });
  }
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("Tetrahedron 10")));
}

TEST(ReadMsh, SurfaceMeshIsRejectedWithTheElementTypesFound) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("surface.msh");
  {
    GmshSession session;
    session.run("writing " + path, [&] {
      occ::addBox(0, 0, 0, 1, 1, 1);
      occ::synchronize();
      gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
      gmsh::model::mesh::generate(2);
      gmsh::write(path);
    });
  }
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr(path), HasSubstr("no linear tetrahedra"), HasSubstr("Triangle")));
}

TEST(ReadMsh, InvalidMeshFailsValidationNamingTheFile) {
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("duplicate.msh");
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
             "$Elements\n2\n1 4 2 0 1 1 2 3 4\n2 4 2 0 1 2 1 4 3\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr("mesh \"" + path + "\""), HasSubstr("duplicate tetrahedron")));
}

TEST(ReadMsh, FoldedTetIsRejectedAsInverted) {
  // Tets 1 and 2 share the face (1, 2, 3) but both apexes lie above it: tet 2 is inverted
  // relative to tet 1 and the mesh overlaps itself.
  const testing::TempDir directory("sinew-read-msh");
  const std::string path = directory.file("folded.msh");
  write_text(path,
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
             "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0.2 0.2 0.5\n$EndNodes\n"
             "$Elements\n2\n1 4 2 0 1 1 2 3 4\n2 4 2 0 1 1 3 2 5\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("inverted tetrahedron"),
                                          HasSubstr("tets 0 and 1"), HasSubstr("folds over itself")));
}

}  // namespace
}  // namespace sinew::mesh
