/// @file test_read_msh_safety.cpp
/// read_msh on hostile or damaged files: Gmsh scripts, FIFOs, malformed headers and sections,
/// counts larger than the file; each must end in an InputError that says what is wrong.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/read_msh.hpp"

namespace sinew::mesh {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using testing::read_msh_error;
using testing::write_text;
using ::testing::Not;

/// A Gmsh script that creates `marker` when Gmsh runs it.
std::string script_touching(const std::string& marker) {
  return "// a .geo script\nSystem \"touch " + marker + "\";\nPoint(1) = {0, 0, 0, 1};\n";
}

const std::string kTetV22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
    "$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n";

TEST(ReadMshSafety, ScriptNamedMshIsNotRun) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string marker = directory.file("pwned");
  const std::string path = directory.file("evil.msh");
  write_text(path, script_touching(marker));
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr("mesh file \"" + path + "\""), HasSubstr("is not a Gmsh MSH file"),
                    HasSubstr("$MeshFormat"), HasSubstr("never runs Gmsh scripts")));
  EXPECT_FALSE(std::filesystem::exists(marker));
}

TEST(ReadMshSafety, GeoExtensionIsRefusedEvenWithAnMshHeader) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string marker = directory.file("pwned");
  const std::string script = directory.file("evil.geo");
  write_text(script, script_touching(marker));
  EXPECT_THAT(read_msh_error(script), AllOf(HasSubstr(script), HasSubstr("extension \".geo\""),
                                            HasSubstr("*.msh")));
  // A genuine MSH file under another name is refused too: Gmsh picks its reader by extension.
  const std::string renamed = directory.file("tet.geo");
  write_text(renamed, kTetV22);
  EXPECT_THAT(read_msh_error(renamed), HasSubstr("extension \".geo\""));
  const std::string no_extension = directory.file("tet");
  write_text(no_extension, kTetV22);
  EXPECT_THAT(read_msh_error(no_extension), HasSubstr("extension \"\""));
  EXPECT_FALSE(std::filesystem::exists(marker));
}

TEST(ReadMshSafety, ScriptAfterAnMshHeaderIsNotRun) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string marker = directory.file("pwned");
  const std::string path = directory.file("header_then_script.msh");
  write_text(path, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + script_touching(marker));
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("no $Nodes section")));
  // Leading blank lines would make Gmsh's first-line sniffing miss the header.
  const std::string blank_first = directory.file("blank_first.msh");
  write_text(blank_first, "\n" + kTetV22 + script_touching(marker));
  EXPECT_THAT(read_msh_error(blank_first), HasSubstr("is not a Gmsh MSH file"));
  EXPECT_FALSE(std::filesystem::exists(marker));
}

TEST(ReadMshSafety, OptionFileBesideTheMeshIsNotRun) {
  // Gmsh, opening "tet.msh", also runs "tet.msh.opt" as a script when it exists.
  const testing::TempDir directory("sinew-msh-safety");
  const std::string marker = directory.file("pwned");
  const std::string path = directory.file("tet.msh");
  write_text(path, kTetV22);
  write_text(path + ".opt", script_touching(marker));
  EXPECT_EQ(read_msh(path).num_tets(), 1);
  EXPECT_FALSE(std::filesystem::exists(marker));
}

TEST(ReadMshSafety, GmshMessagesNameTheUsersFile) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("bad_entity.msh");
  // Passes sinew's checks; Gmsh rejects the element's unknown entity and names the file.
  write_text(path,
              "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
              "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
              "$Elements\n1 1 1 1\n3 9 4 1\n1 1 2 3 4\n$EndElements\n");
  const std::string message = read_msh_error(path);
  EXPECT_THAT(message, HasSubstr("Error loading '" + path + "'"));
  EXPECT_THAT(message, Not(HasSubstr("sinew-input-")));
}

TEST(ReadMshSafety, FifoIsRefusedWithoutBlocking) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("pipe.msh");
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  // Opening a FIFO without a writer would block forever; the check must come first.
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("not a regular file")));
}

TEST(ReadMshSafety, UnsupportedFormatHeaderIsNamed) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("v3.msh");
  write_text(path, "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n$Nodes\n0\n$EndNodes\n");
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr(path), HasSubstr("\"3.0 0 8\""), HasSubstr("2.2, 4.0 and 4.1")));
  write_text(path, "$MeshFormat\n4.1 0 4\n$EndMeshFormat\n");
  EXPECT_THAT(read_msh_error(path), HasSubstr("data size 8"));
}

TEST(ReadMshSafety, NonFiniteCoordinateIsReportedAsSuch) {
  const testing::TempDir directory("sinew-msh-safety");
  for (const std::string value : {"inf", "nan", "1e400"}) {
    const std::string path = directory.file("nonfinite.msh");
    write_text(path,
                "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 " + value + " 1 1\n$EndNodes\n"
                "$Elements\n2\n1 4 2 0 1 1 2 3 4\n2 4 2 0 1 2 3 5 4\n$EndElements\n");
    EXPECT_THAT(read_msh_error(path),
                AllOf(HasSubstr(path), HasSubstr("non-finite coordinate"), HasSubstr("node tag 5"),
                      Not(HasSubstr("inverted"))))
        << value;
  }
}

