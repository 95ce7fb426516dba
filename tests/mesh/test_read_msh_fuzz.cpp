/// @file test_read_msh_fuzz.cpp
/// Seeded, bounded fuzzing of read_msh: small valid .msh files (ASCII and binary 2.2 and 4.1,
/// ASCII 4.0, two of them with $NodeData) are damaged by byte flips, truncation, line deletion
/// and duplication, numbers replaced
/// by huge, negative or non-finite values, and removed sections. Every case must return a mesh
/// that passes validate() or throw sinew::InputError; any other exception fails the test (and a
/// crash or hang shows as one).

#include <gmsh.h>
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/gmsh_session.hpp"
#include "sinew/mesh/read_msh.hpp"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SINEW_FUZZ_UNDER_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define SINEW_FUZZ_UNDER_SANITIZER 1
#endif

namespace sinew::mesh {
namespace {

#ifdef SINEW_FUZZ_UNDER_SANITIZER
constexpr int kCasesPerSeedFile = 30;  // the sanitizer build is several times slower
#else
constexpr int kCasesPerSeedFile = 60;
#endif

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// A coarse mesh of the unit cube with a volume group and a face group, saved as `path`; with
/// `node_data`, followed by a scalar and a vector $NodeData block.
void write_seed_file(const std::string& path, double version, bool binary, bool node_data) {
  GmshSession session;
  session.run("writing " + path, [&] {
    gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}, 1), "body");
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {1}, 2), "side");
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.7);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.7);
    gmsh::model::mesh::generate(3);
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::write(path);
    if (!node_data) return;
    std::string model;
    gmsh::model::getCurrent(model);
    std::vector<std::size_t> tags;
    std::vector<double> coordinates;
    std::vector<double> unused_parametric;
    gmsh::model::mesh::getNodes(tags, coordinates, unused_parametric);
    std::vector<double> height;
    for (std::size_t i = 0; i < tags.size(); ++i) height.push_back(coordinates[3 * i + 2]);
    gmsh::option::setNumber("PostProcessing.SaveMesh", 0);
    const int scalar = gmsh::view::add("height");
    gmsh::view::addHomogeneousModelData(scalar, 0, model, "NodeData", tags, height, 0.0, 1);
    gmsh::view::write(scalar, path, /*append=*/true);
    const int vector = gmsh::view::add("position");
    gmsh::view::addHomogeneousModelData(vector, 0, model, "NodeData", tags, coordinates, 0.0, 3);
    gmsh::view::write(vector, path, /*append=*/true);
  });
}

std::vector<std::string> split_lines(const std::string& bytes) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < bytes.size()) {
    const std::size_t end = bytes.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(bytes.substr(start));
      break;
    }
    lines.push_back(bytes.substr(start, end - start + 1));
    start = end + 1;
  }
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string bytes;
  for (const auto& line : lines) bytes += line;
  return bytes;
}

bool is_number_char(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
         c == 'e' || c == 'E';
}

/// Damages `bytes` in one of several ways; `what` says how.
class Mutator {
 public:
  explicit Mutator(unsigned seed) : random_(seed) {}

  std::string mutate(std::string bytes, std::string& what) {
    if (bytes.empty()) return bytes;
    switch (pick(7)) {
      case 0: {  // flip bits of a few bytes
        const std::size_t flips = 1 + pick(4);
        for (std::size_t i = 0; i < flips; ++i) {
          const std::size_t at = pick(bytes.size());
          bytes[at] = static_cast<char>(bytes[at] ^ (1 << pick(8)));
        }
        what = "flipped " + std::to_string(flips) + " bits";
        return bytes;
      }
      case 1: {
        const std::size_t length = pick(bytes.size());
        what = "truncated to " + std::to_string(length) + " bytes";
        return bytes.substr(0, length);
      }
      case 2:
      case 3: {
        auto lines = split_lines(bytes);
        const std::size_t at = pick(lines.size());
        if (pick(2) == 0) {
          what = "deleted line " + std::to_string(at + 1);
          lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at));
        } else {
          what = "duplicated line " + std::to_string(at + 1);
          lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), lines[at]);
        }
        return join_lines(lines);
      }
      case 4:
      case 5:
        return replace_number(bytes, what);
      default: {
        static const std::array<const char*, 6> kSections = {
            "MeshFormat", "PhysicalNames", "Entities", "Nodes", "Elements", "EndNodes"};
        const std::string name = kSections[pick(kSections.size())];
        const std::string open = "$" + name + "\n";
        const std::size_t start = bytes.find(open);
        if (start == std::string::npos) return replace_number(bytes, what);
        const std::string close = "$End" + name + "\n";
        const std::size_t end = bytes.find(close, start);
        what = "removed section $" + name;
        return bytes.erase(start, end == std::string::npos ? open.size() : end + close.size() - start);
      }
    }
  }

 private:
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_); }

  /// Replaces a textual number (or, half the time in a binary file, 4 or 8 raw bytes) with a
  /// huge, negative, zero or non-finite value.
  std::string replace_number(std::string bytes, std::string& what) {
    static const std::array<const char*, 12> kValues = {
        "1e400", "-1", "nan", "inf", "-inf", "0", "18446744073709551615", "99999999999999",
        "1000000000000000", "-2147483648", "2147483647", "1e-320"};
    const bool binary = bytes.find(" 1 8\n") != std::string::npos;
    if (binary && pick(2) == 0 && bytes.size() > 8) {
      const std::size_t at = pick(bytes.size() - 8);
      const std::array<std::uint64_t, 5> raw = {~std::uint64_t{0}, std::uint64_t{1} << 50,
                                                std::uint64_t{1} << 31, 0x7ff0000000000000ULL,
                                                0x7ff8000000000000ULL};
      const std::uint64_t value = raw[pick(raw.size())];
      const std::size_t width = pick(2) ? 8 : 4;
      std::memcpy(&bytes[at], &value, width);
      what = "overwrote " + std::to_string(width) + " bytes at " + std::to_string(at);
      return bytes;
    }
    // The start of some number token.
    std::vector<std::size_t> starts;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      if (is_number_char(bytes[i]) && (i == 0 || std::isspace(static_cast<unsigned char>(bytes[i - 1])))) {
        starts.push_back(i);
      }
    }
    if (starts.empty()) return bytes;
    const std::size_t start = starts[pick(starts.size())];
    std::size_t end = start;
    while (end < bytes.size() && is_number_char(bytes[end])) ++end;
    const std::string value = kValues[pick(kValues.size())];
    what = "replaced \"" + bytes.substr(start, end - start) + "\" at " + std::to_string(start) +
           " by " + value;
    return bytes.replace(start, end - start, value);
  }

  std::mt19937 random_;
};

