#include "sinew/io/vtu.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_support.hpp"
#include "sinew/core/error.hpp"

namespace sinew::io {
namespace {

namespace fs = std::filesystem;
using testing::decode_binary_array;
using testing::read_text;
using testing::scan_attributes;
using testing::scan_data_arrays;
using testing::ScannedArray;
using testing::TempDir;

/// Two tets sharing a face, plus two boundary triangles; 5 nodes.
VtuData small_mixed_mesh() {
  VtuData data;
  data.points.resize(5, 3);
  data.points << 0.0, 0.0, 0.0,  //
      1.0, 0.0, 0.0,             //
      0.0, 1.0, 0.0,             //
      0.0, 0.0, 1.0,             //
      0.1 + 0.2, 1.0 / 3.0, -7.25e-300;
  data.tets.resize(2, 4);
  data.tets << 0, 1, 2, 3,  //
      1, 2, 3, 4;
  data.triangles.resize(2, 3);
  data.triangles << 0, 2, 1,  //
      1, 2, 4;

  Eigen::MatrixXd displacement(5, 3);
  for (int i = 0; i < 5; ++i) {
    displacement.row(i) << 0.1 * i, -std::sqrt(2.0) * i, 1e-17 * i;
  }
  Eigen::MatrixXd temperature(5, 1);
  temperature << 1.0, 2.0, std::numeric_limits<double>::quiet_NaN(), 4.0, -0.0;
  data.point_fields = {{"displacement", displacement}, {"temperature", temperature}};

  Eigen::MatrixXd stress(4, 9);
  for (int cell = 0; cell < 4; ++cell) {
    for (int k = 0; k < 9; ++k) stress(cell, k) = 100.0 * cell + k + 0.5;
  }
  Eigen::MatrixXd volume(4, 1);
  volume << 1.0 / 6.0, 1.0 / 7.0, 0.0, std::numeric_limits<double>::infinity();
  data.cell_fields = {{"stress", stress}, {"volume", volume}};

  IndexVector region(4);
  region << 1, 2, -3, 2147483647;
  data.int_cell_fields = {{"region", region}};
  return data;
}

const ScannedArray& find_array(const std::vector<ScannedArray>& arrays, const std::string& section,
                               const std::string& name) {
  for (const ScannedArray& array : arrays) {
    if (array.section == section && array.attributes.count("Name") &&
        array.attributes.at("Name") == name) {
      return array;
    }
  }
  throw std::runtime_error("no array '" + name + "' in " + section);
}

/// Bitwise equality, so NaN == NaN and -0 != +0.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void expect_float64_rows(const ScannedArray& array, const Eigen::MatrixXd& expected) {
  EXPECT_EQ(array.attributes.at("type"), "Float64");
  EXPECT_EQ(array.attributes.at("format"), "binary");
  EXPECT_EQ(array.attributes.at("NumberOfComponents"), std::to_string(expected.cols()));
  const std::vector<double> values = decode_binary_array<double>(array);
  ASSERT_EQ(values.size(), static_cast<std::size_t>(expected.size()));
  std::size_t k = 0;
  for (Eigen::Index row = 0; row < expected.rows(); ++row) {
    for (Eigen::Index column = 0; column < expected.cols(); ++column, ++k) {
      EXPECT_TRUE(same_bits(values[k], expected(row, column)))
          << array.attributes.at("Name") << "(" << row << ", " << column << "): " << values[k]
          << " != " << expected(row, column);
    }
  }
}

TEST(Vtu, MixedMeshRoundTripsEveryArrayExactly) {
  TempDir scratch;
  const VtuData data = small_mixed_mesh();
  const std::string path = scratch.file("out/mesh.vtu");
  write_vtu(path, data);
  const std::string xml = read_text(path);

  ASSERT_EQ(xml.rfind("<?xml", 0), 0u);
  const std::size_t file_tag = xml.find("<VTKFile");
  const auto file_attributes = scan_attributes(xml.substr(file_tag, xml.find('>', file_tag) - file_tag));
  EXPECT_EQ(file_attributes.at("type"), "UnstructuredGrid");
  EXPECT_EQ(file_attributes.at("version"), "1.0");
  EXPECT_EQ(file_attributes.at("header_type"), "UInt64");
  EXPECT_EQ(file_attributes.at("byte_order"), "LittleEndian");
  const std::size_t piece_tag = xml.find("<Piece");
  const auto piece = scan_attributes(xml.substr(piece_tag, xml.find('>', piece_tag) - piece_tag));
  EXPECT_EQ(piece.at("NumberOfPoints"), "5");
  EXPECT_EQ(piece.at("NumberOfCells"), "4");
  EXPECT_NE(xml.find("</VTKFile>"), std::string::npos);

  const std::vector<ScannedArray> arrays = scan_data_arrays(xml);
  ASSERT_EQ(arrays.size(), 1u + 3u + 2u + 3u);

  expect_float64_rows(find_array(arrays, "Points", "Points"), Eigen::MatrixXd(data.points));

  const ScannedArray& connectivity = find_array(arrays, "Cells", "connectivity");
  EXPECT_EQ(connectivity.attributes.at("type"), "Int64");
  EXPECT_EQ(decode_binary_array<std::int64_t>(connectivity),
            (std::vector<std::int64_t>{0, 1, 2, 3, 1, 2, 3, 4, 0, 2, 1, 1, 2, 4}));
  const ScannedArray& offsets = find_array(arrays, "Cells", "offsets");
  EXPECT_EQ(offsets.attributes.at("type"), "Int64");
  EXPECT_EQ(decode_binary_array<std::int64_t>(offsets), (std::vector<std::int64_t>{4, 8, 11, 14}));
  const ScannedArray& types = find_array(arrays, "Cells", "types");
  EXPECT_EQ(types.attributes.at("type"), "UInt8");
  EXPECT_EQ(decode_binary_array<std::uint8_t>(types), (std::vector<std::uint8_t>{10, 10, 5, 5}));

  expect_float64_rows(find_array(arrays, "PointData", "displacement"), data.point_fields[0].values);
  expect_float64_rows(find_array(arrays, "PointData", "temperature"), data.point_fields[1].values);
  expect_float64_rows(find_array(arrays, "CellData", "stress"), data.cell_fields[0].values);
  expect_float64_rows(find_array(arrays, "CellData", "volume"), data.cell_fields[1].values);

  const ScannedArray& region = find_array(arrays, "CellData", "region");
  EXPECT_EQ(region.attributes.at("type"), "Int32");
  EXPECT_EQ(region.attributes.at("NumberOfComponents"), "1");
  EXPECT_EQ(decode_binary_array<std::int32_t>(region),
            (std::vector<std::int32_t>{1, 2, -3, 2147483647}));
}

TEST(Vtu, TetsOnlyAndTrianglesOnlyAndEmptyMeshesAreWritten) {
  TempDir scratch;
  VtuData tets_only = small_mixed_mesh();
  tets_only.triangles.resize(0, 3);
  tets_only.cell_fields.clear();
  tets_only.int_cell_fields.clear();
  write_vtu(scratch.file("tets.vtu"), tets_only);
  auto arrays = scan_data_arrays(read_text(scratch.file("tets.vtu")));
  EXPECT_EQ(decode_binary_array<std::uint8_t>(find_array(arrays, "Cells", "types")),
            (std::vector<std::uint8_t>{10, 10}));

  VtuData triangles_only = small_mixed_mesh();
  triangles_only.tets.resize(0, 4);
  triangles_only.cell_fields.clear();
  triangles_only.int_cell_fields.clear();
  write_vtu(scratch.file("triangles.vtu"), triangles_only);
  arrays = scan_data_arrays(read_text(scratch.file("triangles.vtu")));
  EXPECT_EQ(decode_binary_array<std::int64_t>(find_array(arrays, "Cells", "offsets")),
            (std::vector<std::int64_t>{3, 6}));

  write_vtu(scratch.file("empty.vtu"), VtuData{});
  arrays = scan_data_arrays(read_text(scratch.file("empty.vtu")));
  EXPECT_TRUE(decode_binary_array<double>(find_array(arrays, "Points", "Points")).empty());
}

TEST(Vtu, FieldNamesAreXmlEscaped) {
  TempDir scratch;
  VtuData data = small_mixed_mesh();
  data.point_fields[0].name = "u<\"&'>";
  write_vtu(scratch.file("escaped.vtu"), data);
  const std::string xml = read_text(scratch.file("escaped.vtu"));
  EXPECT_NE(xml.find("Name=\"u&lt;&quot;&amp;&apos;&gt;\""), std::string::npos);
}

/// The message of the sinew::Error that `write` throws; fails the test if none is thrown.
template <typename Write>
std::string error_message(Write write) {
  try {
    write();
  } catch (const Error& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected sinew::Error";
  return {};
}

TEST(Vtu, ShapeMismatchesNameTheFieldAndWriteNothing) {
  TempDir scratch;
  const std::string path = scratch.file("bad.vtu");
  auto expect_error = [&](const VtuData& data, const std::vector<std::string>& fragments) {
    const std::string message = error_message([&] { write_vtu(path, data); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
    }
    EXPECT_FALSE(fs::exists(path));
  };

  VtuData data = small_mixed_mesh();
  data.point_fields[1].values.resize(4, 1);
  expect_error(data, {"point field 'temperature'", "4 rows", "expected 5"});

  data = small_mixed_mesh();
  data.cell_fields[0].values.resize(2, 9);  // one per tet only: the triangles were forgotten
  expect_error(data, {"cell field 'stress'", "2 rows", "expected 4"});

  data = small_mixed_mesh();
  data.cell_fields[1].values.resize(4, 0);
  expect_error(data, {"cell field 'volume'", "no columns"});

  data = small_mixed_mesh();
  data.int_cell_fields[0].second.resize(5);
  expect_error(data, {"integer cell field 'region'", "5 rows", "expected 4"});

  data = small_mixed_mesh();
  data.point_fields.push_back({"displacement", Eigen::MatrixXd::Zero(5, 3)});
  expect_error(data, {"'displacement'", "two arrays"});

  data = small_mixed_mesh();
  data.int_cell_fields[0].first = "volume";  // clashes with a Float64 cell field
  expect_error(data, {"'volume'", "two arrays"});

  data = small_mixed_mesh();
  data.point_fields[0].name.clear();
  expect_error(data, {"empty name"});

  data = small_mixed_mesh();
  data.tets(1, 3) = 5;
  expect_error(data, {"tetrahedron 1", "node 5"});

  data = small_mixed_mesh();
  data.triangles(0, 0) = -1;
  expect_error(data, {"triangle 0", "node -1"});

  data = small_mixed_mesh();
  data.points(3, 1) = std::numeric_limits<double>::quiet_NaN();
  expect_error(data, {"point 3", "non-finite"});

  data = small_mixed_mesh();
  data.points(2, 2) = -std::numeric_limits<double>::infinity();
  expect_error(data, {"point 2", "non-finite"});
}

// ----- meshio, through Debian's Python -------------------------------------------------------

/// Parses the summary the Python script prints: lines of whitespace-separated tokens.
std::vector<std::vector<std::string>> read_token_lines(const std::string& path) {
  std::vector<std::vector<std::string>> lines;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream tokens(line);
    std::vector<std::string> words;
    std::string word;
    while (tokens >> word) words.push_back(word);
    if (!words.empty()) lines.push_back(words);
  }
  return lines;
}

const std::vector<std::string>& line_starting_with(const std::vector<std::vector<std::string>>& lines,
                                                   const std::vector<std::string>& prefix) {
  for (const auto& line : lines) {
    if (line.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), line.begin())) {
      return line;
    }
  }
  throw std::runtime_error("meshio summary has no line starting with '" + prefix.front() + " " +
                           (prefix.size() > 1 ? prefix[1] : "") + "'");
}

