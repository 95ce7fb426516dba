#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "sinew/core/error.hpp"
#include "sinew/mesh/key_groups.hpp"
#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

namespace {

/// How many offending items a message lists.
constexpr std::size_t kListedItems = 3;

/// "tet 17 (1-based 18, nodes 3 5 9 12)"
std::string describe_tet(const Tets& tets, Index t) {
  std::ostringstream out;
  out << "tet " << t << " (1-based " << t + 1 << ", nodes " << tets(t, 0) << ' ' << tets(t, 1)
      << ' ' << tets(t, 2) << ' ' << tets(t, 3) << ')';
  return out.str();
}

/// "node 4 (1-based 5) at (1, 0, 0)"
std::string describe_node(const Positions& x, Index v) {
  std::ostringstream out;
  out << "node " << v << " (1-based " << v + 1 << ") at (" << x(v, 0) << ", " << x(v, 1) << ", "
      << x(v, 2) << ')';
  return out.str();
}

/// "3 inverted tetrahedra (negative volume), first: a, b, c"; problems are joined by "; ".
std::string count_and_first(std::size_t count, const std::string& singular,
                            const std::string& plural, const std::vector<std::string>& first) {
  std::string message = std::to_string(count) + " " + (count == 1 ? singular : plural) +
                        (count == 1 ? ": " : ", first: ");
  for (std::size_t i = 0; i < first.size(); ++i) message += (i ? ", " : "") + first[i];
  return message;
}

class Problems {
 public:
  explicit Problems(std::string what) : prefix_("mesh \"" + std::move(what) + "\": ") {}
  void add(std::string problem) { problems_.push_back(std::move(problem)); }
  /// Throws one InputError listing every problem added so far.
  void throw_if_any() const {
    if (problems_.empty()) return;
    std::string message = prefix_;
    for (std::size_t i = 0; i < problems_.size(); ++i) message += (i ? "; " : "") + problems_[i];
    throw InputError(message);
  }

 private:
  std::string prefix_;
  std::vector<std::string> problems_;
};

/// Collects offenders: counts all, keeps the descriptions of the first few.
struct Offenders {
  std::size_t count = 0;
  std::vector<std::string> first;
  template <class Describe>
  void add_lazily(Describe&& describe) {
    if (count++ < kListedItems) first.push_back(describe());
  }
};

void check_indices(const TetMesh& mesh, Problems& problems) {
  const Index num_nodes = mesh.num_nodes();
  Offenders non_finite;
  for (Index v = 0; v < num_nodes; ++v) {
    if (!mesh.rest.row(v).allFinite())
      non_finite.add_lazily([&] { return describe_node(mesh.rest, v); });
  }
  if (non_finite.count) {
    problems.add(count_and_first(non_finite.count, "node with a non-finite coordinate",
                                 "nodes with non-finite coordinates", non_finite.first));
  }

  Offenders out_of_range;
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    for (int k = 0; k < 4; ++k) {
      if (mesh.tets(t, k) < 0 || mesh.tets(t, k) >= num_nodes) {
        out_of_range.add_lazily([&] { return describe_tet(mesh.tets, t); });
        break;
      }
    }
  }
  if (out_of_range.count) {
    problems.add(count_and_first(out_of_range.count, "tetrahedron with a node index",
                                 "tetrahedra with node indices", out_of_range.first) +
                 " (out of range: the mesh has " + std::to_string(num_nodes) + " nodes)");
  }

  const auto num_regions = static_cast<Index>(mesh.region_names.size());
  if (mesh.region.size() != mesh.tets.rows()) {
    problems.add("the region vector has " + std::to_string(mesh.region.size()) + " entries for " +
                 std::to_string(mesh.tets.rows()) + " tetrahedra");
  } else {
    Offenders bad_region;
    for (Index t = 0; t < mesh.num_tets(); ++t) {
      if (mesh.region(t) < 0 || mesh.region(t) >= num_regions) {
        bad_region.add_lazily([&] {
          return "tet " + std::to_string(t) + " has region id " + std::to_string(mesh.region(t));
        });
      }
    }
    if (bad_region.count) {
      problems.add(count_and_first(bad_region.count, "tetrahedron with a region id",
                                   "tetrahedra with region ids", bad_region.first) +
                   " (out of range: the mesh has " + std::to_string(num_regions) + " regions)");
    }
  }

