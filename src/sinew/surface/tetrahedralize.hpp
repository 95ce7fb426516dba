#pragma once
/// @file tetrahedralize.hpp
/// A multi-region tetrahedral mesh from solids bounded by closed surfaces (CGAL Mesh_3 on a
/// labelled domain; docs/surface-input.md, meshing).

#include <optional>
#include <string>
#include <vector>

#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/mesh/tet_quality.hpp"
#include "sinew/surface/solid.hpp"

namespace sinew::surface {

/// One region of the mesh: the points of `solid` not claimed by an earlier part.
struct SolidPart {
  std::string region;
  Solid solid;
};

/// The points within `radius` of the segment a-b (length): a size zone that is not a surface,
/// such as the insertion of a tendon.
struct ZoneCapsule {
  Vector3 a = Vector3::Zero(), b = Vector3::Zero();
  double radius = 0;
};

/// Finer elements near some surfaces or inside a capsule: the size at a point is
/// min(element_size, size + grading * distance to the nearest of `surfaces` and `capsule`), the
/// distance to the capsule being 0 inside it. A zone has surfaces, a capsule or both.
struct SizeZone {
  std::vector<std::string> surfaces;
  std::optional<ZoneCapsule> capsule;
  double size = 1;     ///< element size on those surfaces and in the capsule (length), > 0
  double grading = 0.3;  ///< growth of the size per unit distance from them (dimensionless), >= 0
};

/// Distance from x to the capsule, 0 inside it (length).
double capsule_distance(const ZoneCapsule& capsule, const Vector3& x);

struct TetrahedralizeOptions {
  double element_size = 1;     ///< target tet edge length away from size zones (length), > 0
  /// Largest distance between a boundary triangle and the surface it approximates (length);
  /// 0 = element_size / 20.
  double facet_distance = 0;
  std::vector<SizeZone> size_zones;
  /// Tets whose smallest dihedral angle stays below this after sliver exudation (degrees) make
  /// the mesh fail with a message; 0 = report only.
  double min_dihedral_deg = 0;
  /// Refuse before meshing when the estimate (estimated_tets) exceeds this; 0 = no limit.
  double max_tets = 0;
  std::string what = "mesh";   ///< names the mesh in messages (e.g. the body)
};

/// What the mesher made.
struct TetrahedralizeReport {
  mesh::MeshQuality quality;
  std::vector<Index> tets_per_region;    ///< by region id
  std::vector<double> region_volumes;    ///< by region id (length^3)
  double seconds = 0;                    ///< wall time of meshing
};

/// An order of magnitude of the tets tetrahedralize makes, before meshing: 6 sqrt(2) V / h^3
/// over the parts' bounding box V at element_size h, plus 6 sqrt(2) A / s^2 for every size zone
/// of size s on surfaces of area A. An upper estimate for parts that fill their box loosely.
double estimated_tets(const std::vector<SolidPart>& parts, const SurfaceLibrary& library,
                      const TetrahedralizeOptions& options);

/// Meshes the parts into one conforming TetMesh with one region per part, in part order (where
/// parts overlap, the first listed wins). The boundary of every region is the face set
/// "<region>.surface". Throws InputError naming options.what when a part gets no tets (it is
/// empty or thinner than the elements), or when the quality bound is not met.
mesh::TetMesh tetrahedralize(const std::vector<SolidPart>& parts, const SurfaceLibrary& library,
                             const TetrahedralizeOptions& options, TetrahedralizeReport* report = nullptr);

}  // namespace sinew::surface
