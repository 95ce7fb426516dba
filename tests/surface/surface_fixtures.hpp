#pragma once
/// @file surface_fixtures.hpp
/// Small surface files written by the tests themselves: a unit cube and a tetrahedron as ASCII
/// and binary STL, OBJ, ASCII PLY, glTF (base64 data URI) and GLB (built byte by byte).

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "sinew/surface/surface_mesh.hpp"

namespace sinew::testing {

/// A triangle surface as plain arrays, counter-clockwise seen from outside.
struct Shape {
  std::vector<std::array<float, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// The unit cube [0,1]^3: 8 vertices, 12 triangles, volume 1.
inline Shape unit_cube() {
  return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
          {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
           {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}}};
}

/// The corner tetrahedron (0,0,0), e_x, e_y, e_z: 4 vertices, 4 triangles, volume 1/6.
inline Shape unit_tet() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

inline std::string ascii_stl(const Shape& s, const std::string& name = "shape") {
  std::string out = "solid " + name + "\n";
  for (const auto& t : s.triangles) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (std::uint32_t i : t) {
      out += fmt::format("      vertex {} {} {}\n", s.vertices[i][0], s.vertices[i][1], s.vertices[i][2]);
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid " + name + "\n";
}

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

inline std::string binary_stl(const Shape& s) {
  std::string out(80, ' ');
  std::memcpy(out.data(), "binary test shape", 17);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(s.triangles.size()));
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) put<float>(out, 0.0f);  // normal
    for (std::uint32_t i : t) {
      for (int k = 0; k < 3; ++k) put<float>(out, s.vertices[i][k]);
    }
    put<std::uint16_t>(out, 0);
  }
  return out;
}

inline std::string obj(const Shape& s) {
  std::string out = "# test shape\no shape\n";
  for (const auto& v : s.vertices) out += fmt::format("v {} {} {}\n", v[0], v[1], v[2]);
  for (const auto& t : s.triangles) out += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
  return out;
}

inline std::string ascii_ply(const Shape& s) {
  std::string out = fmt::format(
      "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      s.vertices.size(), s.triangles.size());
  for (const auto& v : s.vertices) out += fmt::format("{} {} {}\n", v[0], v[1], v[2]);
  for (const auto& t : s.triangles) out += fmt::format("3 {} {} {}\n", t[0], t[1], t[2]);
  return out;
}

inline std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 2]);
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

/// A glTF 2.0 document with one mesh per (name, shape), one node each (node i translated by
/// `offsets[i]`), and its binary buffer; `buffer_uri` empty = no uri (GLB).
struct Gltf {
  std::string json;
  std::string bin;
};

