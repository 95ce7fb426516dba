#include "sinew/collision/material_depth.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sinew/collision/aabb_tree.hpp"
#include "sinew/collision/broad_phase.hpp"
#include "sinew/collision/point_triangle_distance.hpp"
#include "sinew/core/error.hpp"

namespace sinew::collision {

namespace {

/// The surface and the nodes come from the user's meshes and choices (a zero-depth face set,
/// region or node selection): a bad one is an input error.
void check_inputs(const Positions& rest, const Triangles& surface, const std::vector<Index>& nodes,
                  const char* what) {
  const Index nv = static_cast<Index>(rest.rows());
  for (Index f = 0; f < surface.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (surface(f, k) < 0 || surface(f, k) >= nv)
        throw InputError(std::string(what) + ": surface triangle " + std::to_string(f) +
                                    " has node index " + std::to_string(surface(f, k)) + " outside 0.." +
                                    std::to_string(nv - 1));
  for (const Index a : nodes)
    if (a < 0 || a >= nv)
      throw InputError(std::string(what) + ": node index " + std::to_string(a) + " outside 0.." +
                                  std::to_string(nv - 1));
  if (surface.rows() == 0 && !nodes.empty())
    throw InputError(std::string(what) + ": the contact surface has no triangles");
}

/// Per-node flag: 1 for vertices of the surface (their depth is exactly 0).
std::vector<char> surface_vertex_flags(const Positions& rest, const Triangles& surface) {
  std::vector<char> on(static_cast<std::size_t>(rest.rows()), 0);
  for (Index f = 0; f < surface.rows(); ++f)
    for (int k = 0; k < 3; ++k) on[static_cast<std::size_t>(surface(f, k))] = 1;
  return on;
}

double squared_distance_to_triangle(const Positions& rest, const Triangles& surface, Index f, const Vector3& p) {
  return point_triangle_squared_distance(p, rest.row(surface(f, 0)).transpose(), rest.row(surface(f, 1)).transpose(),
                                         rest.row(surface(f, 2)).transpose());
}

}  // namespace

VectorX material_depth(const Positions& rest, const Triangles& surface, const std::vector<Index>& nodes) {
  check_inputs(rest, surface, nodes, "material_depth");
  VectorX depth = VectorX::Zero(static_cast<Index>(nodes.size()));
  if (nodes.empty()) return depth;
  const std::vector<char> on_surface = surface_vertex_flags(rest, surface);
  const AabbTree tree(triangle_boxes(rest, surface));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nodes.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const Index a = nodes[i];
      if (on_surface[static_cast<std::size_t>(a)]) continue;
      const Vector3 p = rest.row(a).transpose();
      const auto best = tree.nearest(p, [&](Index f) { return squared_distance_to_triangle(rest, surface, f, p); });
      depth[static_cast<Index>(i)] = std::sqrt(best.second);
    }
  });
  return depth;
}

VectorX material_depth_exhaustive(const Positions& rest, const Triangles& surface, const std::vector<Index>& nodes) {
  check_inputs(rest, surface, nodes, "material_depth_exhaustive");
  VectorX depth = VectorX::Zero(static_cast<Index>(nodes.size()));
  const std::vector<char> on_surface = surface_vertex_flags(rest, surface);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Index a = nodes[i];
    if (on_surface[static_cast<std::size_t>(a)]) continue;
    const Vector3 p = rest.row(a).transpose();
    double best = std::numeric_limits<double>::infinity();
    for (Index f = 0; f < surface.rows(); ++f) best = std::min(best, squared_distance_to_triangle(rest, surface, f, p));
    depth[static_cast<Index>(i)] = std::sqrt(best);
  }
  return depth;
}

}  // namespace sinew::collision
