/// @file build_surface_mesh.cpp

#include "sinew/scene/build_surface_mesh.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/surface/read_surface.hpp"
#include "sinew/surface/repair_surface.hpp"
#include "sinew/surface/surface_checks.hpp"

namespace sinew::scene {

std::string surface_file_path(const SurfaceFileConfig& file, const std::string& directory) {
  std::filesystem::path path(file.file);
  if (path.is_relative() && !directory.empty()) path = std::filesystem::path(directory) / path;
  return path.string();
}

namespace {

/// Most triangles a remeshed surface may have (the VH skin as read has 107k).
constexpr double kMaxRemeshedTriangles = 5e6;
/// Largest relative change of a closed surface's enclosed volume that remeshing may make.
constexpr double kMaxRemeshVolumeChange = 0.05;

std::string describe(const std::string& name, const SurfaceFileConfig& file) {
  std::string text = "surface \"" + name + "\" (" + file.file;
  if (!file.mesh_name.empty()) text += ", mesh " + file.mesh_name;
  return text + ")";
}

surface::ClosedSurface load_surface(const std::string& name, const SurfaceFileConfig& file, const std::string& directory) {
  const std::string what = describe(name, file);
  const std::filesystem::path path(surface_file_path(file, directory));
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    std::string message = what + ": file not found: " + path.lexically_normal().string();
    if (!file.source.empty()) message += "; get it from: " + file.source;
    message += " (the scene's \"data_dir\" or the command line's --data-dir says where surface files are)";
    throw InputError(message);
  }
  surface::SurfaceReadOptions read;
  read.mesh_name = file.mesh_name;
  read.unit_scale = file.unit_scale;
  read.translation = file.translate;
  surface::SurfaceMesh mesh = surface::read_surface(path.string(), read);
  if (file.repair && file.repair->remesh_edge_length > 0) {
    // Equilateral triangles of edge L cover sqrt(3)/4 L^2 each: refuse a target that would make
    // more triangles than a mesher could use, before CGAL allocates them.
    const double length = file.repair->remesh_edge_length;
    const double expected = surface::surface_area(mesh) / (std::sqrt(3.0) / 4 * length * length);
    if (!(expected <= kMaxRemeshedTriangles))
      throw InputError(fmt::format("{}: \"remesh_edge_length\" {:g} would make about {:.3g} triangles of its area "
                                   "{:.6g} (at most {:g}); choose a longer edge",
                                   what, length, expected, surface::surface_area(mesh), kMaxRemeshedTriangles));
  }
  if (file.repair) {
    surface::RepairReport report;
    mesh = surface::repair_surface(mesh, *file.repair, &report);
    logger().info("{}: repaired: {} degenerate and {} duplicate triangles dropped, {} holes filled with {} triangles",
                  what, report.degenerate_dropped, report.duplicates_dropped, report.holes_filled, report.triangles_added);
    if (report.triangles_remeshed > 0) {
      logger().info("{}: remeshed to edges of about {:g}: {} triangles", what, file.repair->remesh_edge_length,
                    report.triangles_remeshed);
      // An edge too long for the surface's features collapses them: refuse a changed shape.
      const double before = report.volume_before_remesh, after = report.volume_after_remesh;
      if (report.closed_before_remesh && !(std::abs(after - before) <= kMaxRemeshVolumeChange * std::abs(before)))
        throw InputError(fmt::format("{}: remeshing to edges of {:g} changed the enclosed volume from {:.6g} to {:.6g} "
                                     "({:+.1f} %, at most {:g} % allowed): the edge is too long for the surface's "
                                     "features; choose a shorter \"remesh_edge_length\"",
                                     what, file.repair->remesh_edge_length, before, after,
                                     100 * (after - before) / before, 100 * kMaxRemeshVolumeChange));
    }
  }
  surface::ClosedSurface closed(mesh, what);
  const std::vector<surface::SelfIntersection> crossings = surface::find_self_intersections(closed.mesh(), 3);
  if (!crossings.empty()) {
    const Vector3& at = crossings.front().location;
    throw InputError(fmt::format("{}: the surface intersects itself (triangles {} and {} cross near ({:.6g}, {:.6g}, {:.6g})); "
                                 "a region needs a surface that bounds a solid",
                                 what, crossings.front().triangle_a, crossings.front().triangle_b, at.x(), at.y(), at.z()));
  }
  return closed;
}

}  // namespace

mesh::TetMesh build_surface_mesh(const SurfaceMeshConfig& config, const std::string& directory) {
  surface::SurfaceLibrary library;
  for (const auto& [name, file] : config.surfaces) library.emplace(name, load_surface(name, file, directory));
  surface::TetrahedralizeReport report;
  mesh::TetMesh result = surface::tetrahedralize(config.parts, library, config.options, &report);
  logger().info("{}: {} nodes, {} tets in {:.2f} s; smallest dihedral angle {:.2f} deg, worst radius ratio {:.3f}, {} slivers (< 5 deg)",
                config.options.what, result.num_nodes(), result.num_tets(), report.seconds, report.quality.min_dihedral_deg,
                report.quality.worst_radius_ratio, report.quality.slivers);
  for (std::size_t r = 0; r < config.parts.size(); ++r) {
    logger().info("  region {}: {} tets, volume {:.6g}", config.parts[r].region, report.tets_per_region[r], report.region_volumes[r]);
  }
  return result;
}

}  // namespace sinew::scene
