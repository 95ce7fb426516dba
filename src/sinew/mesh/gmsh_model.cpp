#include "sinew/mesh/gmsh_model.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "sinew/core/error.hpp"
#include "sinew/mesh/key_groups.hpp"

namespace sinew::mesh {

namespace {

constexpr int kGmshTriangle = 2;

/// Gmsh node tag -> position in the node arrays; dense when the tags are, hashed otherwise.
class NodeTagMap {
 public:
  explicit NodeTagMap(const std::vector<std::size_t>& tags) {
    const std::size_t max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
    if (max_tag <= 2 * tags.size() + 1024) {
      dense_.assign(max_tag + 1, -1);
      for (std::size_t i = 0; i < tags.size(); ++i) dense_[tags[i]] = static_cast<Index>(i);
    } else {
      sparse_.reserve(tags.size());
      for (std::size_t i = 0; i < tags.size(); ++i) sparse_[tags[i]] = static_cast<Index>(i);
    }
  }
  /// Position of `tag`, -1 when Gmsh has no such node.
  Index position(std::size_t tag) const {
    if (!dense_.empty() || sparse_.empty()) return tag < dense_.size() ? dense_[tag] : -1;
    const auto found = sparse_.find(tag);
    return found == sparse_.end() ? -1 : found->second;
  }

 private:
  std::vector<Index> dense_;
  std::unordered_map<std::size_t, Index> sparse_;
};

std::string physical_group_name(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  return name.empty() ? "group_" + std::to_string(tag) : name;
}

/// Index of `name` in `names`, appended when absent.
Index find_or_append(std::vector<std::string>& names, const std::string& name) {
  const auto found = std::find(names.begin(), names.end(), name);
  if (found != names.end()) return static_cast<Index>(found - names.begin());
  names.push_back(name);
  return static_cast<Index>(names.size()) - 1;
}

Triangles append_rows(const Triangles& top, const Triangles& bottom) {
  Triangles stacked(top.rows() + bottom.rows(), 3);
  stacked << top, bottom;
  return stacked;
}

std::string view_option(int view_tag, const std::string& option) {
  return "View[" + std::to_string(gmsh::view::getIndex(view_tag)) + "]." + option;
}

std::string show_point(const Positions& rest, Index node) {
  std::ostringstream out;
  out << "(" << rest(node, 0) << ", " << rest(node, 1) << ", " << rest(node, 2) << ")";
  return out.str();
}

/// The post-processing views of the current Gmsh state (a .msh file's $NodeData blocks) ->
/// mesh.node_fields and mesh.skipped_node_fields (see TetMesh). `node_tags[v]` is the Gmsh tag of
/// mesh node v.
void read_node_fields(TetMesh& mesh, const std::vector<std::size_t>& node_tags) {
  std::vector<int> view_tags;
  gmsh::view::getTags(view_tags);
  if (view_tags.empty()) return;
  const NodeTagMap node_of_tag(node_tags);
  std::map<std::string, int> views_named;
  for (const int view : view_tags) {
    std::string name;
    gmsh::option::getString(view_option(view, "Name"), name);
    if (++views_named[name] > 1) {
      mesh.node_fields.erase(name);
      mesh.skipped_node_fields[name] =
          "the file has " + std::to_string(views_named[name]) + " data views of this name";
      continue;
    }
    double num_steps = 0;
    gmsh::option::getNumber(view_option(view, "NbTimeStep"), num_steps);
    std::string data_type;
    std::vector<std::size_t> tags;
    std::vector<double> data;
    int num_components = 0;
    for (int step = 0; step < static_cast<int>(num_steps) && tags.empty(); ++step) {
      double time = 0;
      gmsh::view::getHomogeneousModelData(view, step, data_type, tags, data, time, num_components);
      if (data_type != "NodeData") break;
    }
    if (data_type != "NodeData") {
      mesh.skipped_node_fields[name] = (data_type.empty() ? std::string("not model data") : data_type) +
                                       ", not node data";
      continue;
    }
    if (tags.empty()) {
      mesh.skipped_node_fields[name] = "no values";
      continue;
    }
    if (num_components != 1 || data.size() != tags.size()) {
      mesh.skipped_node_fields[name] =
          std::to_string(num_components) + " components per node, not 1";
      continue;
    }
    VectorX values = VectorX::Constant(mesh.num_nodes(), std::numeric_limits<double>::quiet_NaN());
    std::vector<char> given(static_cast<std::size_t>(mesh.num_nodes()), 0);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      const Index node = node_of_tag.position(tags[i]);
      if (node < 0) continue;  // a node no tet uses
      values[node] = data[i];
      given[static_cast<std::size_t>(node)] = 1;
    }
    const auto missing = std::count(given.begin(), given.end(), 0);
    if (missing > 0) {
      const auto first = static_cast<Index>(std::find(given.begin(), given.end(), 0) - given.begin());
      mesh.skipped_node_fields[name] =
          "no value at " + std::to_string(missing) + " of the mesh's " + std::to_string(mesh.num_nodes()) +
          " nodes, e.g. node " + std::to_string(first) + " (Gmsh node tag " +
          std::to_string(node_tags[static_cast<std::size_t>(first)]) + ") at " + show_point(mesh.rest, first);
      continue;
    }
    mesh.node_fields[name] = std::move(values);
  }
}

/// Throws InputError naming the Gmsh tags of the first nodes (used by tets) with an infinite
/// or NaN coordinate; `node_tags[kept_positions[v]]` is the tag of mesh node v.
void reject_non_finite_nodes(const Positions& rest, const std::vector<std::size_t>& node_tags,
                             const std::vector<Index>& kept_positions) {
  std::size_t count = 0;
  std::string first;
  for (Index v = 0; v < rest.rows(); ++v) {
    if (rest.row(v).allFinite()) continue;
    if (count++ < 3) {
      first += (first.empty() ? "" : "; ") + std::string("node tag ") +
               std::to_string(node_tags[static_cast<std::size_t>(kept_positions[static_cast<std::size_t>(v)])]) +
               " at " + show_point(rest, v);
    }
  }
  if (count == 0) return;
  throw InputError(std::to_string(count) +
                   (count == 1 ? " node has a non-finite coordinate (infinite, NaN or beyond "
                                 "1.8e308): "
                               : " nodes have non-finite coordinates (infinite, NaN or beyond "
                                 "1.8e308), first: ") +
                   first);
}

}  // namespace