/// Doubles from `words[first...]` (Python repr text, read back exactly by strtod).
std::vector<double> parse_doubles(const std::vector<std::string>& words, std::size_t first) {
  std::vector<double> values;
  for (std::size_t i = first; i < words.size(); ++i) values.push_back(std::strtod(words[i].c_str(), nullptr));
  return values;
}

void expect_same_values(const std::vector<double>& actual, const Eigen::MatrixXd& expected,
                        const std::string& what) {
  ASSERT_EQ(actual.size(), static_cast<std::size_t>(expected.size())) << what;
  std::size_t k = 0;
  for (Eigen::Index row = 0; row < expected.rows(); ++row) {
    for (Eigen::Index column = 0; column < expected.cols(); ++column, ++k) {
      const double e = expected(row, column);
      EXPECT_TRUE(std::isnan(e) ? std::isnan(actual[k]) : actual[k] == e)
          << what << "(" << row << ", " << column << "): meshio read " << actual[k] << ", wrote " << e;
    }
  }
}

TEST(Vtu, MeshioReadsTheFile) {
  const int import_status = std::system("/usr/bin/python3 -c 'import meshio' > /dev/null 2>&1");
  ASSERT_EQ(import_status, 0)
      << "/usr/bin/python3 cannot import meshio (Debian package python3-meshio). "
         "Run scripts/install-deps.sh to install the project's dependencies.";

  TempDir scratch;
  const VtuData data = small_mixed_mesh();
  const std::string vtu_path = scratch.file("mesh.vtu");
  const std::string summary_path = scratch.file("summary.txt");
  const std::string script_path = scratch.file("read_with_meshio.py");
  write_vtu(vtu_path, data);

  // One line per array: a key, the shape, then the values (repr() reads back exactly).
  std::ofstream(script_path) << R"PY(
import sys
import meshio

mesh = meshio.read(sys.argv[1])

def values(array):
    return " ".join(repr(v) for v in array.ravel().tolist())

def shape(array):
    return "x".join(str(n) for n in array.shape)

with open(sys.argv[2], "w") as out:
    out.write(f"points {shape(mesh.points)} {mesh.points.dtype} {values(mesh.points)}\n")
    for block_index, block in enumerate(mesh.cells):
        out.write(f"cells {block_index} {block.type} {shape(block.data)} {values(block.data)}\n")
    for name, array in mesh.point_data.items():
        out.write(f"point_data {name} {shape(array)} {array.dtype} {values(array)}\n")
    for name, blocks in mesh.cell_data.items():
        for block_index, array in enumerate(blocks):
            out.write(f"cell_data {name} {block_index} {shape(array)} {array.dtype} {values(array)}\n")
)PY";
  const std::string command = "/usr/bin/python3 '" + script_path + "' '" + vtu_path + "' '" +
                              summary_path + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << "meshio failed to read " << vtu_path;
  const auto lines = read_token_lines(summary_path);

  const auto& points = line_starting_with(lines, {"points"});
  EXPECT_EQ(points[1], "5x3");
  EXPECT_EQ(points[2], "float64");
  expect_same_values(parse_doubles(points, 3), Eigen::MatrixXd(data.points), "points");

  const auto& tets = line_starting_with(lines, {"cells", "0"});
  EXPECT_EQ(tets[2], "tetra");
  EXPECT_EQ(tets[3], "2x4");
  EXPECT_EQ(std::vector<std::string>(tets.begin() + 4, tets.end()),
            (std::vector<std::string>{"0", "1", "2", "3", "1", "2", "3", "4"}));
  const auto& triangles = line_starting_with(lines, {"cells", "1"});
  EXPECT_EQ(triangles[2], "triangle");
  EXPECT_EQ(triangles[3], "2x3");
  EXPECT_EQ(std::vector<std::string>(triangles.begin() + 4, triangles.end()),
            (std::vector<std::string>{"0", "2", "1", "1", "2", "4"}));

  const auto& displacement = line_starting_with(lines, {"point_data", "displacement"});
  EXPECT_EQ(displacement[2], "5x3");
  expect_same_values(parse_doubles(displacement, 4), data.point_fields[0].values, "displacement");
  const auto& temperature = line_starting_with(lines, {"point_data", "temperature"});
  EXPECT_EQ(temperature[2], "5x1");  // NumberOfComponents="1" is written for scalars too
  expect_same_values(parse_doubles(temperature, 4), data.point_fields[1].values, "temperature");

  for (const int block : {0, 1}) {
    const std::string block_text = std::to_string(block);
    const auto& stress = line_starting_with(lines, {"cell_data", "stress", block_text});
    EXPECT_EQ(stress[3], "2x9");
    expect_same_values(parse_doubles(stress, 5), data.cell_fields[0].values.middleRows(2 * block, 2),
                       "stress block " + block_text);
    const auto& volume = line_starting_with(lines, {"cell_data", "volume", block_text});
    expect_same_values(parse_doubles(volume, 5), data.cell_fields[1].values.middleRows(2 * block, 2),
                       "volume block " + block_text);
    const auto& region = line_starting_with(lines, {"cell_data", "region", block_text});
    EXPECT_EQ(region[3], "2x1");
    EXPECT_EQ(region[4], "int32");
    expect_same_values(parse_doubles(region, 5),
                       data.int_cell_fields[0].second.cast<double>().middleRows(2 * block, 2),
                       "region block " + block_text);
  }
}