inline Gltf gltf(const std::vector<std::pair<std::string, Shape>>& meshes, const std::string& buffer_uri,
                 const std::vector<std::array<float, 3>>& offsets = {}) {
  Gltf g;
  std::string views, accessors, mesh_list, nodes, scene_nodes;
  int view = 0;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const Shape& s = meshes[m].second;
    std::array<float, 3> lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
    const std::size_t pos_offset = g.bin.size();
    for (const auto& v : s.vertices) {
      for (int k = 0; k < 3; ++k) {
        put<float>(g.bin, v[k]);
        lo[k] = std::min(lo[k], v[k]);
        hi[k] = std::max(hi[k], v[k]);
      }
    }
    const std::size_t idx_offset = g.bin.size();
    for (const auto& t : s.triangles) {
      for (std::uint32_t i : t) put<std::uint32_t>(g.bin, i);
    }
    const std::string sep = m == 0 ? "" : ",";
    views += fmt::format("{}{{\"buffer\":0,\"byteOffset\":{},\"byteLength\":{},\"target\":34962}},"
                         "{{\"buffer\":0,\"byteOffset\":{},\"byteLength\":{},\"target\":34963}}",
                         sep, pos_offset, idx_offset - pos_offset, idx_offset, g.bin.size() - idx_offset);
    accessors += fmt::format(
        "{}{{\"bufferView\":{},\"componentType\":5126,\"count\":{},\"type\":\"VEC3\",\"min\":[{},{},{}],"
        "\"max\":[{},{},{}]}},{{\"bufferView\":{},\"componentType\":5125,\"count\":{},\"type\":\"SCALAR\"}}",
        sep, view, s.vertices.size(), lo[0], lo[1], lo[2], hi[0], hi[1], hi[2], view + 1, 3 * s.triangles.size());
    mesh_list += fmt::format("{}{{\"name\":\"{}\",\"primitives\":[{{\"attributes\":{{\"POSITION\":{}}},"
                             "\"indices\":{},\"mode\":4}}]}}",
                             sep, meshes[m].first, view, view + 1);
    const std::array<float, 3> t = m < offsets.size() ? offsets[m] : std::array<float, 3>{0, 0, 0};
    nodes += fmt::format("{}{{\"name\":\"node_{}\",\"mesh\":{},\"translation\":[{},{},{}]}}", sep, meshes[m].first, m,
                         t[0], t[1], t[2]);
    scene_nodes += fmt::format("{}{}", sep, m);
    view += 2;
  }
  const std::string uri = buffer_uri.empty() ? "" : fmt::format("\"uri\":\"{}\",", buffer_uri);
  g.json = fmt::format(
      "{{\"asset\":{{\"version\":\"2.0\"}},\"scene\":0,\"scenes\":[{{\"nodes\":[{}]}}],\"nodes\":[{}],"
      "\"meshes\":[{}],\"accessors\":[{}],\"bufferViews\":[{}],\"buffers\":[{{{}\"byteLength\":{}}}]}}",
      scene_nodes, nodes, mesh_list, accessors, views, uri, g.bin.size());
  return g;
}

/// A .gltf text with the buffer embedded as a base64 data URI.
inline std::string gltf_embedded(const std::vector<std::pair<std::string, Shape>>& meshes,
                                 const std::vector<std::array<float, 3>>& offsets = {}) {
  const Gltf probe = gltf(meshes, "x", offsets);
  return gltf(meshes, "data:application/octet-stream;base64," + base64(probe.bin), offsets).json;
}

/// A .glb: 12-byte header, the JSON chunk (space padded), the BIN chunk (zero padded).
inline std::string glb(const std::vector<std::pair<std::string, Shape>>& meshes,
                       const std::vector<std::array<float, 3>>& offsets = {}) {
  Gltf g = gltf(meshes, "", offsets);
  while (g.json.size() % 4 != 0) g.json += ' ';
  while (g.bin.size() % 4 != 0) g.bin += '\0';
  std::string out = "glTF";
  put<std::uint32_t>(out, 2);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(12 + 8 + g.json.size() + 8 + g.bin.size()));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(g.json.size()));
  put<std::uint32_t>(out, 0x4E4F534Au);  // "JSON"
  out += g.json;
  put<std::uint32_t>(out, static_cast<std::uint32_t>(g.bin.size()));
  put<std::uint32_t>(out, 0x004E4942u);  // "BIN\0"
  out += g.bin;
  return out;
}

/// The vertices as sorted rows, for comparing the same surface read from two formats.
inline std::vector<std::array<double, 3>> sorted_vertices(const surface::SurfaceMesh& mesh) {
  std::vector<std::array<double, 3>> rows;
  for (Index v = 0; v < mesh.vertices.rows(); ++v) rows.push_back({mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)});
  std::sort(rows.begin(), rows.end());
  return rows;
}

/// The triangles as sorted, rotation-normalized triples of vertex positions.
inline std::vector<std::array<std::array<double, 3>, 3>> sorted_triangles(const surface::SurfaceMesh& mesh) {
  std::vector<std::array<std::array<double, 3>, 3>> out;
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    std::array<std::array<double, 3>, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const Index v = mesh.triangles(t, k);
      tri[k] = {mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)};
    }
    const auto first = std::min_element(tri.begin(), tri.end());
    std::rotate(tri.begin(), first, tri.end());  // keeps the winding
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace sinew::testing