  for (const auto& [name, nodes] : mesh.node_sets) {
    for (const Index v : nodes) {
      if (v < 0 || v >= num_nodes) {
        problems.add("node set \"" + name + "\" holds node index " + std::to_string(v) +
                     " (out of range: the mesh has " + std::to_string(num_nodes) + " nodes)");
        break;
      }
    }
  }
  for (const auto& [name, triangles] : mesh.face_sets) {
    if (triangles.size() && (triangles.minCoeff() < 0 || triangles.maxCoeff() >= num_nodes)) {
      problems.add("face set \"" + name + "\" holds a node index out of range (the mesh has " +
                   std::to_string(num_nodes) + " nodes)");
    }
  }
  for (const auto& [name, values] : mesh.node_fields) {
    if (values.size() != num_nodes) {
      problems.add("node field \"" + name + "\" has " + std::to_string(values.size()) +
                   " values (the mesh has " + std::to_string(num_nodes) + " nodes)");
    }
  }
}

void check_volumes(const TetMesh& mesh, const ValidationOptions& options, Problems& problems) {
  std::vector<double> volumes(static_cast<std::size_t>(mesh.num_tets()));
  double sum_abs = 0;
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    volumes[t] = signed_volume(mesh.rest, mesh.tets, t);
    sum_abs += std::abs(volumes[t]);
  }
  const double zero_threshold = options.rel_volume_tolerance * sum_abs / mesh.num_tets();
  Offenders inverted;
  Offenders flat;
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    const auto describe = [&] {
      std::ostringstream out;
      out << describe_tet(mesh.tets, t) << " volume " << volumes[t];
      return out.str();
    };
    if (std::abs(volumes[t]) <= zero_threshold) {
      flat.add_lazily(describe);
    } else if (volumes[t] < 0) {
      inverted.add_lazily(describe);
    }
  }
  if (inverted.count) {
    problems.add(count_and_first(inverted.count, "inverted tetrahedron (negative volume)",
                                 "inverted tetrahedra (negative volume)", inverted.first));
  }
  if (flat.count) {
    std::ostringstream rule;
    rule << " (|volume| <= " << options.rel_volume_tolerance << " x mean |volume|)";
    problems.add(count_and_first(flat.count, "zero-volume tetrahedron" + rule.str(),
                                 "zero-volume tetrahedra" + rule.str(), flat.first));
  }
}

void check_duplicates(const TetMesh& mesh, Problems& problems) {
  std::vector<std::array<Index, 4>> keys(static_cast<std::size_t>(mesh.num_tets()));
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    keys[t] = {mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)};
    std::sort(keys[t].begin(), keys[t].end());
  }
  const KeyGroups groups = group_equal_keys<4>(keys, mesh.num_nodes());
  Offenders duplicates;
  for (Index g = 0; g < groups.num_groups(); ++g) {
    const Index original = groups.order[groups.offsets[g]];
    for (Index i = groups.offsets[g] + 1; i < groups.offsets[g + 1]; ++i) {
      duplicates.add_lazily([&] {
        return describe_tet(mesh.tets, groups.order[i]) + " repeats tet " +
               std::to_string(original) + " (1-based " + std::to_string(original + 1) + ")";
      });
    }
  }
  if (duplicates.count) {
    problems.add(count_and_first(duplicates.count, "duplicate tetrahedron (same four nodes)",
                                 "duplicate tetrahedra (same four nodes)", duplicates.first));
  }
}

