/// @file test_cli_fuzz.cpp
/// A seeded, bounded fuzzer of the command: mutated scenes (values out of range or of the
/// wrong type, huge and tiny numbers, integers past 2^31, deleted and duplicated keys, deep
/// nesting, NUL bytes, truncated and bit-flipped text) through `sinew validate`, and mutated
/// physical values through a small `sinew run`. It fails on any signal (a crash, an abort, a
/// sanitizer report), a hang past its bound, or an exit code outside the documented ones.
///
/// CI runs a short, fixed-seed set; scripts/fuzz-soak.sh runs a long one. Environment:
///   SINEW_FUZZ_SEED        seed (default 18)
///   SINEW_FUZZ_VALIDATE    number of validate cases (default 120; 60 under the sanitizers)
///   SINEW_FUZZ_RUN         number of run cases (default 16; 6 under the sanitizers)
///   SINEW_FUZZ_BINARY      the sinew to test (default: this build's)
///   SINEW_FUZZ_KEEP        a directory to keep every failing case in

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "app/app_test_support.hpp"

namespace sinew::app_test {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kDefaultValidateCases = 60;
constexpr int kDefaultRunCases = 6;
constexpr int kCaseSeconds = 120;
#else
constexpr int kDefaultValidateCases = 120;
constexpr int kDefaultRunCases = 16;
constexpr int kCaseSeconds = 40;
#endif

int env_int(const char* name, int fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::atoi(value) : fallback;
}

std::string env_string(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : fallback;
}

/// The bases: small scenes of every kind (generated meshes made coarse so a case takes
/// a fraction of a second).
std::vector<json> base_scenes() {
  const fs::path examples = fs::path(SINEW_SOURCE_DIR) / "examples";
  std::vector<json> scenes{small_block_scene()};
  for (const char* name : {"uniaxial-mooney-rivlin", "twisted-cylinder", "stacked-blocks", "hertz-ball", "ball-drop"})
    scenes.push_back(json::parse(read_text(examples / (std::string(name) + ".json"))));
  for (json& scene : scenes) {
    for (json& body : scene["bodies"])
      if (body["mesh"].contains("generate")) {
        json& size = body["mesh"]["generate"]["element_size"];
        size = size.get<double>() * 2;
      }
    if (scene.contains("dynamics")) scene["dynamics"]["end_time"] = 0.02;
  }
  return scenes;
}

/// Pointers to every value of `j` (depth first), with their JSON paths.
void collect(json& j, const std::string& path, std::vector<std::pair<std::string, json*>>& out) {
  out.emplace_back(path, &j);
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) collect(it.value(), path + "/" + it.key(), out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collect(j[i], path + "/" + std::to_string(i), out);
  }
}

/// A string value "<kNestMarker><depth>" in a mutated scene stands for `depth` nested arrays.
constexpr const char* kNestMarker = "sinew-fuzz-nest-";

