#pragma once
/// @file constraints_config.hpp
/// Plain descriptions of boundary conditions, rigid bodies and loads, resolved to node
/// indices (the scene module turns names, boxes and planes into these).

#include <string>
#include <vector>

#include "sinew/core/enum_names.hpp"
#include "sinew/fem/motion.hpp"

namespace sinew::fem {

/// Every node of the set follows a rigid motion (fixed = identity motion). 0 free DOFs.
struct PrescribedNodes {
  std::string name;            ///< for logs and reaction-force columns
  std::vector<Index> nodes;    ///< global node indices
  RigidMotion motion;
};

/// Every node of the set keeps n . (x - X) = displacement * amplitude(lambda): it moves only
/// in a plane with unit normal n (which may translate along n). Several such constraints on a
/// node intersect (two planes leave a line, three fix the node).
struct PlanarNodes {
  std::string name;
  std::vector<Index> nodes;
  Vector3 normal = Vector3::UnitZ();  ///< normalized on use
  double displacement = 0;            ///< final normal displacement (length)
  Amplitude amplitude;
};

/// A set of tets that moves as one rigid body. The nodes of these tets (including nodes shared
/// with deformable tets: that is how a rigid part is bonded) follow the body.
struct RigidBody {
  enum class Kind { Fixed, Prescribed, Free };
  std::string name;
  std::vector<Index> tets;     ///< global tet indices
  Kind kind = Kind::Fixed;
  RigidMotion motion;          ///< Prescribed only
};

/// Scene names of RigidBody::Kind ("fixed" and "free" are string values of a region's "rigid",
/// "prescribed" the key of its motion).
inline constexpr NameTable<RigidBody::Kind, 3> kRigidKindNames{{
    {RigidBody::Kind::Fixed, "fixed"},
    {RigidBody::Kind::Prescribed, "prescribed"},
    {RigidBody::Kind::Free, "free"},
}};
constexpr const auto& enum_names(RigidBody::Kind) { return kRigidKindNames; }

/// A constant (dead) force distributed over a node set (total force, force unit): in equal
/// shares, or in the given shares (a traction: each node's tributary boundary area).
struct NodalForce {
  std::string name;
  std::vector<Index> nodes;
  Vector3 total_force = Vector3::Zero();
  Amplitude amplitude;
  std::vector<double> shares;  ///< per entry of `nodes`, summing to 1; empty: equal shares
};

}  // namespace sinew::fem