// ----- PVD -----------------------------------------------------------------------------------

struct PvdEntry {
  std::string timestep;
  std::string file;
};

/// Checks the collection's frame and returns its DataSet entries in document order.
std::vector<PvdEntry> read_pvd(const std::string& path) {
  const std::string xml = read_text(path);
  EXPECT_EQ(xml.rfind("<?xml", 0), 0u);
  EXPECT_NE(xml.find("<VTKFile type=\"Collection\" version=\"0.1\""), std::string::npos);
  const std::size_t open = xml.find("<Collection>");
  const std::size_t close = xml.find("</Collection>");
  EXPECT_NE(open, std::string::npos);
  EXPECT_NE(close, std::string::npos);
  EXPECT_LT(open, close);
  EXPECT_NE(xml.find("</VTKFile>", close), std::string::npos);
  std::vector<PvdEntry> entries;
  std::size_t position = open;
  while ((position = xml.find("<DataSet", position)) != std::string::npos && position < close) {
    const std::size_t end = xml.find("/>", position);
    const auto attributes = scan_attributes(xml.substr(position, end - position));
    EXPECT_EQ(attributes.at("group"), "");
    EXPECT_EQ(attributes.at("part"), "0");
    entries.push_back({attributes.at("timestep"), attributes.at("file")});
    position = end;
  }
  return entries;
}

