#pragma once
/// @file dof_map.hpp
/// The map between Newton's unknowns q and node positions x: free nodes (3 DOFs), nodes
/// held in one or two planes (2 or 1 DOF), prescribed nodes and members of fixed or
/// prescribed rigid bodies (0 DOFs), and members of free rigid bodies (6 DOFs per body:
/// translation, then an incremental rotation vector about the body's current center).
/// It reduces full-space gradients (#V x 3) to q-space; HessianReduction (hessian_reduction.hpp)
/// does the same for Hessians with the q-space pattern it caches.

#include <cstdint>
#include <vector>

#include "sinew/core/energy.hpp"
#include "sinew/core/sparse_matrix.hpp"
#include "sinew/fem/problem.hpp"
#include "sinew/fem/state.hpp"

namespace sinew::fem {

/// The solvers' matrix type, here for the callers that name it fem::SparseMatrix.
using sinew::SparseMatrix;

class DofMap {
 public:
  enum class NodeKind : std::uint8_t { Free, Planar, Prescribed, RigidMember };

  /// Classifies every node. Throws InputError for contradictory constraints (a node in two
  /// rigid bodies, a prescribed rigid-body node, parallel planar constraints).
  explicit DofMap(const Problem& problem);

  Index num_dofs() const { return num_dofs_; }
  NodeKind kind(Index node) const { return node_[static_cast<std::size_t>(node)].kind; }
  /// First q index of a Free or Planar node, or of the free rigid body a member belongs to.
  Index first_dof(Index node) const { return node_[static_cast<std::size_t>(node)].dof; }
  /// Unknowns of a node: 3 Free, 1-2 Planar, 0 Prescribed or member of a fixed/prescribed rigid
  /// body, 6 member of a free rigid body (the body's).
  int num_node_dofs(Index node) const { return node_[static_cast<std::size_t>(node)].ndof; }
  /// Columns of dx_a/dq (3 x num_node_dofs(a)) at the state.
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6> node_jacobian(const State& state, Index a) const;
  std::size_t num_rigid_bodies() const { return rigid_.size(); }
  /// First q index of free rigid body r (translation, then rotation vector), -1 when not free.
  Index rigid_first_dof(std::size_t r) const { return rigid_[r].dof; }
  /// Rest center of rigid body r (mean of its nodes).
  const Vector3& rigid_center(std::size_t r) const { return rigid_[r].center; }
  const std::vector<Index>& rigid_members(std::size_t r) const { return rigid_[r].members; }

  /// Makes `start` (#V x 3 positions and one pose per rigid body, e.g. the end of an earlier
  /// run) the state the motions start from, instead of the rest state: a prescribed node moves
  /// to R(lambda) x_start + t(lambda), a fixed rigid body stays at its start pose, a prescribed
  /// one moves by its motion from its start pose, and a planar constraint's displacement is
  /// measured from the start position. The rest state (the elements' reference) is unchanged.
  /// Throws InputError when the sizes differ or a rigid body's nodes in `start` are not its
  /// pose applied to its rest nodes (to 1e-6 of the body's size).
  void set_start(const State& start);
  /// The state the motions start from: the rest state, or the one set by set_start.
  bool has_start() const { return start_x_.rows() > 0; }
  /// The start state (rest positions, or those of set_start) synced to lambda.
  State initial_state(double lambda) const;
  /// Moves prescribed nodes and fixed/prescribed rigid bodies to lambda, projects planar nodes
  /// onto their planes at lambda, places free rigid bodies' members from their poses.
  void sync(State& state, double lambda) const;

  /// The largest angle (radians) by which a prescribed motion (of nodes or of a rigid body)
  /// turns anything between load parameters `from` and `to` (see RigidMotion::largest_turn).
  double largest_prescribed_turn(double from, double to) const;

  /// q-space gradient J^T g (#dofs) of a full-space gradient g (#V x 3).
  VectorX reduce_gradient(const State& state, const NodalVectors& g) const;

  /// base moved by alpha * dq (dq: #dofs); lambda unchanged.
  State apply_step(const State& base, const VectorX& dq, double alpha) const;
  /// newer + s (newer - older) for free quantities, synced to `lambda` (two-point predictor).
  State extrapolate(const State& older, const State& newer, double s, double lambda) const;

 private:
  /// One per node (20 bytes: most nodes are free, and the planar ones keep their bases apart).
  struct NodeInfo {
    NodeKind kind = NodeKind::Free;
    Index dof = 0;       // first q index (Free/Planar) or the body's (RigidMember of a free body)
    int ndof = 3;        // 3 Free, 1-2 Planar, 0 Prescribed / fixed rigid, 6 free-rigid member
    Index owner = -1;    // prescribed set or rigid body index
    Index planar = -1;   // index into planar_ for a node a planar constraint holds, else -1
  };
  /// A node held by planar constraints.
  struct PlanarInfo {
    Matrix3 basis = Matrix3::Identity();  // first ndof columns span the allowed motion
    std::vector<Index> planes;            // indices into problem.planar
  };
  /// The columns of the node's allowed motion: the identity for a free node.
  const Matrix3& basis(const NodeInfo& node) const;
  struct RigidInfo {
    RigidBody::Kind kind;
    RigidMotion motion;
    Vector3 center = Vector3::Zero();
    std::vector<Index> members;
    Index dof = -1;
  };
  void place_rigid_members(State& state, std::size_t r) const;
  /// Positions the motions start from: the rest positions, or start_x_.
  const Positions& start_positions() const;

  const Problem& problem_;
  std::vector<NodeInfo> node_;
  std::vector<PlanarInfo> planar_;
  std::vector<RigidInfo> rigid_;
  Index num_dofs_ = 0;
  Positions start_x_;                   ///< #V x 3 after set_start, else 0 rows
  std::vector<RigidPose> start_pose_;   ///< one per rigid body (identity without set_start)

};

}  // namespace sinew::fem
