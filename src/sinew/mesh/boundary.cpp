#include <algorithm>
#include <string>

#include "sinew/core/error.hpp"
#include "sinew/mesh/key_groups.hpp"
#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

Triangles boundary_triangles(const Tets& tets) {
  return faces_as_triangles(tets, boundary_face_ids(group_tet_faces(tets, node_count_bound(tets))));
}

Triangles interface_triangles(const TetMesh& mesh, Index region_a, Index region_b) {
  const auto num_regions = static_cast<Index>(mesh.region_names.size());
  for (const Index region : {region_a, region_b}) {
    if (region < 0 || region >= num_regions) {
      throw InputError("interface_triangles: region id " + std::to_string(region) +
                       " is out of range (the mesh has " + std::to_string(num_regions) +
                       " regions)");
    }
  }
  if (region_a == region_b) {
    throw InputError("interface_triangles: region \"" + mesh.region_names[region_a] +
                     "\" given twice; an interface needs two different regions");
  }
  const KeyGroups faces = group_tet_faces(mesh.tets, node_count_bound(mesh.tets));
  std::vector<Index> face_ids;
  for (Index g = 0; g < faces.num_groups(); ++g) {
    if (faces.group_size(g) != 2) continue;
    const Index first = faces.order[faces.offsets[g]];
    const Index second = faces.order[faces.offsets[g] + 1];
    const Index region_first = mesh.region(first / 4);
    const Index region_second = mesh.region(second / 4);
    if (region_first == region_a && region_second == region_b) face_ids.push_back(first);
    if (region_first == region_b && region_second == region_a) face_ids.push_back(second);
  }
  std::sort(face_ids.begin(), face_ids.end());
  return faces_as_triangles(mesh.tets, face_ids);
}

}  // namespace sinew::mesh
