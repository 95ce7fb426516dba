#pragma once
/// @file tet_quality.hpp
/// Shape quality of tetrahedra: dihedral angles and the radius ratio (docs/surface-input.md,
/// mesh quality).

#include "sinew/core/types.hpp"

namespace sinew::mesh {

/// Quality of one tet, from its four corners.
struct TetShape {
  double min_dihedral_deg = 0;  ///< smallest of the six dihedral angles (degrees); 70.53 for a regular tet
  double max_dihedral_deg = 0;  ///< largest (degrees)
  double radius_ratio = 0;      ///< 3 r_in / R_circumscribed, in [0, 1]; 1 for a regular tet
};

/// The shape of tet t of (x, tets). x: #V x 3.
TetShape tet_shape(const Positions& x, const Tets& tets, Index t);

/// The worst shapes over a mesh.
struct MeshQuality {
  double min_dihedral_deg = 180;     ///< smallest dihedral angle of any tet
  double max_dihedral_deg = 0;       ///< largest dihedral angle of any tet
  double worst_radius_ratio = 1;     ///< smallest radius ratio of any tet
  double mean_radius_ratio = 0;
  Index worst_tet = -1;              ///< the tet of the smallest dihedral angle
  Index slivers = 0;                 ///< tets whose smallest dihedral angle is below `sliver_angle_deg`
};

/// Quality over all tets; a tet counts as a sliver below `sliver_angle_deg` (degrees).
MeshQuality mesh_quality(const Positions& x, const Tets& tets, double sliver_angle_deg = 5.0);

}  // namespace sinew::mesh