/// `text` with every quoted nesting marker replaced by its nested arrays "[[...[0]...]]".
std::string nested_text(std::string text) {
  const std::string opening = std::string("\"") + kNestMarker;
  for (auto at = text.find(opening); at != std::string::npos; at = text.find(opening, at)) {
    const auto end = text.find('"', at + 1);
    const int depth = std::stoi(text.substr(at + opening.size(), end - at - opening.size()));
    text.replace(at, end + 1 - at, std::string(static_cast<std::size_t>(depth), '[') + "0" +
                                       std::string(static_cast<std::size_t>(depth), ']'));
    at += 2 * static_cast<std::size_t>(depth) + 1;
  }
  return text;
}

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_); }

  /// One structural mutation of a value somewhere in `scene`.
  void mutate_value(json& scene) {
    std::vector<std::pair<std::string, json*>> values;
    collect(scene, "", values);
    json& target = *values[pick(values.size())].second;
    static const std::vector<json> numbers{0,      -1,        1e300,         -1e300,     1e-300, 2147483648.0,
                                           4294967296.0, -2147483649.0, 1e19,   1e30,   0.5,    1e9,
                                           -0.0,   1e-12,     3,             1e6,        -1e-9};
    static const std::vector<json> others{"x", nullptr, true, json::array(), json::object(), "nan", "inf",
                                          std::string("a\0b", 3), std::string(5000, 'n'), "", "*", "bodies"};
    switch (pick(8)) {
      case 0: case 1: case 2:
        target = numbers[pick(numbers.size())];
        break;
      case 3:
        target = others[pick(others.size())];
        break;
      case 4:  // delete a key or an element
        if (target.is_object() && !target.empty()) {
          auto it = target.begin();
          std::advance(it, static_cast<long>(pick(target.size())));
          target.erase(it);
        } else if (target.is_array() && !target.empty()) {
          target.erase(target.begin() + static_cast<long>(pick(target.size())));
        }
        break;
      case 5:  // duplicate an element (duplicate names, extra bodies or conditions)
        if (target.is_array() && !target.empty()) target.push_back(target[pick(target.size())]);
        break;
      case 6:  // nesting, shallow or deep: a marker that nested_text() expands after dumping
        // (a deep json value would overflow this test's own stack when dumped)
        target = std::string(kNestMarker) + (pick(2) == 0 ? "10" : "100000");
        break;
      default:  // a number scaled far
        if (target.is_number()) target = target.get<double>() * (pick(2) == 0 ? 1e12 : -1e-12);
        break;
    }
  }

  /// One textual mutation of `text`.
  void mutate_text(std::string& text) {
    if (text.empty()) return;
    switch (pick(4)) {
      case 0: text.resize(pick(text.size())); break;
      case 1: text[pick(text.size())] = static_cast<char>(pick(256)); break;
      case 2: text.insert(pick(text.size()), std::string(pick(2) == 0 ? 200000 : 3, pick(2) == 0 ? '[' : '{')); break;
      default: text.erase(pick(text.size()), 1 + pick(40)); break;
    }
  }

  /// A physical value of the scene set far off (for runs, which must stay short: no counts,
  /// sizes or times are touched).
  void mutate_physics(json& scene) {
    std::vector<std::pair<std::string, json*>> values;
    collect(scene, "", values);
    std::vector<json*> physical;
    for (auto& [path, value] : values) {
      if (!value->is_number()) continue;
      for (const char* key : {"/C1", "/C2", "/a", "/b", "/density", "/gravity", "/translation", "/angle_deg",
                              "/penalty", "/contact_penalty_scale", "/total_force", "/mu", "/kappa"})
        if (path.find(key) != std::string::npos) physical.push_back(value);
    }
    if (physical.empty()) return;
    static const std::vector<double> values_far{0, -1, 1e300, 1e30, 1e-300, 1e12, -1e12, 360, 720, 1e-9};
    *physical[pick(physical.size())] = values_far[pick(values_far.size())];
  }

 private:
  std::mt19937_64 random_;
};

struct Outcomes {
  std::map<std::string, int> counts;  ///< "validate exit 1" -> cases
  std::vector<std::string> failures;
};

