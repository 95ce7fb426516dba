#include "sinew/mesh/tet_mesh_bytes.hpp"

#include <cstdint>
#include <cstring>

#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::mesh {

namespace {

/// Appends counts, strings and the coefficients of Eigen matrices (row-major ones as stored).
class Writer {
 public:
  void count(std::size_t n) {
    const auto value = static_cast<std::uint64_t>(n);
    raw(&value, sizeof(value));
  }
  void text(const std::string& s) {
    count(s.size());
    raw(s.data(), s.size());
  }
  template <class Matrix>
  void matrix(const Matrix& m) {
    count(static_cast<std::size_t>(m.rows()));
    count(static_cast<std::size_t>(m.cols()));
    raw(m.data(), static_cast<std::size_t>(m.size()) * sizeof(typename Matrix::Scalar));
  }
  std::string bytes;

 private:
  void raw(const void* data, std::size_t size) { bytes.append(static_cast<const char*>(data), size); }
};

/// Reads what Writer wrote, checking each length against the bytes left.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  std::size_t count() {
    std::uint64_t value = 0;
    raw(&value, sizeof(value));
    if (value > bytes_.size()) fail("a count larger than the bytes");
    return static_cast<std::size_t>(value);
  }
  std::string text() {
    std::string s(count(), '\0');
    raw(s.data(), s.size());
    return s;
  }
  template <class Matrix>
  Matrix matrix() {
    const std::size_t rows = count(), cols = count();
    using Scalar = typename Matrix::Scalar;
    if (Matrix::ColsAtCompileTime != Eigen::Dynamic && cols != static_cast<std::size_t>(Matrix::ColsAtCompileTime))
      fail("a matrix of another width");
    if (cols > 0 && rows > (bytes_.size() - at_) / sizeof(Scalar) / cols) fail("a matrix larger than the bytes");
    Matrix m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    raw(m.data(), rows * cols * sizeof(Scalar));
    return m;
  }
  void expect_end() const {
    if (at_ != bytes_.size()) fail("bytes after the mesh");
  }

 private:
  void raw(void* out, std::size_t size) {
    if (size > bytes_.size() - at_) fail("they end early");
    if (size > 0) std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }
  [[noreturn]] void fail(const char* what) const {
    throw Error(fmt::format("a mesh's bytes do not read back ({} at byte {} of {})", what, at_, bytes_.size()));
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string tet_mesh_bytes(const TetMesh& mesh) {
  Writer w;
  w.bytes.reserve(static_cast<std::size_t>(mesh.rest.size()) * sizeof(double) +
                  static_cast<std::size_t>(mesh.tets.size() + mesh.region.size()) * sizeof(Index) + 4096);
  w.matrix(mesh.rest);
  w.matrix(mesh.tets);
  w.matrix(mesh.region);
  w.count(mesh.region_names.size());
  for (const std::string& name : mesh.region_names) w.text(name);
  w.count(mesh.node_sets.size());
  for (const auto& [name, nodes] : mesh.node_sets) {
    w.text(name);
    w.matrix(Eigen::Map<const IndexVector>(nodes.data(), static_cast<Eigen::Index>(nodes.size())));
  }
  w.count(mesh.face_sets.size());
  for (const auto& [name, faces] : mesh.face_sets) {
    w.text(name);
    w.matrix(faces);
  }
  w.count(mesh.node_fields.size());
  for (const auto& [name, values] : mesh.node_fields) {
    w.text(name);
    w.matrix(values);
  }
  w.count(mesh.skipped_node_fields.size());
  for (const auto& [name, why] : mesh.skipped_node_fields) {
    w.text(name);
    w.text(why);
  }
  return std::move(w.bytes);
}

TetMesh tet_mesh_from_bytes(std::string_view bytes) {
  Reader r(bytes);
  TetMesh mesh;
  mesh.rest = r.matrix<Positions>();
  mesh.tets = r.matrix<Tets>();
  mesh.region = r.matrix<IndexVector>();
  mesh.region_names.resize(r.count());
  for (std::string& name : mesh.region_names) name = r.text();
  for (std::size_t n = r.count(); n > 0; --n) {
    std::string name = r.text();
    const IndexVector nodes = r.matrix<IndexVector>();
    mesh.node_sets[std::move(name)] = std::vector<Index>(nodes.data(), nodes.data() + nodes.size());
  }
  for (std::size_t n = r.count(); n > 0; --n) {
    std::string name = r.text();
    mesh.face_sets[std::move(name)] = r.matrix<Triangles>();
  }
  for (std::size_t n = r.count(); n > 0; --n) {
    std::string name = r.text();
    mesh.node_fields[std::move(name)] = r.matrix<VectorX>();
  }
  for (std::size_t n = r.count(); n > 0; --n) {
    std::string name = r.text();
    mesh.skipped_node_fields[std::move(name)] = r.text();
  }
  r.expect_end();
  return mesh;
}

}  // namespace sinew::mesh
