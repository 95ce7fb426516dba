#pragma once
/// @file app_test_support.hpp
/// Helpers of the command-line tests: running the real `sinew` executable (SINEW_BINARY) with
/// its standard output and error captured to files in a TempDir, and a small valid scene to
/// break in one place per test.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/temp_dir.hpp"

extern char** environ;

namespace sinew::app_test {

namespace fs = std::filesystem;

/// The repository (examples/, scripts/).
inline const fs::path kSource = SINEW_SOURCE_DIR;
using nlohmann::json;

using sinew::testing::read_text;
using sinew::testing::TempDir;
using sinew::testing::write_text;

/// `text` in single quotes for /bin/sh.
inline std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `program` with `arguments` (each quoted), standard output and error captured in files of
/// `directory`, and returns the exit code and both texts. `launcher`: words put before the
/// program (such as mpirun and its options), each quoted.
inline CommandResult run_program(const std::string& program, const std::vector<std::string>& arguments,
                                 const TempDir& directory, const std::vector<std::string>& launcher = {}) {
  static std::atomic<int> counter{0};
  const int n = counter++;
  const fs::path out_file = directory / ("stdout_" + std::to_string(n) + ".txt");
  const fs::path err_file = directory / ("stderr_" + std::to_string(n) + ".txt");
  std::string command;
  for (const auto& word : launcher) command += shell_quote(word) + " ";
  command += shell_quote(program);
  for (const auto& argument : arguments) command += " " + shell_quote(argument);
  command += " >" + shell_quote(out_file.string()) + " 2>" + shell_quote(err_file.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  if (status != -1 && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.out = read_text(out_file);
  result.err = read_text(err_file);
  return result;
}

/// run_program on SINEW_BINARY, the command under test.
inline CommandResult run_sinew(const std::vector<std::string>& arguments, const TempDir& directory,
                               const std::vector<std::string>& launcher = {}) {
  return run_program(SINEW_BINARY, arguments, directory, launcher);
}

/// When run_and_signal signals the run it started.
struct SignalPlan {
  int signal = SIGINT;
  /// Waited for first, unless empty: a file the run writes once it is where the signal should
  /// find it (a checkpoint, the output directory's lock).
  fs::path ready;
  std::chrono::milliseconds delay{0};  ///< then waited, counted from when `ready` exists
};

struct SignalledRun {
  int status = -1;         ///< wait status (-1: could not start)
  bool signalled = false;  ///< false when the run ended before the signal was sent
  fs::path log;            ///< its standard output and error
};

/// Starts `launcher` + SINEW_BINARY + `arguments` (standard output and error to a new file in
/// `directory`, standard input /dev/null), sends the signal as `plan` says unless the run ended
/// before, and waits for it. A launcher such as mpirun gets the signal and passes it on.
inline SignalledRun run_and_signal(const std::vector<std::string>& arguments, const TempDir& directory,
                                   const SignalPlan& plan, const std::vector<std::string>& launcher = {}) {
  static std::atomic<int> counter{0};
  SignalledRun run;
  run.log = directory / ("signalled_" + std::to_string(counter++) + ".txt");
  std::vector<std::string> words = launcher;
  words.emplace_back(SINEW_BINARY);
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, run.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return run;
  auto ended = [&] { return waitpid(pid, &run.status, WNOHANG) == pid; };
  while (!plan.ready.empty() && !fs::exists(plan.ready)) {
    if (ended()) return run;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto until = std::chrono::steady_clock::now() + plan.delay;
  while (std::chrono::steady_clock::now() < until) {
    if (ended()) return run;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(pid, plan.signal);
  run.signalled = true;
  waitpid(pid, &run.status, 0);
  return run;
}

/// `sinew run <scene> -o <output> --no-progress`.
inline CommandResult run_scene_file(const fs::path& scene, const fs::path& output, const TempDir& directory) {
  return run_sinew({"run", scene.string(), "-o", output.string(), "--no-progress"}, directory);
}

/// A small valid scene: a 10 mm Mooney-Rivlin cube (coarse generated mesh) on a fixed bottom
/// face, its top face pushed down 1 mm in 2 increments.
inline json small_block_scene() {
  return json::parse(R"({
    "name": "small-block",
    "units": "mm, N, MPa",
    "materials": {"rubber": {"law": "mooney-rivlin", "C1": 0.5, "C2": 0.1, "a": 2.0}},
    "bodies": [
      {"name": "block",
       "mesh": {"generate": {"element_size": 5.0,
         "parts": [{"region": "rubber", "shape": {"box": {"min": [0, 0, 0], "max": [10, 10, 10]}}}]}},
       "regions": {"rubber": {"material": "rubber", "density": 1e-6}}}
    ],
    "boundary_conditions": [
      {"name": "bottom", "type": "fixed",
       "nodes": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1], "tolerance": 1e-6}}},
      {"name": "top", "type": "prescribed",
       "nodes": {"plane": {"point": [0, 0, 10], "normal": [0, 0, 1], "tolerance": 1e-6}},
       "motion": {"translation": [0, 0, -1]}}
    ],
    "solver": {"increments": 2},
    "output": {"vtu": true, "every": 1}
  })");
}

/// The CSV table at `path`: its lines split at commas (header first).
inline std::vector<std::vector<std::string>> read_csv_cells(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(path));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

/// A 48 kB tmpfs mounted on `path` while the object lives (a full disk for the tests of write
/// failures). mounted() is false where mounting is not allowed (not root, a sandbox): skip then.
class SmallTmpfs {
 public:
  explicit SmallTmpfs(fs::path path) : path_(std::move(path)) {
    fs::create_directories(path_);
    const std::string mount = "mount -t tmpfs -o size=48k tmpfs " + shell_quote(path_.string()) + " 2>/dev/null";
    mounted_ = ::geteuid() == 0 && std::system(mount.c_str()) == 0;
  }
  ~SmallTmpfs() {
    if (mounted_) std::system(("umount " + shell_quote(path_.string()) + " 2>/dev/null").c_str());
  }
  SmallTmpfs(const SmallTmpfs&) = delete;
  SmallTmpfs& operator=(const SmallTmpfs&) = delete;
  bool mounted() const { return mounted_; }

 private:
  fs::path path_;
  bool mounted_ = false;
};

/// Every regular file under `directory`, recursively, relative to it.
inline std::vector<std::string> files_under(const fs::path& directory) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(directory)) {
    files.push_back(fs::relative(entry.path(), directory).generic_string());
  }
  return files;
}

}  // namespace sinew::app_test
