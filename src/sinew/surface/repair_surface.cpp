/// @file repair_surface.cpp
/// CGAL Polygon Mesh Processing behind repair_surface and find_self_intersections.

#include "sinew/surface/repair_surface.hpp"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <set>

#include "sinew/surface/cgal_surface.hpp"
#include "sinew/surface/surface_checks.hpp"

namespace sinew::surface {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

/// Triangles kept after dropping repeated-vertex, zero-area and duplicate ones.
Triangles clean_triangles(const SurfaceMesh& surface, const RepairOptions& options, RepairReport& report) {
  double mean_edge = 0;
  for (Index t = 0; t < surface.triangles.rows(); ++t) {
    mean_edge += (surface.vertices.row(surface.triangles(t, 1)) - surface.vertices.row(surface.triangles(t, 0))).norm();
  }
  if (surface.triangles.rows() > 0) mean_edge /= static_cast<double>(surface.triangles.rows());
  const double min_area = 1e-12 * mean_edge * mean_edge;
  std::set<std::array<Index, 3>> seen;
  std::vector<Index> kept;
  for (Index t = 0; t < surface.triangles.rows(); ++t) {
    const Index a = surface.triangles(t, 0), b = surface.triangles(t, 1), c = surface.triangles(t, 2);
    if (options.drop_degenerate) {
      const Vector3 e1 = (surface.vertices.row(b) - surface.vertices.row(a)).transpose();
      const Vector3 e2 = (surface.vertices.row(c) - surface.vertices.row(a)).transpose();
      if (a == b || b == c || a == c || 0.5 * e1.cross(e2).norm() <= min_area) {
        ++report.degenerate_dropped;
        continue;
      }
    }
    if (options.drop_duplicates) {
      std::array<Index, 3> key{a, b, c};
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) {
        ++report.duplicates_dropped;
        continue;
      }
    }
    kept.push_back(t);
  }
  Triangles triangles(static_cast<Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i) triangles.row(static_cast<Index>(i)) = surface.triangles.row(kept[i]);
  return triangles;
}

cgal::Kernel::Triangle_3 triangle_of(const cgal::Mesh& mesh, cgal::Mesh::Face_index face) {
  const auto h = mesh.halfedge(face);
  return {mesh.point(mesh.source(h)), mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h)))};
}

/// A point of both triangles: the mean of the corners of their intersection (a point, segment,
/// triangle or convex polygon); the mean of their six corners if the inexact construction
/// finds none.
Vector3 crossing_point(const cgal::Mesh& mesh, cgal::Mesh::Face_index a, cgal::Mesh::Face_index b) {
  const cgal::Kernel::Triangle_3 ta = triangle_of(mesh, a), tb = triangle_of(mesh, b);
  std::vector<cgal::Point> corners;
  if (const auto result = CGAL::intersection(ta, tb)) {  // a boost::variant (CGAL 5)
    if (const auto* point = boost::get<cgal::Point>(&*result)) {
      corners.push_back(*point);
    } else if (const auto* segment = boost::get<cgal::Kernel::Segment_3>(&*result)) {
      corners.insert(corners.end(), {segment->source(), segment->target()});
    } else if (const auto* triangle = boost::get<cgal::Kernel::Triangle_3>(&*result)) {
      corners.insert(corners.end(), {triangle->vertex(0), triangle->vertex(1), triangle->vertex(2)});
    } else if (const auto* polygon = boost::get<std::vector<cgal::Point>>(&*result)) {
      corners = *polygon;
    }
  }
  if (corners.empty()) {
    for (int k = 0; k < 3; ++k) corners.insert(corners.end(), {ta.vertex(k), tb.vertex(k)});
  }
  Vector3 sum = Vector3::Zero();
  for (const cgal::Point& p : corners) sum += cgal::to_vector(p);
  return sum / static_cast<double>(corners.size());
}

}  // namespace

SurfaceMesh repair_surface(const SurfaceMesh& surface, const RepairOptions& options, RepairReport* report_out) {
  RepairReport report;
  SurfaceMesh cleaned = surface;
  cleaned.triangles = clean_triangles(surface, options, report);
  cgal::Mesh mesh = cgal::to_cgal(cleaned, &report.non_manifold_dropped);
  if (options.fill_holes) {
    std::vector<cgal::Mesh::Halfedge_index> loops;
    PMP::extract_boundary_cycles(mesh, std::back_inserter(loops));
    for (const auto h : loops) {
      std::vector<cgal::Mesh::Face_index> patch;
      std::vector<cgal::Mesh::Vertex_index> added;
      PMP::triangulate_and_refine_hole(mesh, h, std::back_inserter(patch), std::back_inserter(added));
      if (!patch.empty()) {
        ++report.holes_filled;
        report.triangles_added += static_cast<Index>(patch.size());
      }
    }
  }
  if (options.remesh_edge_length > 0 && !mesh.is_empty()) {
    // Three rounds, CGAL's default: each splits edges longer than 4/3 of the target, collapses
    // those shorter than 4/5, flips toward valence 6 and relaxes the vertices in the tangent plane.
    const SurfaceMesh before = cgal::from_cgal(mesh, surface.name);
    report.closed_before_remesh = surface_topology(before).closed();
    report.volume_before_remesh = enclosed_volume(before);
    PMP::isotropic_remeshing(faces(mesh), options.remesh_edge_length, mesh);
    mesh.collect_garbage();
    report.triangles_remeshed = static_cast<Index>(mesh.number_of_faces());
    report.volume_after_remesh = enclosed_volume(cgal::from_cgal(mesh, surface.name));
  }
  if (report_out != nullptr) *report_out = report;
  return cgal::from_cgal(mesh, surface.name);
}

std::vector<SelfIntersection> find_self_intersections(const SurfaceMesh& surface, std::size_t limit) {
  const cgal::Mesh mesh = cgal::to_cgal(surface);
  std::vector<std::pair<cgal::Mesh::Face_index, cgal::Mesh::Face_index>> pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  std::vector<SelfIntersection> found;
  for (const auto& [a, b] : pairs) {
    if (limit != 0 && found.size() >= limit) break;
    SelfIntersection hit;
    hit.triangle_a = static_cast<Index>(a.idx());
    hit.triangle_b = static_cast<Index>(b.idx());
    hit.location = crossing_point(mesh, a, b);
    found.push_back(hit);
  }
  return found;
}

}  // namespace sinew::surface