TEST(Pvd, WellFormedAfterEveryAddWithPathsRelativeToThePvd) {
  TempDir scratch;
  PvdSeries series(scratch.file("results/run.pvd"));
  EXPECT_EQ(series.path(), scratch.file("results/run.pvd"));

  series.add(0.0, scratch.file("results/frames/step_0000.vtu"));  // absolute
  auto entries = read_pvd(series.path());
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].timestep, "0");
  EXPECT_EQ(entries[0].file, "frames/step_0000.vtu");

  series.add(0.1, "frames/./step_0001.vtu");  // relative to the pvd's directory
  entries = read_pvd(series.path());
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1].timestep, "0.1");
  EXPECT_EQ(entries[1].file, "frames/step_0001.vtu");

  series.add(0.25, scratch.file("elsewhere/step_0002.vtu"));  // outside the pvd's directory
  entries = read_pvd(series.path());
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[2].timestep, "0.25");
  EXPECT_EQ(entries[2].file, "../elsewhere/step_0002.vtu");

  // The times read back exactly.
  EXPECT_EQ(std::strtod(entries[1].timestep.c_str(), nullptr), 0.1);
}

TEST(Pvd, TimesStayInOrder) {
  TempDir scratch;
  PvdSeries series(scratch.file("run.pvd"));
  series.add(1.0, "a.vtu");
  series.add(3.0, "c.vtu");
  series.add(2.0, "b.vtu");
  series.add(3.0, "d.vtu");  // equal times keep their order of addition
  const auto entries = read_pvd(series.path());
  ASSERT_EQ(entries.size(), 4u);
  std::vector<std::string> files;
  for (const auto& entry : entries) files.push_back(entry.file);
  EXPECT_EQ(files, (std::vector<std::string>{"a.vtu", "b.vtu", "c.vtu", "d.vtu"}));
  for (std::size_t i = 1; i < entries.size(); ++i) {
    EXPECT_LE(std::strtod(entries[i - 1].timestep.c_str(), nullptr),
              std::strtod(entries[i].timestep.c_str(), nullptr));
  }
}

