#pragma once
/// @file state.hpp
/// What changes during a solve: node positions, rigid-body poses, and the load parameter (or
/// time) the constraints were synced to.

#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::fem {

/// Pose of one rigid body: x = R (X - center) + center + t.
struct RigidPose {
  Matrix3 R = Matrix3::Identity();
  Vector3 t = Vector3::Zero();
};

/// Everything that changes during a solve.
struct State {
  Positions x;                   ///< #V x 3 current positions, consistent with all constraints
  std::vector<RigidPose> rigid;  ///< one per Problem::rigid_bodies
  double lambda = 0;             ///< load parameter (or time) the constraints were synced to
};

}  // namespace sinew::fem
