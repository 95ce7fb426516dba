#include "sinew/parallel/partition.hpp"

#include <petscmat.h>
#include <scotch.h>

#include <algorithm>
#include <cstdlib>
#include <array>
#include <string>

#include "sinew/core/error.hpp"
#include "sinew/core/share.hpp"
#include "sinew/parallel/petsc.hpp"
#include "sinew/parallel/ranks.hpp"

namespace sinew::parallel {
namespace {

using MatHandle = PetscHandle<Mat, MatDestroy>;
using PartitioningHandle = PetscHandle<MatPartitioning, MatPartitioningDestroy>;
using IsHandle = PetscHandle<IS, ISDestroy>;

/// The dual graph's neighbours of every tet, as compressed rows (#T + 1 starts, neighbours):
/// tets that share a face (sorted node triple), in increasing order, never the tet itself.
void dual_graph(const Tets& tets, std::vector<Index>& starts, std::vector<Index>& neighbours) {
  constexpr std::array<std::array<int, 3>, 4> kFaces{{{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}};
  struct Face {
    std::array<Index, 3> nodes;
    Index tet;
  };
  std::vector<Face> faces;
  faces.reserve(static_cast<std::size_t>(4 * tets.rows()));
  for (Index t = 0; t < tets.rows(); ++t)
    for (const auto& corners : kFaces) {
      Face face{{tets(t, corners[0]), tets(t, corners[1]), tets(t, corners[2])}, t};
      std::sort(face.nodes.begin(), face.nodes.end());
      faces.push_back(face);
    }
  std::sort(faces.begin(), faces.end(),
            [](const Face& a, const Face& b) { return a.nodes != b.nodes ? a.nodes < b.nodes : a.tet < b.tet; });
  std::vector<std::pair<Index, Index>> edges;  // both directions
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].nodes == faces[i].nodes) ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = a + 1; b < j; ++b)
        if (faces[a].tet != faces[b].tet) {
          edges.emplace_back(faces[a].tet, faces[b].tet);
          edges.emplace_back(faces[b].tet, faces[a].tet);
        }
    i = j;
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  starts.assign(static_cast<std::size_t>(tets.rows()) + 1, 0);
  neighbours.clear();
  neighbours.reserve(edges.size());
  for (const auto& [from, to] : edges) {
    ++starts[static_cast<std::size_t>(from) + 1];
    neighbours.push_back(to);
  }
  for (std::size_t t = 0; t + 1 < starts.size(); ++t) starts[t + 1] += starts[t];
}

/// A PetscMalloc'ed copy of `values` (MatCreateMPIAdj and the vertex weights take ownership).
PetscInt* petsc_copy(const PetscInt* values, std::size_t count) {
  PetscInt* copy = nullptr;
  check_petsc(PetscMalloc1(std::max<std::size_t>(count, 1), &copy), "PetscMalloc1");
  std::copy(values, values + count, copy);
  return copy;
}

}  // namespace