TEST(Pvd, NonFiniteTimeOrEmptyPathIsAnError) {
  TempDir scratch;
  PvdSeries series(scratch.file("run.pvd"));
  EXPECT_THROW(series.add(std::numeric_limits<double>::quiet_NaN(), "a.vtu"), Error);
  EXPECT_THROW(series.add(std::numeric_limits<double>::infinity(), "a.vtu"), Error);
  EXPECT_THROW(series.add(0.0, ""), Error);
  EXPECT_FALSE(fs::exists(series.path()));
  EXPECT_THROW(PvdSeries(""), Error);
}

TEST(Pvd, FailedWriteDoesNotKeepTheEntry) {
  TempDir scratch;
  const std::string pvd_path = scratch.file("run.pvd");
  fs::create_directories(pvd_path + "/blocker");  // a non-empty directory where the pvd should go
  PvdSeries series(pvd_path);
  EXPECT_THROW(series.add(0.0, "a.vtu"), Error);
  fs::remove_all(pvd_path);
  series.add(1.0, "b.vtu");
  const auto entries = read_pvd(pvd_path);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].file, "b.vtu");
}

}  // namespace
}  // namespace sinew::io

namespace sinew::io {
namespace {

TEST(Pvd, RestoreRewritesTheCollectionAndLaterAddsGoOnFromIt) {
  TempDir scratch;
  PvdSeries first(scratch.file("run.pvd"));
  first.add(0.0, "a.vtu");
  first.add(1.0, "b.vtu");
  const auto kept = first.entries();
  first.add(2.0, "c.vtu");  // written after the checkpoint by a run that was then killed
  PvdSeries resumed(scratch.file("run.pvd"));
  resumed.restore(kept);
  ASSERT_EQ(read_pvd(resumed.path()).size(), 2u);  // at once, even with nothing more to add
  resumed.add(2.0, "c.vtu");
  std::vector<std::string> files;
  for (const auto& entry : read_pvd(resumed.path())) files.push_back(entry.file);
  EXPECT_EQ(files, (std::vector<std::string>{"a.vtu", "b.vtu", "c.vtu"}));
}

}  // namespace
}  // namespace sinew::io