void reject_folded_tets(const Positions& rest, const Tets& tets) {
  // Two tets sharing a face must lie on opposite sides of it; a tet on the same side as its
  // neighbour is inverted relative to it (the mesh folds over itself). Independent of the
  // file's winding convention.
  struct FaceUse {
    std::array<Index, 3> nodes;
    Index tet;
    Index opposite;
  };
  std::vector<FaceUse> uses;
  uses.reserve(static_cast<std::size_t>(4 * tets.rows()));
  for (Index t = 0; t < tets.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<Index, 3> face{};
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (i != skip) face[k++] = tets(t, i);
      std::sort(face.begin(), face.end());
      uses.push_back({face, t, tets(t, skip)});
    }
  std::sort(uses.begin(), uses.end(), [](const FaceUse& a, const FaceUse& b) { return a.nodes < b.nodes; });
  std::vector<std::pair<Index, Index>> folded;
  for (std::size_t i = 0; i + 1 < uses.size(); ++i) {
    if (uses[i].nodes != uses[i + 1].nodes) continue;
    if (uses[i].opposite == uses[i + 1].opposite) continue;  // duplicate tets: validate() reports them
    const auto& f = uses[i].nodes;
    const Eigen::Vector3d a = rest.row(f[0]).transpose();
    const Eigen::Vector3d n = (rest.row(f[1]).transpose() - a).cross(rest.row(f[2]).transpose() - a);
    const double s1 = n.dot(rest.row(uses[i].opposite).transpose() - a);
    const double s2 = n.dot(rest.row(uses[i + 1].opposite).transpose() - a);
    if (s1 * s2 > 0) folded.emplace_back(uses[i].tet, uses[i + 1].tet);
  }
  if (folded.empty()) return;
  std::string first;
  for (std::size_t i = 0; i < std::min<std::size_t>(folded.size(), 3); ++i)
    first += (i ? "; " : "") + std::string("tets ") + std::to_string(folded[i].first) + " and " +
             std::to_string(folded[i].second) + " (1-based " + std::to_string(folded[i].first + 1) + " and " +
             std::to_string(folded[i].second + 1) + ")";
  throw InputError(std::to_string(folded.size()) +
                   (folded.size() == 1 ? " inverted tetrahedron: a pair" : " inverted tetrahedra: pairs") +
                   " of tets that share a face lie on the same side of it, so the mesh "
                   "folds over itself; first: " + first + ". Fix the mesh (e.g. re-mesh it in Gmsh).");
}