/// Union-find with path halving.
struct DisjointSets {
  std::vector<Index> parent;
  explicit DisjointSets(std::size_t size) : parent(size) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  Index find(Index i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(Index a, Index b) { parent[find(a)] = find(b); }
};

void check_manifold(const TetMesh& mesh, const ValidationOptions& options, Problems& problems) {
  // Faces shared by more than two tets.
  const KeyGroups faces = group_tet_faces(mesh.tets, mesh.num_nodes());
  Offenders crowded_faces;
  for (Index g = 0; g < faces.num_groups(); ++g) {
    if (faces.group_size(g) <= 2) continue;
    crowded_faces.add_lazily([&] {
      const Index face = faces.order[faces.offsets[g]];
      const auto corners = tet_face(mesh.tets, face / 4, face % 4);
      std::string description = "face (" + std::to_string(corners[0]) + ", " +
                                std::to_string(corners[1]) + ", " + std::to_string(corners[2]) +
                                ") of tets";
      for (Index i = faces.offsets[g]; i < faces.offsets[g + 1]; ++i) {
        description += " " + std::to_string(faces.order[i] / 4);
      }
      return description;
    });
  }
  if (crowded_faces.count) {
    problems.add(count_and_first(crowded_faces.count, "face shared by more than two tetrahedra",
                                 "faces shared by more than two tetrahedra", crowded_faces.first) +
                 " (non-manifold)");
    return;
  }
  if (!options.check_boundary_manifold) return;

  // Boundary edges must each join exactly two boundary triangles.
  const Triangles boundary = faces_as_triangles(mesh.tets, boundary_face_ids(faces));
  const auto num_triangles = static_cast<Index>(boundary.rows());
  std::vector<std::array<Index, 2>> edge_keys(static_cast<std::size_t>(num_triangles) * 3);
  for (Index f = 0; f < num_triangles; ++f) {
    for (int e = 0; e < 3; ++e) {
      const Index a = boundary(f, e);
      const Index b = boundary(f, (e + 1) % 3);
      edge_keys[3 * f + e] = {std::min(a, b), std::max(a, b)};
    }
  }
  const KeyGroups edges = group_equal_keys<2>(edge_keys, mesh.num_nodes());
  Offenders bad_edges;
  for (Index g = 0; g < edges.num_groups(); ++g) {
    if (edges.group_size(g) == 2) continue;
    bad_edges.add_lazily([&] {
      const auto& key = edge_keys[edges.order[edges.offsets[g]]];
      return "edge (" + std::to_string(key[0]) + ", " + std::to_string(key[1]) + ") in " +
             std::to_string(edges.group_size(g)) + " boundary triangles";
    });
  }
  if (bad_edges.count) {
    problems.add(count_and_first(bad_edges.count,
                                 "boundary edge not shared by exactly two boundary triangles",
                                 "boundary edges not shared by exactly two boundary triangles",
                                 bad_edges.first) +
                 " (non-manifold boundary: bodies touching along an edge?)");
    return;
  }

  // Around each boundary node the boundary triangles must form a single fan. Corner 3 f + k is
  // node boundary(f, k); corners of the same node are joined across each shared edge.
  DisjointSets fans(static_cast<std::size_t>(num_triangles) * 3);
  const auto corner_of = [&boundary](Index f, Index node) {
    for (int k = 0; k < 3; ++k) {
      if (boundary(f, k) == node) return 3 * f + k;
    }
    return Index{-1};  // unreachable: the edge's nodes are corners of f
  };
  for (Index g = 0; g < edges.num_groups(); ++g) {
    const Index edge_1 = edges.order[edges.offsets[g]];
    const Index edge_2 = edges.order[edges.offsets[g] + 1];
    for (const Index node : edge_keys[edge_1]) {
      fans.unite(corner_of(edge_1 / 3, node), corner_of(edge_2 / 3, node));
    }
  }
  std::vector<Index> fan_of_node(static_cast<std::size_t>(mesh.num_nodes()), -1);
  std::vector<char> pinched(static_cast<std::size_t>(mesh.num_nodes()), 0);
  for (Index corner = 0; corner < 3 * num_triangles; ++corner) {
    const Index node = boundary(corner / 3, corner % 3);
    const Index fan = fans.find(corner);
    if (fan_of_node[node] < 0) {
      fan_of_node[node] = fan;
    } else if (fan_of_node[node] != fan) {
      pinched[node] = 1;
    }
  }
  Offenders pinched_nodes;
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    if (pinched[v]) pinched_nodes.add_lazily([&] { return describe_node(mesh.rest, v); });
  }
  if (pinched_nodes.count) {
    problems.add(count_and_first(pinched_nodes.count,
                                 "boundary node where separate sheets of the boundary meet",
                                 "boundary nodes where separate sheets of the boundary meet",
                                 pinched_nodes.first) +
                 " (non-manifold boundary: bodies touching at a single point?)");
  }
}

}  // namespace

void validate(const TetMesh& mesh, const std::string& what, const ValidationOptions& options) {
  Problems problems(what);
  if (mesh.num_tets() == 0) {
    problems.add("no tetrahedra");
    problems.throw_if_any();
  }
  check_indices(mesh, problems);
  problems.throw_if_any();  // the checks below index nodes and regions
  check_volumes(mesh, options, problems);
  check_duplicates(mesh, problems);
  problems.throw_if_any();
  check_manifold(mesh, options, problems);
  problems.throw_if_any();
}

}  // namespace sinew::mesh
