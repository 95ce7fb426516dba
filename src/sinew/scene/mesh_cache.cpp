/// @file mesh_cache.cpp
/// Entries are CBOR (nlohmann::json): {"format", "key", "rest", "tets", "region",
/// "region_names", "node_sets", "face_sets"}, arrays flattened row by row.
#include "sinew/scene/mesh_cache.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "sinew/core/error.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/scene/build_surface_mesh.hpp"

namespace sinew::scene {
namespace {

using json = nlohmann::json;

/// Bumped whenever an entry's layout changes.
constexpr int kFormat = 1;
/// Larger entries are not read (a 3e6-tet mesh, the default limit, takes about 200 MB).
constexpr std::uintmax_t kMaxEntryBytes = std::uintmax_t{1} << 31;

/// 64-bit FNV-1a: a file name for the key, not a security boundary (the entry holds its key).
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = 14695981039346656037ull) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

/// Hash and size of a file's bytes, or nullopt when it cannot be read.
std::optional<std::string> file_fingerprint(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::uint64_t hash = 14695981039346656037ull;
  std::uintmax_t size = 0;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    hash = fnv1a(std::string_view(buffer.data(), n), hash);
    size += n;
  }
  if (in.bad()) return std::nullopt;
  return fmt::format("{:016x}:{}", hash, size);
}

std::string executable_identity() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "unknown executable";
  std::error_code size_ec, time_ec;
  const auto size = std::filesystem::file_size(self, size_ec);
  const auto time = std::filesystem::last_write_time(self, time_ec).time_since_epoch().count();
  return fmt::format("{} {} {}", self.string(), size_ec ? 0 : size, time_ec ? 0 : static_cast<long long>(time));
}

template <class Matrix>
json flat(const Matrix& m) {
  return json(std::vector<typename Matrix::Scalar>(m.data(), m.data() + m.size()));
}

template <class Matrix>
Matrix unflat(const json& values, Eigen::Index cols) {
  const auto v = values.get<std::vector<typename Matrix::Scalar>>();
  if (v.size() % static_cast<std::size_t>(cols) != 0) throw std::runtime_error("an array's length is not a multiple of its rows");
  Matrix m(static_cast<Eigen::Index>(v.size()) / cols, cols);
  std::copy(v.begin(), v.end(), m.data());
  return m;
}

}  // namespace

std::optional<std::string> mesh_cache_key(const MeshSourceConfig& mesh, const std::string& data_directory) {
  std::string key = fmt::format("sinew mesh cache {}\nexecutable {}\nmesh {}\n", kFormat, executable_identity(), mesh.cache_key);
  if (mesh.surfaces) {
    key += fmt::format("element size {:a}\n", mesh.surfaces->options.element_size);
    for (const auto& [name, file] : mesh.surfaces->surfaces) {
      const auto fingerprint = file_fingerprint(surface_file_path(file, data_directory));
      if (!fingerprint) return std::nullopt;
      key += fmt::format("surface {} {}\n", name, *fingerprint);
    }
  } else {
    key += fmt::format("element size {:a}\n", mesh.generate.element_size);
  }
  return key;
}

std::string mesh_cache_file(const std::string& directory, const std::string& key) {
  return (std::filesystem::path(directory) / fmt::format("{:016x}.sinew-mesh", fnv1a(key))).string();
}

std::optional<mesh::TetMesh> read_cached_mesh(const std::string& file, const std::string& key, std::string& problem) {
  problem.clear();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec || !std::filesystem::is_regular_file(file, ec)) {
    problem = "not a regular file";
    return std::nullopt;
  }
  if (size > kMaxEntryBytes) {
    problem = fmt::format("{} bytes, more than a cache entry can hold", size);
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && in.fail()) {
    problem = "unreadable";
    return std::nullopt;
  }
  mesh::TetMesh mesh;
  try {
    const json entry = json::from_cbor(bytes);
    if (!entry.is_object() || entry.value("format", 0) != kFormat) {
      problem = "not a sinew mesh cache entry of format " + std::to_string(kFormat);
      return std::nullopt;
    }
    if (entry.at("key").get<std::string>() != key) {
      problem = "it holds the mesh of another key (a hash collision)";
      return std::nullopt;
    }
    mesh.rest = unflat<Positions>(entry.at("rest"), 3);
    mesh.tets = unflat<Tets>(entry.at("tets"), 4);
    mesh.region = unflat<IndexVector>(entry.at("region"), 1);
    mesh.region_names = entry.at("region_names").get<std::vector<std::string>>();
    for (const auto& [name, nodes] : entry.at("node_sets").items()) mesh.node_sets[name] = nodes.get<std::vector<Index>>();
    for (const auto& [name, faces] : entry.at("face_sets").items()) mesh.face_sets[name] = unflat<Triangles>(faces, 3);
  } catch (const std::exception& e) {
    problem = std::string("unreadable entry: ") + e.what();
    return std::nullopt;
  }
  if (mesh.region.size() != mesh.tets.rows()) {
    problem = "its region list does not match its tets";
    return std::nullopt;
  }
  for (Index r = 0; r < mesh.region.size(); ++r) {
    if (mesh.region[r] < 0 || static_cast<std::size_t>(mesh.region[r]) >= mesh.region_names.size()) {
      problem = "a tet's region is out of range";
      return std::nullopt;
    }
  }
  for (const auto& [name, nodes] : mesh.node_sets) {
    for (const Index v : nodes) {
      if (v < 0 || v >= mesh.num_nodes()) {
        problem = "node set \"" + name + "\" has a node out of range";
        return std::nullopt;
      }
    }
  }
  for (const auto& [name, faces] : mesh.face_sets) {
    if ((faces.array() < 0).any() || (faces.array() >= mesh.num_nodes()).any()) {
      problem = "face set \"" + name + "\" has a node out of range";
      return std::nullopt;
    }
  }
  try {
    // What every mesher guarantees; not a manifold boundary, which the surface mesher does not.
    mesh::validate(mesh, file, mesh::ValidationOptions{.check_boundary_manifold = false});
  } catch (const InputError& e) {
    problem = e.what();
    return std::nullopt;
  }
  return mesh;
}

void write_cached_mesh(const std::string& file, const std::string& key, const mesh::TetMesh& mesh) {
  json entry;
  entry["format"] = kFormat;
  entry["key"] = key;
  entry["rest"] = flat(mesh.rest);
  entry["tets"] = flat(mesh.tets);
  entry["region"] = flat(mesh.region);
  entry["region_names"] = mesh.region_names;
  entry["node_sets"] = json::object();
  for (const auto& [name, nodes] : mesh.node_sets) entry["node_sets"][name] = nodes;
  entry["face_sets"] = json::object();
  for (const auto& [name, faces] : mesh.face_sets) entry["face_sets"][name] = flat(faces);
  const std::vector<std::uint8_t> bytes = json::to_cbor(entry);
  io::write_file_atomically(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace sinew::scene
