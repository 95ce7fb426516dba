#include "sinew/mesh/tet_mesh.hpp"

#include <algorithm>

#include "sinew/core/error.hpp"

namespace sinew::mesh {

Index TetMesh::region_id(const std::string& name) const {
  const auto found = std::find(region_names.begin(), region_names.end(), name);
  if (found != region_names.end()) return static_cast<Index>(found - region_names.begin());
  std::string known;
  for (const auto& region_name : region_names) {
    known += (known.empty() ? "\"" : ", \"") + region_name + "\"";
  }
  throw InputError("no region named \"" + name + "\" in the mesh; its regions are: " +
                   (known.empty() ? std::string("(none)") : known));
}

double signed_volume(const Positions& x, const Tets& tets, Index t) {
  const Vector3 x0 = x.row(tets(t, 0)).transpose();
  const Vector3 e1 = x.row(tets(t, 1)).transpose() - x0;
  const Vector3 e2 = x.row(tets(t, 2)).transpose() - x0;
  const Vector3 e3 = x.row(tets(t, 3)).transpose() - x0;
  return e1.dot(e2.cross(e3)) / 6.0;
}

Index orient_positively(const Positions& rest, Tets& tets) {
  Index flipped = 0;
  for (Index t = 0; t < tets.rows(); ++t) {
    if (signed_volume(rest, tets, t) < 0) {
      std::swap(tets(t, 2), tets(t, 3));
      ++flipped;
    }
  }
  return flipped;
}

std::vector<Index> referenced_nodes(const Tets& tets) {
  std::vector<char> used(static_cast<std::size_t>(tets.size() == 0 ? 0 : tets.maxCoeff() + 1), 0);
  for (Index i = 0; i < tets.size(); ++i) used[static_cast<std::size_t>(tets.data()[i])] = 1;
  std::vector<Index> nodes;
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (used[v]) nodes.push_back(static_cast<Index>(v));
  }
  return nodes;
}

}  // namespace sinew::mesh
