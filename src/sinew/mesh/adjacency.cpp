#include <algorithm>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

NodeTetAdjacency node_tet_adjacency(const Tets& tets, Index num_nodes) {
  NodeTetAdjacency adjacency;
  adjacency.offsets.assign(static_cast<std::size_t>(num_nodes) + 1, 0);
  for (Index i = 0; i < tets.size(); ++i) ++adjacency.offsets[tets.data()[i] + 1];
  for (Index v = 0; v < num_nodes; ++v) adjacency.offsets[v + 1] += adjacency.offsets[v];
  adjacency.indices.resize(static_cast<std::size_t>(tets.size()));
  std::vector<Index> next(adjacency.offsets.begin(), adjacency.offsets.end() - 1);
  for (Index t = 0; t < tets.rows(); ++t) {  // ascending t: each list comes out sorted
    for (int k = 0; k < 4; ++k) adjacency.indices[next[tets(t, k)]++] = t;
  }
  return adjacency;
}

NodeNodeAdjacency node_node_adjacency(const Tets& tets, Index num_nodes) {
  // Scatter, reading the tets in order: each tet appends its other three nodes to the list of
  // each of its nodes (random writes are much cheaper than random reads of tet rows).
  std::vector<Index> start(static_cast<std::size_t>(num_nodes) + 1, 0);
  for (Index i = 0; i < tets.size(); ++i) start[tets.data()[i] + 1] += 3;
  for (Index v = 0; v < num_nodes; ++v) start[v + 1] += start[v];
  std::vector<Index> others(static_cast<std::size_t>(start[num_nodes]));
  {
    std::vector<Index> next(start.begin(), start.end() - 1);
    for (Index t = 0; t < tets.rows(); ++t) {
      for (int k = 0; k < 4; ++k) {
        Index* out = others.data() + next[tets(t, k)];
        next[tets(t, k)] += 3;
        for (int j = 1; j < 4; ++j) *out++ = tets(t, (k + j) % 4);
      }
    }
  }

  // Per node: add itself, sort, drop repeats; compact into the CSR arrays.
  NodeNodeAdjacency adjacency;
  adjacency.offsets.reserve(static_cast<std::size_t>(num_nodes) + 1);
  adjacency.indices.reserve(others.size() / 4 + static_cast<std::size_t>(num_nodes));
  adjacency.offsets.push_back(0);
  std::vector<Index> neighbours;
  for (Index v = 0; v < num_nodes; ++v) {
    neighbours.assign(others.begin() + start[v], others.begin() + start[v + 1]);
    neighbours.push_back(v);
    std::sort(neighbours.begin(), neighbours.end());
    const auto end = std::unique(neighbours.begin(), neighbours.end());
    adjacency.indices.insert(adjacency.indices.end(), neighbours.begin(), end);
    adjacency.offsets.push_back(static_cast<Index>(adjacency.indices.size()));
  }
  return adjacency;
}

}  // namespace sinew::mesh
