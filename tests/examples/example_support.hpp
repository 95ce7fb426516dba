#pragma once
/// @file example_support.hpp
/// Helpers of the example regression tests: readers for the files a run writes (steps.csv,
/// sinew.pvd, the points and displacements of a .vtu; written here independently of the
/// writers) and a runner that solves an example scene through the library into a TempDir.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "run_scene.hpp"
#include "sinew/scene/load_scene.hpp"
#include "support/base64_decode.hpp"
#include "support/files.hpp"
#include "support/temp_dir.hpp"

namespace sinew::examples_test {

namespace fs = std::filesystem;

using sinew::testing::decode_base64;
using sinew::testing::read_text;
using sinew::testing::TempDir;

/// A CSV file of numbers with a header line (no quoted fields: steps.csv and newton.csv).
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  std::size_t index(const std::string& column) const {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == column) return i;
    }
    throw std::runtime_error("no column '" + column + "'");
  }
  double at(std::size_t row, const std::string& column) const { return rows.at(row).at(index(column)); }
  std::vector<double> column(const std::string& name) const {
    const std::size_t c = index(name);
    std::vector<double> values;
    for (const auto& row : rows) values.push_back(row.at(c));
    return values;
  }
  /// Largest value of a column (-inf for a table without rows).
  double column_max(const std::string& name) const {
    const std::size_t c = index(name);
    double largest = -std::numeric_limits<double>::infinity();
    for (const auto& row : rows) largest = std::max(largest, row.at(c));
    return largest;
  }
};

inline std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}

inline CsvTable read_csv(const fs::path& path) {
  std::istringstream in(read_text(path));
  CsvTable table;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path.string() + " is empty");
  table.columns = split_commas(line);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    for (const auto& field : split_commas(line)) row.push_back(std::stod(field));
    if (row.size() != table.columns.size()) {
      throw std::runtime_error(path.string() + ": a row has " + std::to_string(row.size()) + " fields, the header " +
                               std::to_string(table.columns.size()));
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

/// Only the named numeric columns of a CSV file whose other columns may hold text (no quoted
/// commas in the file), in the order given.
inline CsvTable read_csv_columns(const fs::path& path, const std::vector<std::string>& names) {
  std::istringstream in(read_text(path));
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path.string() + " is empty");
  CsvTable header;
  header.columns = split_commas(line);
  std::vector<std::size_t> picked;
  for (const auto& name : names) picked.push_back(header.index(name));
  CsvTable table;
  table.columns = names;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto fields = split_commas(line);
    std::vector<double> row;
    for (const std::size_t c : picked) row.push_back(std::stod(fields.at(c)));
    table.rows.push_back(std::move(row));
  }
  return table;
}

/// The value of attribute `name` in an XML start tag (the text from '<' to '>').
inline std::string xml_attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t start = tag.find(key);
  if (start == std::string::npos) throw std::runtime_error("no attribute " + name + " in " + tag);
  const std::size_t value = start + key.size();
  return tag.substr(value, tag.find('"', value) - value);
}

struct PvdEntry {
  double time = 0;
  std::string file;  ///< relative to the .pvd's directory
};

inline std::vector<PvdEntry> read_pvd(const fs::path& path) {
  const std::string xml = read_text(path);
  std::vector<PvdEntry> entries;
  std::size_t position = 0;
  while ((position = xml.find("<DataSet", position)) != std::string::npos) {
    const std::size_t end = xml.find('>', position);
    const std::string tag = xml.substr(position, end - position + 1);
    entries.push_back({std::stod(xml_attribute(tag, "timestep")), xml_attribute(tag, "file")});
    position = end;
  }
  return entries;
}

/// The Float64 DataArray named `name` with `components` components of a binary .vtu (UInt64
/// header), #entries x components.
inline Eigen::MatrixXd vtu_array(const std::string& xml, const std::string& name, int components = 1) {
  const std::size_t tag_start = xml.find("<DataArray type=\"Float64\" Name=\"" + name + "\"");
  if (tag_start == std::string::npos) throw std::runtime_error("no Float64 DataArray " + name);
  const std::size_t tag_end = xml.find('>', tag_start);
  const std::string tag = xml.substr(tag_start, tag_end - tag_start + 1);
  const std::string declared =
      tag.find(" NumberOfComponents=") == std::string::npos ? "" : xml_attribute(tag, "NumberOfComponents");
  if ((declared.empty() ? 1 : std::stoi(declared)) != components)
    throw std::runtime_error(name + " does not have " + std::to_string(components) + " components");
  std::string text = xml.substr(tag_end + 1, xml.find("</DataArray>", tag_end) - tag_end - 1);
  text.erase(0, text.find_first_not_of(" \n\t"));
  text.erase(text.find_last_not_of(" \n\t") + 1);
  const std::string bytes = decode_base64(text);
  std::uint64_t count = 0;
  if (bytes.size() < 8) throw std::runtime_error(name + ": shorter than its header");
  std::memcpy(&count, bytes.data(), 8);
  const auto row_bytes = static_cast<std::uint64_t>(8 * components);
  if (count != bytes.size() - 8 || count % row_bytes != 0) throw std::runtime_error(name + ": bad byte count");
  const auto rows = static_cast<Eigen::Index>(count / row_bytes);
  Eigen::MatrixXd values(rows, components);
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (int c = 0; c < components; ++c) {
      double v = 0;
      std::memcpy(&v, bytes.data() + 8 + 8 * (components * r + c), 8);
      values(r, c) = v;
    }
  }
  return values;
}