TEST(ReadMshSafety, DuplicateNodeTagIsReportedAsSuch) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("duplicate_tag.msh");
  write_text(path,
              "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
              "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n2 5 5 5\n$EndNodes\n"
              "$Elements\n2\n1 4 2 0 1 1 2 3 4\n2 4 2 0 1 2 3 5 4\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("duplicate node tag 2"),
                                          Not(HasSubstr("inverted"))));
}

TEST(ReadMshSafety, MissingEndNodesIsReportedAsAnUnclosedSection) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("no_end_nodes.msh");
  write_text(path,
              "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
              "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
              "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr(path), HasSubstr("$Nodes section is not closed by $EndNodes"),
                    Not(HasSubstr("no elements"))));
  // Cut off inside the $Elements section.
  write_text(path,
              "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
              "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
              "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n");
  EXPECT_THAT(read_msh_error(path), HasSubstr("$Elements section is not closed by $EndElements"));
}

TEST(ReadMshSafety, ElementWithAnUndefinedNodeTagIsReported) {
  // Gmsh 4.8 keeps such an element with a missing node and crashes when it is queried.
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("undefined_node.msh");
  write_text(path,
              "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
              "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
              "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 18446744073709551615 4\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr(path), HasSubstr("element 1 refers to node tag 18446744073709551615")));
  write_text(path,
              "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
              "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
              "$Elements\n1\n7 4 2 0 1 1 2 3 9\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path), HasSubstr("element 7 refers to node tag 9"));
}

TEST(ReadMshSafety, UnknownElementTypeIsReported) {
  // Gmsh 4.8 aborts on an assertion when it meets an element type it does not know.
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("unknown_type.msh");
  write_text(path,
              "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
              "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
              "$Elements\n1\n1 1028 2 0 1 1 2 3 4\n$EndElements\n");
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("elements of type 1028")));
}

TEST(ReadMshSafety, NodeDataForAnUndefinedNodeIsReported) {
  // Gmsh 4.8 indexes its storage with the tag and crashes.
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("node_data.msh");
  write_text(path, kTetV22 + "$NodeData\n1\n\"f\"\n1\n0\n3\n0\n1\n2\n1 0.5\n2147483647 1\n"
                              "$EndNodeData\n");
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr(path), HasSubstr("$NodeData section gives a value for node tag 2147483647")));
  // A negative matrix size in an interpolation scheme (Gmsh 4.8 aborts on it).
  write_text(path, kTetV22 + "$InterpolationScheme\n\"s\"\n1\n1\n1\n-2 2\n0 0\n0 0\n"
                              "$EndInterpolationScheme\n");
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr("$InterpolationScheme"), HasSubstr("\"-2\"")));
}

TEST(ReadMshSafety, NegativePhysicalNameCountIsReported) {
  // Gmsh 4.8 crashes on it.
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("physical_names.msh");
  write_text(path, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n-1\n3 1 \"body\"\n"
                    "$EndPhysicalNames\n" + kTetV22.substr(kTetV22.find("$Nodes")));
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr(path), HasSubstr("$PhysicalNames"),
                                          HasSubstr("\"-1\" where a count")));
}

template <class T>
std::string raw(T value) {
  return std::string(reinterpret_cast<const char*>(&value), sizeof(T));
}

/// A binary v4.1 file with one tet whose $Nodes header announces `num_nodes` nodes.
std::string binary_tet_v41(std::uint64_t num_nodes, std::uint64_t block_nodes = 4) {
  std::string file = "$MeshFormat\n4.1 1 8\n" + raw<int>(1) + "\n$EndMeshFormat\n$Nodes\n";
  for (const std::uint64_t v : {std::uint64_t{1}, num_nodes, std::uint64_t{1}, std::uint64_t{4}})
    file += raw(v);
  file += raw<int>(3) + raw<int>(1) + raw<int>(0) + raw(block_nodes);
  for (std::uint64_t tag = 1; tag <= 4; ++tag) file += raw(tag);
  const double coordinates[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (const double x : coordinates) file += raw(x);
  file += "\n$EndNodes\n$Elements\n";
  for (const std::uint64_t v : {std::uint64_t{1}, std::uint64_t{1}, std::uint64_t{1}, std::uint64_t{1}})
    file += raw(v);
  file += raw<int>(3) + raw<int>(1) + raw<int>(4) + raw(std::uint64_t{1});
  for (const std::uint64_t v : {std::uint64_t{1}, std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3},
                                std::uint64_t{4}})
    file += raw(v);
  file += "\n$EndElements\n";
  return file;
}

TEST(ReadMshSafety, BinaryCountLargerThanTheFileIsReported) {
  const testing::TempDir directory("sinew-msh-safety");
  const std::string path = directory.file("binary.msh");
  write_text(path, binary_tet_v41(4));
  EXPECT_EQ(read_msh(path).num_tets(), 1);  // the fixture itself is sound
  write_text(path, binary_tet_v41(1'000'000'000'000'000));
  EXPECT_THAT(read_msh_error(path),
              AllOf(HasSubstr(path), HasSubstr("malformed or truncated"),
                    HasSubstr("1000000000000000 nodes"), Not(HasSubstr("bad_alloc"))));
  write_text(path, binary_tet_v41(4, 1'000'000'000'000'000));
  EXPECT_THAT(read_msh_error(path), AllOf(HasSubstr("malformed or truncated"),
                                          HasSubstr("nodes in an entity block")));
}

}  // namespace
}  // namespace sinew::mesh
