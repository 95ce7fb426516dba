#pragma once
/// @file mpi_test_support.hpp
/// Helpers of the tests that run sinew under mpirun (test_cli_mpi*.cpp): the launcher's words,
/// a table comparison at a column's scale, and the fixture that runs a scene on one process and
/// on N ranks and compares the runs.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "app_test_support.hpp"

namespace sinew::app_test {

/// mpirun with N ranks, allowed as root and on more ranks than cores (N = 4 on 2 cores).
inline std::vector<std::string> mpirun(int ranks) {
  std::vector<std::string> words;
#ifdef SINEW_SANITIZER_BUILD
  // OpenMPI's PMIx progress thread leaves 32 bytes in a plugin it unloads at MPI_Finalize: a leak
  // LeakSanitizer cannot attribute (an unknown module) and so cannot suppress. The ranks run
  // without leak checking; the code they run is leak-checked in the one-process tests.
  words = {"env", "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1"};
#endif
  for (const char* word : {"mpirun", "--allow-run-as-root", "--oversubscribe", "-n"}) words.emplace_back(word);
  words.push_back(std::to_string(ranks));
  return words;
}

/// `launcher` run under `timeout` (120 s; 400 s instrumented; exit code 124 if it hangs).
inline std::vector<std::string> with_timeout(std::vector<std::string> launcher) {
#ifdef SINEW_SANITIZER_BUILD
  // Instrumented ranks on a loaded 2-core machine: a resumed 0.4 s of block-on-incline took over
  // 120 s there. The suite's per-test limit (600 s) still bounds the whole test.
  launcher.insert(launcher.begin(), {"timeout", "400"});
#else
  launcher.insert(launcher.begin(), {"timeout", "120"});
#endif
  return launcher;
}

inline bool have_mpirun() { return std::system("command -v mpirun >/dev/null 2>&1") == 0; }

/// True for a column of forces or moments (a body's or a contact's reaction: `name.fx` ...
/// `name.mz`, `name.force`).
inline bool is_reaction_column(const std::string& column) {
  for (const char* suffix : {".fx", ".fy", ".fz", ".mx", ".my", ".mz", ".force"}) {
    const std::string s(suffix);
    if (column.size() > s.size() && column.compare(column.size() - s.size(), s.size(), s) == 0) return true;
  }
  return false;
}

/// Every numeric column of `actual` equals `expected`'s to `relative` of the column's largest
/// magnitude; text cells are equal. Reactions are compared at the scale of the table's largest
/// reaction: one that is zero up to round-off (a symmetry plane's moment) is round-off of the
/// forces that are not. `iterations_allowed`: how many Newton iterations a row's
/// `newton_iterations` may differ by.
inline void expect_same_table(const fs::path& expected, const fs::path& actual, double relative,
                              int iterations_allowed = 0) {
  SCOPED_TRACE(actual.string());
  const auto a = read_csv_cells(expected), b = read_csv_cells(actual);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.front(), b.front());
  double reaction_scale = 0;
  for (std::size_t j = 0; j < a.front().size(); ++j)
    if (is_reaction_column(a.front()[j]))
      for (std::size_t i = 1; i < a.size(); ++i)
        if (j < a[i].size()) reaction_scale = std::max(reaction_scale, std::abs(std::strtod(a[i][j].c_str(), nullptr)));
  for (std::size_t j = 0; j < a.front().size(); ++j) {
    double scale = 0;
    std::vector<std::pair<double, double>> values;
    for (std::size_t i = 1; i < a.size(); ++i) {
      ASSERT_EQ(a[i].size(), b[i].size()) << "row " << i;
      char* end_a = nullptr;
      char* end_b = nullptr;
      const double x = std::strtod(a[i][j].c_str(), &end_a), y = std::strtod(b[i][j].c_str(), &end_b);
      if (*end_a != '\0' || *end_b != '\0') {
        EXPECT_EQ(a[i][j], b[i][j]) << "row " << i << ", column " << a.front()[j];
        continue;
      }
      scale = std::max({scale, std::abs(x), std::abs(y)});
      values.emplace_back(x, y);
    }
    const std::string& column = a.front()[j];
    if (is_reaction_column(column)) scale = std::max(scale, reaction_scale);
    // Converged residuals are round-off themselves: compared at the tolerance they met.
    const double floor = column == "residual"            ? 1e-8
                         : column == "newton_iterations" ? iterations_allowed + 1e-12
                                                         : 1e-12;
    for (std::size_t i = 0; i < values.size(); ++i)
      EXPECT_LE(std::abs(values[i].first - values[i].second), relative * scale + floor)
          << "row " << i + 1 << ", column " << column << ": " << values[i].first << " against "
          << values[i].second;
  }
}

/// How closely expect_same_runs asks the runs to agree.
struct SameRunsOptions {
  /// On a long path round-off may decide whether a step's residual meets the tolerance an
  /// iteration earlier or later; then a step may take up to two Newton iterations more or less and
  /// the run 1 % more or less in all, while everything else still agrees to 1e-6.
  bool iterations_may_differ = false;
};