/// The Float64, 3-component DataArray named `name`, #points x 3.
inline Eigen::MatrixXd vtu_vector_array(const std::string& xml, const std::string& name) {
  return vtu_array(xml, name, 3);
}

/// Current positions and displacements of a .vtu written by a run; rest = x - u.
struct VtuState {
  Eigen::MatrixXd x;
  Eigen::MatrixXd u;
  Eigen::MatrixXd rest() const { return x - u; }
};

inline VtuState read_vtu_state(const fs::path& path) {
  const std::string xml = read_text(path);
  return {vtu_vector_array(xml, "Points"), vtu_vector_array(xml, "displacement")};
}

struct ExampleRun {
  scene::SceneConfig config;
  app::RunReport report;
  double seconds = 0;
  fs::path output;
};

inline fs::path example_path(const std::string& name) {
  return fs::path(SINEW_SOURCE_DIR) / "examples" / (name + ".json");
}

/// Runs `config` through the library into `<directory>/<subdirectory>`.
inline ExampleRun run_config(scene::SceneConfig config, const TempDir& directory, const std::string& name,
                             const std::string& subdirectory = "out") {
  ExampleRun run;
  run.config = std::move(config);
  run.output = directory.path() / subdirectory;
  app::RunOptions options;
  options.output_directory = run.output.string();
  options.progress_bar = false;
  options.log_steps = false;
  const auto start = std::chrono::steady_clock::now();
  run.report = app::run_scene(run.config, options);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ example  ] %s: %.2f s, %s\n", name.c_str(), run.seconds, run.report.message.c_str());
  ::testing::Test::RecordProperty("seconds", std::to_string(run.seconds));
  return run;
}

/// Loads examples/<name>.json and runs it through the library into `<directory>/out`.
inline ExampleRun run_example(const std::string& name, const TempDir& directory) {
  return run_config(scene::load_scene_file(example_path(name).string()), directory, name);
}

/// examples/falling-rods.json reduced for the suite: 2 of its 5 rows, 3 of its 7 columns (the
/// rods over the middle of the bar) and the first 0.5 s, with an output every 0.1 s.
inline scene::SceneConfig reduced_falling_rods() {
  scene::SceneConfig config = scene::load_scene_file(example_path("falling-rods").string());
  auto& rods = config.bodies.at(0).mesh.parts.at(0).shape.children;
  if (config.bodies.at(0).name != "rods" || rods.size() != 35u)
    throw std::runtime_error("examples/falling-rods.json: expected a body \"rods\" of 7 x 5 rods");
  std::vector<mesh::Shape> kept;
  for (int row = 0; row < 2; ++row)
    for (int column = 2; column < 5; ++column) kept.push_back(rods.at(static_cast<std::size_t>(7 * row + column)));
  rods = kept;
  config.dynamics.options.end_time = 0.5;
  config.dynamics.options.output_interval = 0.1;
  return config;
}

/// What every successful run writes: a .pvd listing increment 0 (the rest state) and every
/// increment with an existing .vtu each, steps.csv with one row per accepted step (lambda
/// ending at 1), newton.csv, and summary.json saying success; no last_converged.vtu.
inline void expect_complete_outputs(const ExampleRun& run) {
  ASSERT_TRUE(run.report.success) << run.report.message;
  const int increments = run.config.solver.stepping.increments;
  for (const char* file : {"sinew.pvd", "steps.csv", "newton.csv", "summary.json"}) {
    EXPECT_TRUE(fs::is_regular_file(run.output / file)) << file;
  }
  EXPECT_FALSE(fs::exists(run.output / "last_converged.vtu"));

  const auto pvd = read_pvd(run.output / "sinew.pvd");
  ASSERT_EQ(pvd.size(), static_cast<std::size_t>(increments + 1)) << "the .pvd lists increments 0.." << increments;
  for (int k = 0; k <= increments; ++k) {
    char expected_file[64];
    std::snprintf(expected_file, sizeof(expected_file), "vtu/increment_%04d.vtu", k);
    EXPECT_EQ(pvd[k].file, expected_file);
    EXPECT_NEAR(pvd[k].time, static_cast<double>(k) / increments, 1e-12) << expected_file;
    EXPECT_TRUE(fs::is_regular_file(run.output / pvd[k].file)) << pvd[k].file;
  }

  const auto steps = read_csv(run.output / "steps.csv");
  ASSERT_EQ(steps.rows.size(), static_cast<std::size_t>(run.report.result.steps));
  ASSERT_FALSE(steps.rows.empty());
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    EXPECT_EQ(steps.at(i, "step"), static_cast<double>(i + 1));
    if (i > 0) {
      EXPECT_GT(steps.at(i, "lambda"), steps.at(i - 1, "lambda")) << "row " << i;
    }
  }
  EXPECT_NEAR(steps.rows.back()[steps.index("lambda")], 1.0, 1e-12);
  EXPECT_EQ(steps.rows.back()[steps.index("increment")], static_cast<double>(increments));

  const auto summary = nlohmann::json::parse(read_text(run.output / "summary.json"));
  EXPECT_EQ(summary.at("success"), true);
  EXPECT_EQ(summary.at("scene"), run.config.name);
  EXPECT_EQ(summary.at("steps"), run.report.result.steps);
  EXPECT_EQ(summary.at("increments_completed"), increments);
  EXPECT_DOUBLE_EQ(summary.at("lambda_reached").get<double>(), 1.0);
}

/// The row of `steps` whose lambda is `lambda` (within 1e-9), or -1.
inline int row_at_lambda(const CsvTable& steps, double lambda) {
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    if (std::abs(steps.at(i, "lambda") - lambda) < 1e-9) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace sinew::examples_test