std::vector<int> partition_tets(const Tets& tets, const std::vector<int>& weights, int parts) {
  const auto num_tets = static_cast<std::size_t>(tets.rows());
  if (!weights.empty() && weights.size() != num_tets)
    throw Error("partition_tets: " + std::to_string(weights.size()) + " weights for " + std::to_string(num_tets) +
                " tets");
  if (std::any_of(weights.begin(), weights.end(), [](int w) { return w < 1; }))
    throw Error("partition_tets: a tet's weight is below 1");
  std::vector<int> owner(num_tets, 0);
  if (parts <= 1) return owner;
  if (num_tets < static_cast<std::size_t>(std::max(parts, size()))) {
    for (int part = 0; part < parts; ++part) {
      const ItemRange range = share_of(num_tets, part, parts);
      std::fill(owner.begin() + static_cast<std::ptrdiff_t>(range.begin),
                owner.begin() + static_cast<std::ptrdiff_t>(range.end), part);
    }
    return owner;
  }

  ensure_petsc();
  std::vector<Index> starts, neighbours;
  dual_graph(tets, starts, neighbours);
  // This rank's rows of the graph: a contiguous share, with local row starts.
  const ItemRange mine = my_share(num_tets);
  const auto first = static_cast<std::size_t>(starts[mine.begin]);
  std::vector<PetscInt> local_starts(mine.end - mine.begin + 1);
  for (std::size_t t = mine.begin; t <= mine.end; ++t)
    local_starts[t - mine.begin] = static_cast<PetscInt>(static_cast<std::size_t>(starts[t]) - first);
  const std::vector<PetscInt> local_neighbours(neighbours.begin() + static_cast<std::ptrdiff_t>(first),
                                               neighbours.begin() + starts[mine.end]);

  MatHandle graph;
  check_petsc(MatCreateMPIAdj(PETSC_COMM_WORLD, static_cast<PetscInt>(mine.end - mine.begin),
                              static_cast<PetscInt>(num_tets), petsc_copy(local_starts.data(), local_starts.size()),
                              petsc_copy(local_neighbours.data(), local_neighbours.size()), nullptr, &*graph),
              "MatCreateMPIAdj");
  PartitioningHandle partitioning;
  check_petsc(MatPartitioningCreate(PETSC_COMM_WORLD, &*partitioning), "MatPartitioningCreate");
  check_petsc(MatPartitioningSetAdjacency(partitioning.get(), graph.get()), "MatPartitioningSetAdjacency");
  check_petsc(MatPartitioningSetType(partitioning.get(), MATPARTITIONINGPTSCOTCH), "MatPartitioningSetType");
  check_petsc(MatPartitioningSetNParts(partitioning.get(), parts), "MatPartitioningSetNParts");
  if (!weights.empty()) {
    const std::vector<PetscInt> local_weights(weights.begin() + static_cast<std::ptrdiff_t>(mine.begin),
                                              weights.begin() + static_cast<std::ptrdiff_t>(mine.end));
    check_petsc(MatPartitioningSetVertexWeights(partitioning.get(),
                                                petsc_copy(local_weights.data(), local_weights.size())),
                "MatPartitioningSetVertexWeights");
  }
  IsHandle local_parts, all_parts;
  // The same graph gets the same partition on every call and in every run (a resumed run cuts
  // its mesh as the first did). Scotch 7's threads race: with its default number of them, a
  // second call cut tests/parallel's bar differently from the first in 11 of 12 runs. One
  // thread (SCOTCH_PTHREAD_NUMBER, read when Scotch starts its threads), and the one random
  // generator of the whole process started afresh.
  ::setenv("SCOTCH_PTHREAD_NUMBER", "1", 1);
  SCOTCH_randomReset();
  check_petsc(MatPartitioningApply(partitioning.get(), &*local_parts), "MatPartitioningApply");
  check_petsc(ISAllGather(local_parts.get(), &*all_parts), "ISAllGather");
  PetscInt count = 0;
  check_petsc(ISGetLocalSize(all_parts.get(), &count), "ISGetLocalSize");
  if (static_cast<std::size_t>(count) != num_tets)
    throw Error("partition_tets: PT-Scotch returned " + std::to_string(count) + " parts for " +
                std::to_string(num_tets) + " tets");
  const PetscInt* part_of = nullptr;
  check_petsc(ISGetIndices(all_parts.get(), &part_of), "ISGetIndices");
  for (std::size_t t = 0; t < num_tets; ++t) owner[t] = static_cast<int>(part_of[t]);
  check_petsc(ISRestoreIndices(all_parts.get(), &part_of), "ISRestoreIndices");
  if (std::any_of(owner.begin(), owner.end(), [&](int p) { return p < 0 || p >= parts; }))
    throw Error("partition_tets: PT-Scotch returned a part out of range");
  return owner;
}

std::vector<int> node_owners(const Tets& tets, const std::vector<int>& tet_owner, Index num_nodes) {
  if (tet_owner.size() != static_cast<std::size_t>(tets.rows()))
    throw Error("node_owners: " + std::to_string(tet_owner.size()) + " owners for " + std::to_string(tets.rows()) +
                " tets");
  std::vector<int> owner(static_cast<std::size_t>(std::max<Index>(num_nodes, 0)), -1);
  for (Index t = 0; t < tets.rows(); ++t)
    for (int c = 0; c < 4; ++c) {
      const Index node = tets(t, c);
      if (node < 0 || node >= num_nodes)
        throw Error("node_owners: tet " + std::to_string(t) + " refers to node " + std::to_string(node) + " of " +
                    std::to_string(num_nodes));
      int& o = owner[static_cast<std::size_t>(node)];
      if (o < 0) o = tet_owner[static_cast<std::size_t>(t)];
    }
  for (int& o : owner) o = std::max(o, 0);
  return owner;
}

}  // namespace sinew::parallel
