#pragma once
/// @file key_groups.hpp
/// Sort-based matching of small index tuples (tet faces, edges, tets): the engine behind
/// boundary extraction, interface extraction and the duplicate/manifold checks of validate().
/// Linear-time bucketing by the smallest index followed by tiny per-bucket sorts; no maps.

#include <array>
#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::mesh {

/// Local faces of a tet, face f opposite node f. For a positively oriented tet each face
/// (a, b, c) has its normal (xb - xa) x (xc - xa) pointing out of the tet.
inline constexpr std::array<std::array<int, 3>, 4> kTetFaceCorners = {{
    {{1, 2, 3}},
    {{0, 3, 2}},
    {{0, 1, 3}},
    {{0, 2, 1}},
}};

/// Groups of equal keys. `order` is a permutation of the key indices 0..#keys-1 in which equal
/// keys are adjacent and, within a group, ascending; group g is
/// order[offsets[g] .. offsets[g+1]). Groups are ordered by key (lexicographically).
struct KeyGroups {
  std::vector<Index> order;    ///< #keys
  std::vector<Index> offsets;  ///< #groups + 1
  Index num_groups() const { return static_cast<Index>(offsets.size()) - 1; }
  Index group_size(Index g) const { return offsets[g + 1] - offsets[g]; }
};

/// Groups equal keys. Every key must be sorted ascending with entries in [0, num_values).
/// Cost O(#keys + num_values) plus sorts of the keys sharing a smallest entry.
template <int N>
KeyGroups group_equal_keys(const std::vector<std::array<Index, N>>& keys, Index num_values);

/// The 4 #T faces of the tets as sorted node triples; face f of tet t is entry 4 t + f
/// (see kTetFaceCorners).
std::vector<std::array<Index, 3>> sorted_tet_face_keys(const Tets& tets);

/// The tet faces grouped by node set: a boundary face forms a group of one, an interior face a
/// group of two. Face ids are 4 t + f.
KeyGroups group_tet_faces(const Tets& tets, Index num_nodes);

/// Ids (4 t + f) of the faces that form a group of one in `faces` (boundary faces), ascending.
std::vector<Index> boundary_face_ids(const KeyGroups& faces);

/// The faces with the given ids (4 t + f) as triangles with the orientation of
/// kTetFaceCorners, in the given order. #ids x 3.
Triangles faces_as_triangles(const Tets& tets, const std::vector<Index>& face_ids);

/// Face f of tet t with the orientation of kTetFaceCorners (outward for a positive tet).
inline std::array<Index, 3> tet_face(const Tets& tets, Index t, int f) {
  const auto& corners = kTetFaceCorners[static_cast<std::size_t>(f)];
  return {tets(t, corners[0]), tets(t, corners[1]), tets(t, corners[2])};
}

/// One more than the largest node index of the tets (0 when there are none).
Index node_count_bound(const Tets& tets);

}  // namespace sinew::mesh
