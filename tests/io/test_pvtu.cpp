// Parallel VTU sets: the pieces of a dataset cover each cell once with the points and fields it
// needs, and the .pvtu lists the pieces and declares the arrays they hold.

#include "sinew/io/pvtu.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "io_test_support.hpp"
#include "sinew/core/error.hpp"

namespace sinew::io {
namespace {

using testing::read_text;
using testing::scan_attributes;
using testing::scan_data_arrays;
using testing::TempDir;

/// A bar of 6 tets over 12 nodes (three cubes' worth of corners in a row) and 4 triangles, with
/// a vector point field, a tensor-free scalar cell field and an integer cell field whose values
/// name their cell.
VtuData bar() {
  VtuData data;
  data.points.resize(12, 3);
  for (int i = 0; i < 12; ++i) data.points.row(i) << i / 4, (i % 4) / 2, i % 2;
  data.tets.resize(6, 4);
  data.tets << 0, 1, 2, 4,  //
      1, 2, 3, 5,           //
      4, 5, 6, 8,           //
      5, 6, 7, 9,           //
      8, 9, 10, 11,         //
      2, 3, 6, 7;
  data.triangles.resize(4, 3);
  data.triangles << 0, 1, 2,  //
      8, 9, 10,               //
      1, 3, 5,                //
      9, 11, 10;
  Eigen::MatrixXd displacement(12, 3);
  for (int i = 0; i < 12; ++i) displacement.row(i) << 0.5 * i, -1.0 * i, 2.0 + i;
  data.point_fields = {{"displacement", displacement}};
  Eigen::MatrixXd J(10, 1);
  IndexVector cell_id(10);
  for (int c = 0; c < 10; ++c) {
    J(c, 0) = 1.0 + 0.01 * c;
    cell_id[c] = 100 + c;
  }
  data.cell_fields = {{"J", J}};
  data.int_cell_fields = {{"cell", cell_id}};
  return data;
}

/// The cells k of 0..count-1 with (k * 5 + 1) % parts == part, in decreasing order: pieces that
/// are neither contiguous nor in the whole's order, as a mesh partition gives.
std::vector<Index> cells_of(Index count, int part, int parts) {
  std::vector<Index> cells;
  for (Index k = count - 1; k >= 0; --k)
    if ((k * 5 + 1) % parts == part) cells.push_back(k);
  return cells;
}

TEST(VtuPiece, PiecesCoverEveryCellOnceWithThePointsAndFieldsTheyUse) {
  const VtuData whole = bar();
  for (const int parts : {1, 2, 3, 4}) {
    SCOPED_TRACE(std::to_string(parts) + " pieces");
    std::multiset<Index> cells_seen;
    for (int part = 0; part < parts; ++part) {
      const std::vector<Index> tets = cells_of(6, part, parts), triangles = cells_of(4, part, parts);
      const VtuData piece = vtu_piece(whole, tets, triangles);
      ASSERT_EQ(piece.tets.rows(), static_cast<Eigen::Index>(tets.size()));
      ASSERT_EQ(piece.triangles.rows(), static_cast<Eigen::Index>(triangles.size()));
      // Each piece point is a point of the whole: find which, by its displacement (unique here).
      std::vector<Index> original(static_cast<std::size_t>(piece.points.rows()));
      for (Eigen::Index v = 0; v < piece.points.rows(); ++v) {
        original[static_cast<std::size_t>(v)] = static_cast<Index>(piece.point_fields[0].values(v, 0) / 0.5 + 0.5);
        EXPECT_EQ(piece.points.row(v), whole.points.row(original[static_cast<std::size_t>(v)]));
        EXPECT_EQ(piece.point_fields[0].values.row(v), whole.point_fields[0].values.row(original[static_cast<std::size_t>(v)]));
        if (v > 0) {
          EXPECT_LT(original[static_cast<std::size_t>(v - 1)], original[static_cast<std::size_t>(v)]);
        }
      }
      // The cells are the whole's, corner for corner, with their own field values; every piece
      // point is used by a cell.
      std::set<Index> used;
      for (Eigen::Index t = 0; t < piece.tets.rows(); ++t)
        for (int c = 0; c < 4; ++c) {
          EXPECT_EQ(original[static_cast<std::size_t>(piece.tets(t, c))], whole.tets(tets[static_cast<std::size_t>(t)], c));
          used.insert(piece.tets(t, c));
        }
      for (Eigen::Index f = 0; f < piece.triangles.rows(); ++f)
        for (int c = 0; c < 3; ++c) {
          EXPECT_EQ(original[static_cast<std::size_t>(piece.triangles(f, c))],
                    whole.triangles(triangles[static_cast<std::size_t>(f)], c));
          used.insert(piece.triangles(f, c));
        }
      EXPECT_EQ(used.size(), static_cast<std::size_t>(piece.points.rows()));
      const IndexVector& ids = piece.int_cell_fields.at(0).second;
      ASSERT_EQ(ids.size(), piece.tets.rows() + piece.triangles.rows());
      for (Eigen::Index c = 0; c < ids.size(); ++c) {
        cells_seen.insert(ids[c]);
        // In the piece's order: its tets, then its triangles.
        const std::size_t k = static_cast<std::size_t>(c);
        EXPECT_EQ(ids[c], c < piece.tets.rows() ? 100 + tets[k] : 106 + triangles[k - tets.size()]);
        EXPECT_DOUBLE_EQ(piece.cell_fields[0].values(c, 0), 1.0 + 0.01 * static_cast<double>(ids[c] - 100));
        // Tets first, then triangles: a piece's triangle rows name whole cells 106..109.
        EXPECT_EQ(ids[c] >= 106, c >= piece.tets.rows());
      }
    }
    std::multiset<Index> every_cell;
    for (Index c = 100; c < 110; ++c) every_cell.insert(c);
    EXPECT_EQ(cells_seen, every_cell);
  }
}

TEST(VtuPiece, ACellOutsideThePointsACellNotInTheWholeOrAFieldOfTheWrongLengthIsAnError) {
  VtuData broken = bar();
  broken.tets(3, 2) = 12;
  EXPECT_THAT([&] { vtu_piece(broken, {0, 1, 2, 3, 4, 5}, {0, 1, 2, 3}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("point 12 of 12")));
  const VtuData whole = bar();
  EXPECT_THAT([&] { vtu_piece(whole, {0, 6}, {}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("tet 6 of 6")));
  EXPECT_THAT([&] { vtu_piece(whole, {}, {-1}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("triangle -1 of 4")));
  VtuData short_field = bar();
  short_field.cell_fields[0].values.conservativeResize(9, 1);
  EXPECT_THAT([&] { vtu_piece(short_field, {0, 1, 2}, {0, 1}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("'J' has 9 rows for 10 cells")));
}

TEST(Pvtu, ListsThePiecesAndDeclaresTheArraysTheyHold) {
  TempDir directory;
  const VtuData whole = bar();
  std::vector<std::string> pieces;
  for (int part = 0; part < 3; ++part) {
    pieces.push_back("set_p" + std::to_string(part) + ".vtu");
    write_vtu((directory.path() / pieces.back()).string(),
              vtu_piece(whole, cells_of(6, part, 3), cells_of(4, part, 3)));
  }
  const auto path = directory.path() / "set.pvtu";
  write_pvtu(path.string(), whole, pieces);
  const std::string xml = read_text(path);
  EXPECT_NE(xml.find("<VTKFile type=\"PUnstructuredGrid\""), std::string::npos);
  EXPECT_NE(xml.find("header_type=\"UInt64\""), std::string::npos);

  // Every <Piece Source=...> in order.
  std::vector<std::string> sources;
  for (std::size_t at = xml.find("<Piece "); at != std::string::npos; at = xml.find("<Piece ", at + 1))
    sources.push_back(scan_attributes(xml.substr(at, xml.find('>', at) - at)).at("Source"));
  EXPECT_EQ(sources, pieces);

  // Each declaration matches the array of that name in a piece: type and components.
  const std::vector<testing::ScannedArray> piece_arrays =
      scan_data_arrays(read_text(directory.path() / pieces[1]));
  std::size_t declared = 0;
  for (std::size_t at = xml.find("<PDataArray "); at != std::string::npos; at = xml.find("<PDataArray ", at + 1)) {
    const auto attributes = scan_attributes(xml.substr(at, xml.find('>', at) - at));
    bool found = false;
    for (const auto& array : piece_arrays)
      if (array.attributes.at("Name") == attributes.at("Name")) {
        found = true;
        EXPECT_EQ(array.attributes.at("type"), attributes.at("type")) << attributes.at("Name");
        EXPECT_EQ(array.attributes.at("NumberOfComponents"), attributes.at("NumberOfComponents")) << attributes.at("Name");
      }
    EXPECT_TRUE(found) << attributes.at("Name");
    ++declared;
  }
  EXPECT_EQ(declared, 4u);  // Points, displacement, J, cell
}

TEST(Pvtu, NoPiecesOrAnUnnamedPieceIsAnErrorAndNothingIsWritten) {
  TempDir directory;
  const auto path = directory.path() / "set.pvtu";
  EXPECT_THAT([&] { write_pvtu(path.string(), bar(), {}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("no pieces")));
  EXPECT_THAT([&] { write_pvtu(path.string(), bar(), {"a.vtu", ""}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("a piece has no file name")));
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sinew::io
