/// @file cgal_surface.cpp

#include "sinew/surface/cgal_surface.hpp"

#include <vector>

namespace sinew::surface::cgal {

Mesh to_cgal(const SurfaceMesh& surface, Index* rejected) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertex(static_cast<std::size_t>(surface.vertices.rows()));
  for (Index v = 0; v < surface.vertices.rows(); ++v) {
    vertex[static_cast<std::size_t>(v)] = mesh.add_vertex(to_point(surface.vertices.row(v).transpose()));
  }
  Index refused = 0;
  for (Index t = 0; t < surface.triangles.rows(); ++t) {
    const auto a = vertex[static_cast<std::size_t>(surface.triangles(t, 0))];
    const auto b = vertex[static_cast<std::size_t>(surface.triangles(t, 1))];
    const auto c = vertex[static_cast<std::size_t>(surface.triangles(t, 2))];
    if (a == b || b == c || a == c || mesh.add_face(a, b, c) == Mesh::null_face()) ++refused;
  }
  if (rejected != nullptr) *rejected = refused;
  return mesh;
}

SurfaceMesh from_cgal(const Mesh& input, const std::string& name) {
  Mesh mesh = input;
  mesh.collect_garbage();
  SurfaceMesh surface;
  surface.name = name;
  surface.vertices.resize(static_cast<Index>(mesh.number_of_vertices()), 3);
  for (const auto v : mesh.vertices()) surface.vertices.row(static_cast<Index>(v.idx())) = to_vector(mesh.point(v)).transpose();
  surface.triangles.resize(static_cast<Index>(mesh.number_of_faces()), 3);
  Index t = 0;
  for (const auto f : mesh.faces()) {
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k < 3) surface.triangles(t, k) = static_cast<Index>(v.idx());
      ++k;
    }
    ++t;
  }
  return surface;
}

}  // namespace sinew::surface::cgal
