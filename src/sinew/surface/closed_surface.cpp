/// @file closed_surface.cpp
/// ClosedSurface on CGAL's AABB tree and Side_of_triangle_mesh.

#include "sinew/surface/closed_surface.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <cmath>
#include <optional>

#include "sinew/core/error.hpp"
#include "sinew/surface/cgal_surface.hpp"
#include "sinew/surface/surface_checks.hpp"

namespace sinew::surface {

namespace {
using Primitive = CGAL::AABB_face_graph_triangle_primitive<cgal::Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<cgal::Kernel, Primitive>>;
using Side = CGAL::Side_of_triangle_mesh<cgal::Mesh, cgal::Kernel, CGAL::Default, Tree>;

std::string format_point(const Vector3& x) {
  return "(" + std::to_string(x.x()) + ", " + std::to_string(x.y()) + ", " + std::to_string(x.z()) + ")";
}

/// A vertex of one boundary edge, for the message of an open surface.
Vector3 boundary_vertex(const SurfaceMesh& mesh) {
  std::map<std::pair<Index, Index>, int> uses;
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Index a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& [edge, count] : uses) {
    if (count != 2) return mesh.vertices.row(edge.first).transpose();
  }
  return Vector3::Zero();
}
}  // namespace

struct ClosedSurface::Impl {
  SurfaceMesh surface;
  cgal::Mesh mesh;
  Tree tree;
  std::optional<Side> side;
  double volume = 0;
  Bounds bounds;
};

ClosedSurface::ClosedSurface(const SurfaceMesh& input, const std::string& what) : impl_(std::make_unique<Impl>()) {
  if (input.triangles.rows() == 0) throw InputError(what + ": the surface has no triangles");
  if (!input.vertices.allFinite()) throw InputError(what + ": a vertex is NaN or infinite");
  const SurfaceTopology topology = surface_topology(input);
  if (topology.non_manifold_edges > 0) {
    throw InputError(what + ": not a manifold surface: " + std::to_string(topology.non_manifold_edges) +
                     " edges are shared by three or more triangles");
  }
  if (topology.boundary_edges > 0) {
    throw InputError(what + ": the surface is open: " + std::to_string(topology.boundary_edges) +
                     " boundary edges, one at " + format_point(boundary_vertex(input)) +
                     "; a region needs a closed surface (\"repair\": {\"fill_holes\": true} closes holes)");
  }
  impl_->surface = input;
  double volume = enclosed_volume(input);
  if (volume < 0) {
    impl_->surface.triangles.col(1).swap(impl_->surface.triangles.col(2));
    volume = -volume;
  }
  if (!(volume > 0)) throw InputError(what + ": the surface encloses no volume");
  impl_->volume = volume;
  Index rejected = 0;
  impl_->mesh = cgal::to_cgal(impl_->surface, &rejected);
  if (rejected > 0) {
    throw InputError(what + ": " + std::to_string(rejected) +
                     " triangles are inconsistently oriented or repeat an edge; the surface is not a clean 2-manifold");
  }
  impl_->tree.insert(faces(impl_->mesh).first, faces(impl_->mesh).second, impl_->mesh);
  impl_->tree.accelerate_distance_queries();
  impl_->side.emplace(impl_->tree);
  for (Index v = 0; v < impl_->surface.vertices.rows(); ++v) impl_->bounds.extend(impl_->surface.vertices.row(v).transpose());
}

ClosedSurface::~ClosedSurface() = default;
ClosedSurface::ClosedSurface(ClosedSurface&&) noexcept = default;
ClosedSurface& ClosedSurface::operator=(ClosedSurface&&) noexcept = default;

bool ClosedSurface::contains(const Vector3& point) const {
  const Vector3& lo = impl_->bounds.min;
  const Vector3& hi = impl_->bounds.max;
  if ((point.array() < lo.array()).any() || (point.array() > hi.array()).any()) return false;
  return (*impl_->side)(cgal::to_point(point)) != CGAL::ON_UNBOUNDED_SIDE;
}

double ClosedSurface::distance(const Vector3& point) const {
  return std::sqrt(CGAL::to_double(impl_->tree.squared_distance(cgal::to_point(point))));
}

double ClosedSurface::signed_distance(const Vector3& point) const {
  const double unsigned_distance = distance(point);
  return contains(point) ? -unsigned_distance : unsigned_distance;
}

double ClosedSurface::volume() const { return impl_->volume; }
Bounds ClosedSurface::bounds() const { return impl_->bounds; }
const SurfaceMesh& ClosedSurface::mesh() const { return impl_->surface; }

}  // namespace sinew::surface