Triangles orient_like_boundary(const Tets& tets, const Triangles& triangles) {
  const Triangles boundary = boundary_triangles(tets);
  const auto num_boundary = static_cast<Index>(boundary.rows());
  std::vector<std::array<Index, 3>> keys;
  keys.reserve(static_cast<std::size_t>(boundary.rows() + triangles.rows()));
  for (const Triangles* source : {&boundary, &triangles}) {
    for (Index f = 0; f < source->rows(); ++f) {
      std::array<Index, 3> key = {(*source)(f, 0), (*source)(f, 1), (*source)(f, 2)};
      std::sort(key.begin(), key.end());
      keys.push_back(key);
    }
  }
  Index num_values = node_count_bound(tets);
  if (triangles.size()) num_values = std::max(num_values, triangles.maxCoeff() + 1);
  const KeyGroups groups = group_equal_keys<3>(keys, num_values);

  Triangles oriented = triangles;
  for (Index g = 0; g < groups.num_groups(); ++g) {
    const Index first = groups.order[groups.offsets[g]];  // groups are ascending
    if (first >= num_boundary) continue;                  // not on the boundary
    for (Index i = groups.offsets[g] + 1; i < groups.offsets[g + 1]; ++i) {
      oriented.row(groups.order[i] - num_boundary) = boundary.row(first);
    }
  }
  return oriented;
}

