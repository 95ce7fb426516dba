#include "sinew/mesh/key_groups.hpp"

#include <algorithm>

namespace sinew::mesh {

namespace {

/// Insertion sort for the few dozen keys of a typical bucket, std::sort beyond.
template <class Iterator>
void sort_small_range(Iterator begin, Iterator end) {
  constexpr std::ptrdiff_t kInsertionSortLimit = 48;
  if (end - begin > kInsertionSortLimit) {
    std::sort(begin, end);
    return;
  }
  for (Iterator i = begin + (begin != end); i < end; ++i) {
    auto value = *i;
    Iterator j = i;
    for (; j > begin && value < *(j - 1); --j) *j = *(j - 1);
    *j = value;
  }
}

}  // namespace

template <int N>
KeyGroups group_equal_keys(const std::vector<std::array<Index, N>>& keys, Index num_values) {
  const auto num_keys = static_cast<Index>(keys.size());

  // Counting sort by the smallest entry, moving whole entries (key and index) so that the
  // sorts below work on contiguous memory: bucket v holds the keys whose first entry is v.
  struct Entry {
    std::array<Index, N> key;
    Index index;
    /// Entry-wise loops: std::array's operators call memcmp, which dominated the profile.
    bool same_key(const Entry& other) const {
      for (int i = 0; i < N; ++i) {
        if (key[i] != other.key[i]) return false;
      }
      return true;
    }
    bool operator<(const Entry& other) const {
      for (int i = 1; i < N; ++i) {  // entry 0 is the bucket's, equal
        if (key[i] != other.key[i]) return key[i] < other.key[i];
      }
      return index < other.index;
    }
  };
  std::vector<Index> bucket_start(static_cast<std::size_t>(num_values) + 1, 0);
  for (const auto& key : keys) ++bucket_start[static_cast<std::size_t>(key[0]) + 1];
  for (Index v = 0; v < num_values; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<Entry> entries(keys.size());
  {
    std::vector<Index> next(bucket_start.begin(), bucket_start.end() - 1);
    for (Index k = 0; k < num_keys; ++k) entries[next[keys[k][0]]++] = Entry{keys[k], k};
  }

  // Within a bucket, sort by the whole key (ties by key index, so groups come out ascending)
  // and cut runs of equal keys into groups.
  KeyGroups groups;
  groups.order.resize(keys.size());
  groups.offsets.reserve(keys.size() / 2 + 1);
  for (Index v = 0; v < num_values; ++v) {
    const Index begin = bucket_start[v];
    const Index end = bucket_start[v + 1];
    sort_small_range(entries.begin() + begin, entries.begin() + end);
    for (Index i = begin; i < end; ++i) {
      groups.order[i] = entries[i].index;
      if (i == begin || !entries[i].same_key(entries[i - 1])) groups.offsets.push_back(i);
    }
  }
  groups.offsets.push_back(num_keys);
  return groups;
}

template KeyGroups group_equal_keys<2>(const std::vector<std::array<Index, 2>>&, Index);
template KeyGroups group_equal_keys<3>(const std::vector<std::array<Index, 3>>&, Index);
template KeyGroups group_equal_keys<4>(const std::vector<std::array<Index, 4>>&, Index);

std::vector<std::array<Index, 3>> sorted_tet_face_keys(const Tets& tets) {
  std::vector<std::array<Index, 3>> keys(static_cast<std::size_t>(tets.rows()) * 4);
  for (Index t = 0; t < tets.rows(); ++t) {
    for (int f = 0; f < 4; ++f) {
      auto key = tet_face(tets, t, f);
      // Three-element sorting network.
      if (key[0] > key[1]) std::swap(key[0], key[1]);
      if (key[1] > key[2]) std::swap(key[1], key[2]);
      if (key[0] > key[1]) std::swap(key[0], key[1]);
      keys[static_cast<std::size_t>(4 * t + f)] = key;
    }
  }
  return keys;
}

KeyGroups group_tet_faces(const Tets& tets, Index num_nodes) {
  return group_equal_keys<3>(sorted_tet_face_keys(tets), num_nodes);
}

std::vector<Index> boundary_face_ids(const KeyGroups& faces) {
  // Mark the faces that form a group of one, then list them in id (tet) order.
  std::vector<char> on_boundary(faces.order.size(), 0);
  for (Index g = 0; g < faces.num_groups(); ++g) {
    if (faces.group_size(g) == 1) on_boundary[faces.order[faces.offsets[g]]] = 1;
  }
  std::vector<Index> ids;
  for (std::size_t id = 0; id < on_boundary.size(); ++id) {
    if (on_boundary[id]) ids.push_back(static_cast<Index>(id));
  }
  return ids;
}

Triangles faces_as_triangles(const Tets& tets, const std::vector<Index>& face_ids) {
  Triangles triangles(static_cast<Eigen::Index>(face_ids.size()), 3);
  for (std::size_t i = 0; i < face_ids.size(); ++i) {
    const auto face = tet_face(tets, face_ids[i] / 4, face_ids[i] % 4);
    triangles.row(static_cast<Eigen::Index>(i)) << face[0], face[1], face[2];
  }
  return triangles;
}

Index node_count_bound(const Tets& tets) { return tets.size() == 0 ? 0 : tets.maxCoeff() + 1; }

}  // namespace sinew::mesh