TEST(ReadMshFuzz, DamagedFilesGiveAValidMeshOrAnInputError) {
  const testing::TempDir directory("sinew-msh-fuzz");
  struct Seed {
    std::string name;
    double version;
    bool binary;
    bool node_data;
  };
  const std::vector<Seed> seeds = {
      {"v22_ascii", 2.2, false, false},       {"v22_binary", 2.2, true, false},
      {"v40_ascii", 4.0, false, false},       {"v41_ascii", 4.1, false, false},
      {"v41_binary", 4.1, true, false},       {"v22_ascii_fields", 2.2, false, true},
      {"v41_binary_fields", 4.1, true, true}};
  // SINEW_FUZZ_SEED and SINEW_FUZZ_CASES (per seed file) explore further than the fixed run;
  // SINEW_FUZZ_VERBOSE prints every case and message; SINEW_FUZZ_KEEP=<text> saves the case
  // whose label contains <text> as "<text>.kept.msh".
  const char* seed_override = std::getenv("SINEW_FUZZ_SEED");
  const char* cases_override = std::getenv("SINEW_FUZZ_CASES");
  Mutator mutator(seed_override ? static_cast<unsigned>(std::stoul(seed_override)) : 18u);
  const int num_cases = cases_override ? std::stoi(cases_override) : kCasesPerSeedFile;
  const bool verbose = std::getenv("SINEW_FUZZ_VERBOSE") != nullptr;
  int returned = 0;
  int input_errors = 0;
  int other_errors = 0;
  for (const auto& seed : seeds) {
    const std::string seed_path = directory.file(seed.name + "_seed.msh");
    write_seed_file(seed_path, seed.version, seed.binary, seed.node_data);
    const std::string original = read_bytes(seed_path);
    ASSERT_GT(read_msh(seed_path).num_tets(), 0) << seed.name;
    const std::string path = directory.file("case.msh");
    for (int c = 0; c < num_cases; ++c) {
      std::string what;
      std::string bytes = mutator.mutate(original, what);
      if (c % 4 == 3) {  // a second mutation on every fourth case
        std::string more;
        bytes = mutator.mutate(bytes, more);
        what += ", then " + more;
      }
      write_bytes(path, bytes);
      const std::string label = seed.name + " case " + std::to_string(c) + ": " + what;
      if (verbose) std::cerr << label << std::endl;  // names the case a crash happens in
      try {
        const TetMesh mesh = read_msh(path);
        validate(mesh, label);
        ++returned;
      } catch (const InputError& error) {
        ++input_errors;
        if (verbose) std::cerr << "  " << error.what() << std::endl;
        const char* keep = std::getenv("SINEW_FUZZ_KEEP");
        if (keep && label.find(keep) != std::string::npos) write_bytes(keep + std::string(".kept.msh"), bytes);
      } catch (const std::exception& error) {
        ++other_errors;
        ADD_FAILURE() << label << ": " << typeid(error).name() << ": " << error.what();
      } catch (...) {
        ++other_errors;
        ADD_FAILURE() << label << ": a non-standard exception";
      }
    }
  }
  std::cout << "read_msh fuzz: " << returned << " valid meshes, " << input_errors
            << " InputErrors, " << other_errors << " other exceptions\n";
  EXPECT_EQ(other_errors, 0);
  EXPECT_GT(input_errors, 0);
}

}  // namespace
}  // namespace sinew::mesh