class Mpi : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_mpirun()) GTEST_SKIP() << "mpirun is not installed";
  }

  /// Runs `scene` on one process and on each of `ranks`, and compares every run with the first.
  void expect_same_runs(const json& scene, std::initializer_list<int> ranks, const SameRunsOptions& options = {}) {
    const fs::path base = directory / ("case" + std::to_string(cases_++));
    fs::create_directories(base);
    const fs::path scene_path = base / "scene.json";
    write_text(scene_path, scene.dump(2));
    const fs::path serial = base / "serial";
    const CommandResult one = run_sinew({"run", scene_path.string(), "-o", serial.string(), "--no-progress", "-j", "1"},
                                        directory);
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const json reference = json::parse(read_text(serial / "summary.json"));
    for (const int n : ranks) {
#ifdef SINEW_SANITIZER_BUILD
      if (n != *ranks.begin()) continue;  // the sanitizer build, four times slower, tries the first count
#endif
      SCOPED_TRACE(std::to_string(n) + " ranks");
      const fs::path output = base / ("ranks" + std::to_string(n));
      const CommandResult many = run_sinew(
          {"run", scene_path.string(), "-o", output.string(), "--no-progress", "-j", "1"}, directory, mpirun(n));
      ASSERT_EQ(many.exit_code, 0) << many.err;
      last_ranks_log = many.err;
      // Rank 0 logs; the others are silent (one "solved" line, not N).
      const auto solved_lines = [](const std::string& text) {
        std::size_t count = 0;
        for (std::size_t at = text.find("solved:"); at != std::string::npos; at = text.find("solved:", at + 1)) ++count;
        return count;
      };
      EXPECT_EQ(solved_lines(many.err), 1u) << many.err;
      const json summary = json::parse(read_text(output / "summary.json"));
      for (const char* key : {"status", "steps", "newton_iterations", "step_cuts", "dofs", "tets"}) {
        if (!reference.contains(key)) continue;
        if (options.iterations_may_differ && std::string(key) == "newton_iterations") {
          EXPECT_NEAR(summary.at(key).get<double>(), reference.at(key).get<double>(),
                      std::max(1.0, 0.01 * reference.at(key).get<double>()));
          continue;
        }
        EXPECT_EQ(summary.at(key), reference.at(key)) << key;
      }
      expect_same_table(serial / "steps.csv", output / "steps.csv", 1e-6, options.iterations_may_differ ? 2 : 0);
      if (fs::exists(serial / "rigid_bodies.csv")) {
        expect_same_table(serial / "rigid_bodies.csv", output / "rigid_bodies.csv", 1e-6);
      }
      expect_parallel_vtu_sets(serial, output, n);
    }
  }

  /// The files of `serial` outside vtu/ are in `output` too, and each vtu/X.vtu of the serial
  /// run is, in `output` (a run on `n` ranks), a parallel set vtu/X.pvtu of pieces vtu/X_p<r>.vtu
  /// whose cells add up to the serial file's; sinew.pvd lists the sets.
  static void expect_parallel_vtu_sets(const fs::path& serial, const fs::path& output, int n) {
    std::size_t serial_files = 0, datasets = 0;
    for (const std::string& file : files_under(serial)) {
      const fs::path path(file);
      if (path.parent_path() != "vtu") {
        if (file != "vtu") {
          ++serial_files;
          EXPECT_TRUE(fs::exists(output / path)) << file;
        }
        continue;
      }
      ++datasets;
      const std::string stem = (path.parent_path() / path.stem()).generic_string();
      const std::string set = read_text(output / (stem + ".pvtu"));
      const auto cells = [](const std::string& vtu) {
        const std::size_t at = vtu.find("NumberOfCells=\"");
        return at == std::string::npos ? -1L : std::stol(vtu.substr(at + 15));
      };
      long piece_cells = 0;
      for (int r = 0; r < n; ++r) {
        const std::string piece = path.stem().string() + "_p" + std::to_string(r) + ".vtu";
        EXPECT_NE(set.find("Source=\"" + piece + "\""), std::string::npos) << stem << ".pvtu lacks " << piece;
        piece_cells += cells(read_text(output / "vtu" / piece));
      }
      EXPECT_EQ(piece_cells, cells(read_text(serial / path))) << stem;
      EXPECT_NE(read_text(output / "sinew.pvd").find(stem + ".pvtu"), std::string::npos) << stem;
    }
    // n pieces and a .pvtu per dataset, plus the vtu folder itself when there is one.
    EXPECT_EQ(files_under(output).size(), serial_files + datasets * (n + 1) + (datasets > 0 ? 1 : 0));
  }

  TempDir directory;
  std::string last_ranks_log;  ///< rank 0's log (standard error) of expect_same_runs' last run on ranks
  int cases_ = 0;
};

/// The example `name` with its linear solver replaced (`solver`: "" keeps it).
inline json example(const std::string& name, const std::string& solver = "") {
  json scene = json::parse(read_text(kSource / "examples" / (name + ".json")));
  if (!solver.empty()) scene["solver"]["linear"]["solver"] = solver;
  if (solver == "petsc-gamg") scene["solver"]["linear"]["tolerance"] = 1e-10;
  return scene;
}

}  // namespace sinew::app_test
