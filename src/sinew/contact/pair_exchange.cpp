#include "sinew/contact/pair_exchange.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace sinew::contact {
namespace {

template <class T>
void put(std::vector<char>& bytes, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  const auto* p = reinterpret_cast<const char*>(&value);
  bytes.insert(bytes.end(), p, p + sizeof(T));
}

void put_doubles(std::vector<char>& bytes, const double* values, std::size_t n) {
  const auto* p = reinterpret_cast<const char*>(values);
  bytes.insert(bytes.end(), p, p + n * sizeof(double));
}

/// Reads values from bytes, in order, and checks that they do not run out.
class Reader {
 public:
  explicit Reader(const std::vector<char>& bytes) : bytes_(bytes) {}
  bool done() const { return at_ == bytes_.size(); }
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  void get_doubles(double* values, std::size_t n) { std::memcpy(values, take(n * sizeof(double)), n * sizeof(double)); }

 private:
  const char* take(std::size_t n) {
    if (bytes_.size() - at_ < n) throw std::runtime_error("unpack_pairs: the bytes end inside a pair");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

}  // namespace

void pack_pairs(const std::vector<ActivePair>& pairs, ContactMethod method, std::vector<char>& bytes) {
  for (const ActivePair& p : pairs) {
    put(bytes, p.triangle);
    put(bytes, p.tet);
    put(bytes, p.penalty);
    if (method == ContactMethod::Area) {
      const collision::ClipPolygon& polygon = p.support.polygon;
      put(bytes, polygon.count);
      for (int k = 0; k < polygon.count; ++k) {
        const auto i = static_cast<std::size_t>(k);
        put_doubles(bytes, polygon.vertices[i].data(), 3);
        put_doubles(bytes, polygon.barycentric[i].data(), 4);
        put(bytes, polygon.provenance[i]);
      }
    } else {
      const collision::CollocationPoints& points = p.support.points;
      put(bytes, points.count);
      put(bytes, points.vertex);
      for (int k = 0; k < points.count; ++k) put_doubles(bytes, points.barycentric[static_cast<std::size_t>(k)].data(), 4);
    }
  }
}

std::vector<ActivePair> unpack_pairs(const std::vector<char>& bytes, ContactMethod method) {
  std::vector<ActivePair> pairs;
  Reader in(bytes);
  while (!in.done()) {
    ActivePair& p = pairs.emplace_back();
    p.triangle = in.get<Index>();
    p.tet = in.get<Index>();
    p.penalty = in.get<double>();
    if (method == ContactMethod::Area) {
      collision::ClipPolygon& polygon = p.support.polygon;
      polygon.count = in.get<int>();
      if (polygon.count < 0 || polygon.count > collision::kMaxClipVertices)
        throw std::runtime_error("unpack_pairs: a clip polygon of " + std::to_string(polygon.count) + " vertices");
      for (int k = 0; k < polygon.count; ++k) {
        const auto i = static_cast<std::size_t>(k);
        in.get_doubles(polygon.vertices[i].data(), 3);
        in.get_doubles(polygon.barycentric[i].data(), 4);
        polygon.provenance[i] = in.get<collision::ClipVertexProvenance>();
      }
    } else {
      collision::CollocationPoints& points = p.support.points;
      points.count = in.get<int>();
      if (points.count < 0 || points.count > 3)
        throw std::runtime_error("unpack_pairs: " + std::to_string(points.count) + " collocation points");
      points.vertex = in.get<std::array<std::int8_t, 3>>();
      for (int k = 0; k < points.count; ++k) in.get_doubles(points.barycentric[static_cast<std::size_t>(k)].data(), 4);
    }
  }
  return pairs;
}

}  // namespace sinew::contact