/// Runs `arguments` under a time bound and classifies the end: exit codes 0-5 are documented
/// (0, 1 for validate; 0, 1, 2 for a run of a valid scene: 3-5 count as failures too).
void run_case(const std::string& binary, const std::string& kind, const std::vector<std::string>& arguments,
              const std::vector<int>& allowed, const TempDir& directory, const fs::path& scene,
              Outcomes& outcomes) {
  std::string command = "timeout -s KILL " + std::to_string(kCaseSeconds) + " " + shell_quote(binary);
  for (const auto& a : arguments) command += " " + shell_quote(a);
  command += " >" + shell_quote((directory / "out.txt").string()) + " 2>" +
             shell_quote((directory / "err.txt").string()) + " </dev/null";
  const int status = std::system(command.c_str());
  std::string outcome;
  bool failed = false;
  if (status == -1 || !WIFEXITED(status)) {
    outcome = "signal";
    failed = true;
  } else {
    const int code = WEXITSTATUS(status);
    if (code == 137) {
      outcome = "hang (> " + std::to_string(kCaseSeconds) + " s)";
    } else if (code >= 128) {
      outcome = "signal " + std::to_string(code - 128);
    } else {
      outcome = "exit " + std::to_string(code);
    }
    failed = std::find(allowed.begin(), allowed.end(), code) == allowed.end();
  }
  ++outcomes.counts[kind + " " + outcome];
  if (!failed) return;
  std::string err = read_text(directory / "err.txt");
  if (err.size() > 600) err = err.substr(0, 600) + "...";
  outcomes.failures.push_back(kind + " " + outcome + ": " + err);
  const std::string keep = env_string("SINEW_FUZZ_KEEP", "");
  if (!keep.empty()) {
    fs::create_directories(keep);
    fs::copy_file(scene, fs::path(keep) / (kind + "_" + std::to_string(outcomes.failures.size()) + ".json"),
                  fs::copy_options::overwrite_existing);
  }
}

void report(const Outcomes& outcomes, int seed) {
  std::string summary = "fuzz seed " + std::to_string(seed) + ":";
  for (const auto& [outcome, count] : outcomes.counts) summary += "\n  " + outcome + ": " + std::to_string(count);
  std::cout << summary << "\n";
  for (const auto& failure : outcomes.failures) ADD_FAILURE() << failure;
}

TEST(Fuzz, MutatedScenesThroughValidateNeverCrashOrHang) {
  const int seed = env_int("SINEW_FUZZ_SEED", 18);
  const int cases = env_int("SINEW_FUZZ_VALIDATE", kDefaultValidateCases);
  const std::string binary = env_string("SINEW_FUZZ_BINARY", SINEW_BINARY);
  const std::vector<json> bases = base_scenes();
  Mutator mutator(static_cast<std::uint64_t>(seed));
  TempDir directory;
  const fs::path scene_path = directory / "scene.json";
  Outcomes outcomes;
  for (int k = 0; k < cases; ++k) {
    json scene = bases[mutator.pick(bases.size())];
    const std::size_t mutations = 1 + mutator.pick(3);
    for (std::size_t m = 0; m < mutations; ++m) mutator.mutate_value(scene);
    std::string text = nested_text(scene.dump(1, ' ', false, json::error_handler_t::replace));
    if (mutator.pick(4) == 0) mutator.mutate_text(text);
    write_text(scene_path, text);
    run_case(binary, "validate", {"validate", scene_path.string()}, {0, 1}, directory, scene_path, outcomes);
  }
  report(outcomes, seed);
}

TEST(Fuzz, MutatedPhysicalValuesThroughRunNeverCrashOrHang) {
  const int seed = env_int("SINEW_FUZZ_SEED", 18);
  const int cases = env_int("SINEW_FUZZ_RUN", kDefaultRunCases);
  const std::string binary = env_string("SINEW_FUZZ_BINARY", SINEW_BINARY);
  std::vector<json> bases{small_block_scene()};
  json ball = base_scenes()[4];  // hertz-ball: contact
  ball["solver"]["increments"] = 2;
  bases.push_back(ball);
  Mutator mutator(static_cast<std::uint64_t>(seed) * 7919);
  TempDir directory;
  const fs::path scene_path = directory / "scene.json";
  Outcomes outcomes;
  for (int k = 0; k < cases; ++k) {
    json scene = bases[mutator.pick(bases.size())];
    scene["output"]["vtu"] = false;
    mutator.mutate_physics(scene);
    write_text(scene_path, scene.dump(1));
    const fs::path output = directory / ("out" + std::to_string(k));
    run_case(binary, "run", {"run", scene_path.string(), "-o", output.string(), "--no-progress", "-q"}, {0, 1, 2},
             directory, scene_path, outcomes);
  }
  report(outcomes, seed);
}

}  // namespace
}  // namespace sinew::app_test
