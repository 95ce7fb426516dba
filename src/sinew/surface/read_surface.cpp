/// @file read_surface.cpp
/// Mesh selection, option checks, the weld of coincident vertices and the placement.

#include "sinew/surface/read_surface.hpp"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <map>

#include "sinew/core/error.hpp"
#include "sinew/surface/assimp_import.hpp"
#include "sinew/surface/surface_file.hpp"

namespace sinew::surface {
namespace {

std::string quoted_list(const std::vector<ImportedMesh>& meshes) {
  std::string list;
  for (const ImportedMesh& m : meshes) list += (list.empty() ? "'" : ", '") + m.name + "'";
  return list;
}

void check_options(const std::string& path, const SurfaceReadOptions& options) {
  if (!std::isfinite(options.unit_scale) || options.unit_scale <= 0) {
    throw InputError(fmt::format("surface file '{}': unit_scale must be positive and finite, got {}", path,
                                 options.unit_scale));
  }
  const Matrix3& r = options.rotation;
  if (!r.allFinite() || (r.transpose() * r - Matrix3::Identity()).cwiseAbs().maxCoeff() > 1e-9 ||
      std::abs(r.determinant() - 1) > 1e-9) {
    throw InputError(fmt::format(
        "surface file '{}': the rotation must be orthonormal with determinant +1 (a proper rotation, tolerance 1e-9)",
        path));
  }
  if (!options.translation.allFinite()) {
    throw InputError(fmt::format("surface file '{}': the translation must be finite", path));
  }
}

const ImportedMesh& select(const std::string& path, const std::vector<ImportedMesh>& meshes, const std::string& name) {
  if (name.empty()) {
    if (meshes.size() == 1) return meshes.front();
    throw InputError(fmt::format("surface file '{}' has {} meshes ({}); choose one by name", path, meshes.size(),
                                 quoted_list(meshes)));
  }
  for (const ImportedMesh& m : meshes) {
    if (m.name == name) return m;
  }
  throw InputError(fmt::format("surface file '{}' has no mesh '{}'; its meshes are {}", path, name, quoted_list(meshes)));
}

/// Joins vertices at exactly the same position (file coordinates, -0 == +0) and drops vertices
/// no triangle uses; new indices in order of first use.
SurfaceMesh weld(const ImportedMesh& mesh) {
  std::map<std::array<double, 3>, Index> index_of;
  std::vector<Index> renumber(static_cast<std::size_t>(mesh.vertices.rows()), -1);
  std::vector<Index> first_vertex;  // new index -> an old vertex at that position
  SurfaceMesh out{.vertices = Positions(0, 3), .triangles = mesh.triangles, .name = mesh.name};
  for (Index t = 0; t < out.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Index old = out.triangles(t, k);
      auto& slot = renumber[static_cast<std::size_t>(old)];
      if (slot < 0) {
        const std::array<double, 3> key{mesh.vertices(old, 0) + 0.0, mesh.vertices(old, 1) + 0.0,
                                        mesh.vertices(old, 2) + 0.0};
        auto [it, added] = index_of.emplace(key, static_cast<Index>(first_vertex.size()));
        if (added) first_vertex.push_back(old);
        slot = it->second;
      }
      out.triangles(t, k) = slot;
    }
  }
  out.vertices.resize(static_cast<Index>(first_vertex.size()), 3);
  for (std::size_t i = 0; i < first_vertex.size(); ++i) {
    out.vertices.row(static_cast<Index>(i)) = mesh.vertices.row(first_vertex[i]);
  }
  return out;
}

}  // namespace

SurfaceMesh read_surface(const std::string& path, const SurfaceReadOptions& options) {
  check_options(path, options);
  const std::vector<ImportedMesh> meshes = import_meshes(read_surface_file(path));
  const ImportedMesh& chosen = select(path, meshes, options.mesh_name);
  if (chosen.triangles.rows() == 0) {
    throw InputError(fmt::format("surface file '{}', mesh '{}' has no triangles", path, chosen.name));
  }
  SurfaceMesh mesh = weld(chosen);
  const Matrix3 linear = options.unit_scale * options.rotation;
  for (Index v = 0; v < mesh.vertices.rows(); ++v) {
    const Vector3 x = linear * mesh.vertices.row(v).transpose() + options.translation;
    if (!x.allFinite()) {
      throw InputError(fmt::format("surface file '{}', mesh '{}': vertex {} is not finite after scaling", path,
                                   mesh.name, v));
    }
    mesh.vertices.row(v) = x.transpose();
  }
  return mesh;
}

std::vector<std::string> surface_mesh_names(const std::string& path) {
  std::vector<std::string> names;
  for (const ImportedMesh& m : import_meshes(read_surface_file(path))) names.push_back(m.name);
  return names;
}

}  // namespace sinew::surface