TetMesh tet_mesh_from_gmsh_model() {
  std::vector<std::size_t> node_tags;
  std::vector<double> node_coordinates;
  std::vector<double> unused_parametric;
  gmsh::model::mesh::getNodes(node_tags, node_coordinates, unused_parametric, -1, -1,
                              /*includeBoundary=*/false, /*returnParametricCoord=*/false);
  const NodeTagMap node_position(node_tags);

  // Regions: dimension-3 physical groups by ascending tag.
  TetMesh mesh;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 3);
  std::sort(groups.begin(), groups.end());
  std::unordered_map<int, Index> region_of_group;
  for (const auto& [dim, tag] : groups) {
    region_of_group[tag] = find_or_append(mesh.region_names, physical_group_name(dim, tag));
  }

  // Tets of every volume, as node positions, and their regions.
  std::vector<Index> tet_nodes;  // 4 per tet, positions in node_tags
  std::vector<Index> tet_regions;
  Index default_region = -1;
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  for (const auto& [dim, volume] : volumes) {
    std::vector<int> volume_groups;
    gmsh::model::getPhysicalGroupsForEntity(dim, volume, volume_groups);
    Index region = -1;
    if (!volume_groups.empty()) {
      const int group = *std::min_element(volume_groups.begin(), volume_groups.end());
      const auto found = region_of_group.find(group);
      // Gmsh may not list a group it read with a malformed tag among the physical groups.
      region = found != region_of_group.end()
                   ? found->second
                   : find_or_append(mesh.region_names, physical_group_name(dim, group));
    }
    std::vector<std::size_t> element_tags;
    std::vector<std::size_t> element_nodes;
    gmsh::model::mesh::getElementsByType(kGmshLinearTetrahedron, element_tags, element_nodes,
                                         volume);
    if (element_tags.empty()) continue;
    if (region < 0) {
      if (default_region < 0) default_region = find_or_append(mesh.region_names, "default");
      region = default_region;
    }
    for (const std::size_t tag : element_nodes) {
      const Index position = node_position.position(tag);
      if (position < 0) {
        throw Error("Gmsh tetrahedron refers to node tag " + std::to_string(tag) +
                    ", which the model does not define");
      }
      tet_nodes.push_back(position);
    }
    tet_regions.insert(tet_regions.end(), element_tags.size(), region);
  }

  // Keep the nodes used by tets, in ascending tag order.
  std::vector<char> used(node_tags.size(), 0);
  for (const Index position : tet_nodes) used[static_cast<std::size_t>(position)] = 1;
  std::vector<Index> kept_positions;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i]) kept_positions.push_back(static_cast<Index>(i));
  }
  std::sort(kept_positions.begin(), kept_positions.end(),
            [&node_tags](Index a, Index b) { return node_tags[a] < node_tags[b]; });
  std::vector<Index> new_index(node_tags.size(), -1);
  mesh.rest.resize(static_cast<Eigen::Index>(kept_positions.size()), 3);
  for (std::size_t v = 0; v < kept_positions.size(); ++v) {
    const auto position = static_cast<std::size_t>(kept_positions[v]);
    new_index[position] = static_cast<Index>(v);
    for (int d = 0; d < 3; ++d) {
      mesh.rest(static_cast<Eigen::Index>(v), d) = node_coordinates[3 * position + d];
    }
  }
  const auto num_tets = static_cast<Eigen::Index>(tet_regions.size());
  mesh.tets.resize(num_tets, 4);
  for (Eigen::Index t = 0; t < num_tets; ++t) {
    for (int k = 0; k < 4; ++k) mesh.tets(t, k) = new_index[tet_nodes[4 * t + k]];
  }
  mesh.region = Eigen::Map<const IndexVector>(tet_regions.data(), num_tets);
  reject_non_finite_nodes(mesh.rest, node_tags, kept_positions);
  reject_folded_tets(mesh.rest, mesh.tets);
  orient_positively(mesh.rest, mesh.tets);

  const auto mapped_node = [&](std::size_t tag) {
    const Index position = node_position.position(tag);
    return position < 0 ? Index{-1} : new_index[position];
  };

  // Node sets (dimensions 0-2) and face sets (dimension 2).
  gmsh::vectorpair set_groups;
  gmsh::model::getPhysicalGroups(set_groups);
  std::sort(set_groups.begin(), set_groups.end());
  for (const auto& [dim, tag] : set_groups) {
    if (dim > 2) continue;
    const std::string name = physical_group_name(dim, tag);

    std::vector<std::size_t> group_node_tags;
    std::vector<double> unused_coordinates;
    gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, group_node_tags, unused_coordinates);
    auto& nodes = mesh.node_sets[name];
    for (const std::size_t node_tag : group_node_tags) {
      const Index node = mapped_node(node_tag);
      if (node >= 0) nodes.push_back(node);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());

    if (dim != 2) continue;
    std::vector<Index> corners;
    std::vector<int> surfaces;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, surfaces);
    for (const int surface : surfaces) {
      std::vector<std::size_t> element_tags;
      std::vector<std::size_t> element_nodes;
      gmsh::model::mesh::getElementsByType(kGmshTriangle, element_tags, element_nodes, surface);
      for (std::size_t f = 0; f < element_tags.size(); ++f) {
        const std::array<Index, 3> triangle = {mapped_node(element_nodes[3 * f]),
                                               mapped_node(element_nodes[3 * f + 1]),
                                               mapped_node(element_nodes[3 * f + 2])};
        if (std::all_of(triangle.begin(), triangle.end(), [](Index v) { return v >= 0; })) {
          corners.insert(corners.end(), triangle.begin(), triangle.end());
        }
      }
    }
    const Triangles triangles = orient_like_boundary(
        mesh.tets, Eigen::Map<const Triangles>(corners.data(),
                                               static_cast<Eigen::Index>(corners.size() / 3), 3));
    auto existing = mesh.face_sets.find(name);
    if (existing == mesh.face_sets.end()) {
      mesh.face_sets[name] = triangles;
    } else {
      existing->second = append_rows(existing->second, triangles);
    }
  }

  std::vector<std::size_t> kept_tags(kept_positions.size());
  for (std::size_t v = 0; v < kept_positions.size(); ++v) kept_tags[v] = node_tags[kept_positions[v]];
  read_node_fields(mesh, kept_tags);
  return mesh;
}

std::vector<std::string> gmsh_element_type_names(int dim, const std::vector<int>& excluded_types) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, dim);
  std::vector<std::string> names;
  for (const int type : types) {
    if (std::find(excluded_types.begin(), excluded_types.end(), type) != excluded_types.end()) {
      continue;
    }
    std::string name;
    int dim = 0;
    int order = 0;
    int num_nodes = 0;
    int num_primary_nodes = 0;
    std::vector<double> local_coordinates;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, num_nodes, local_coordinates,
                                            num_primary_nodes);
    names.push_back(name);
  }
  return names;
}

}  // namespace sinew::mesh
