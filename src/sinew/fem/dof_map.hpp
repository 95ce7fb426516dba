#pragma once
/// @file dof_map.hpp
/// The map between Newton's unknowns q and node positions x: free nodes (3 DOFs), nodes
/// held in one or two planes (2 or 1 DOF), prescribed nodes and members of fixed or
/// prescribed rigid bodies (0 DOFs), and members of free rigid bodies (6 DOFs per body:
/// translation, then an incremental rotation vector about the body's current center).
/// It reduces full-space gradients and Hessians (#V x 3, 3x3 node blocks) to q-space,
/// including the second-order term of the rotation map.

#include <Eigen/SparseCore>
#include <vector>

#include "sinew/core/block_sparse_matrix.hpp"
#include "sinew/core/energy.hpp"
#include "sinew/fem/problem.hpp"

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

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class DofMap {
 public:
  enum class NodeKind : std::uint8_t { Free, Planar, Prescribed, RigidMember };

  /// Classifies every node. Throws InputError for contradictory constraints (a node in two
  /// rigid bodies, a prescribed rigid-body node, parallel planar constraints).
  explicit DofMap(const Problem& problem);

  Index num_dofs() const { return num_dofs_; }
  NodeKind kind(Index node) const { return node_[static_cast<std::size_t>(node)].kind; }
  /// Rest center of rigid body r (mean of its nodes).
  const Vector3& rigid_center(std::size_t r) const { return rigid_[r].center; }
  const std::vector<Index>& rigid_members(std::size_t r) const { return rigid_[r].members; }

  /// Rest positions synced to lambda.
  State initial_state(double lambda) const;
  /// Moves prescribed nodes and fixed/prescribed rigid bodies to lambda, projects planar nodes
  /// onto their planes at lambda, places free rigid bodies' members from their poses.
  void sync(State& state, double lambda) const;

  /// The largest angle (radians) by which a prescribed motion (of nodes or of a rigid body)
  /// turns anything between load parameters `from` and `to` (see RigidMotion::largest_turn).
  double largest_prescribed_turn(double from, double to) const;

  /// q-space gradient J^T g (#dofs) of a full-space gradient g (#V x 3).
  VectorX reduce_gradient(const State& state, const NodalVectors& g) const;

  /// Builds the q-space pattern for H's pattern (call when H.pattern_version() changes).
  void bind_pattern(const BlockSparseMatrix& H);
  /// K = J^T H J + (rotation second-order terms from g) + diag(viscosity) in q-space; K keeps
  /// the same sparsity pattern between calls (values overwritten). `viscosity`: per node (#V),
  /// or empty.
  void reduce_hessian(const State& state, const BlockSparseMatrix& H, const NodalVectors& g,
                      const VectorX& node_viscosity, SparseMatrix& K) const;

  /// base moved by alpha * dq (dq: #dofs); lambda unchanged.
  State apply_step(const State& base, const VectorX& dq, double alpha) const;
  /// newer + s (newer - older) for free quantities, synced to `lambda` (two-point predictor).
  State extrapolate(const State& older, const State& newer, double s, double lambda) const;

 private:
  struct NodeInfo {
    NodeKind kind = NodeKind::Free;
    Index dof = 0;       // first q index (Free/Planar) or the body's (RigidMember of a free body)
    int ndof = 3;        // 3 Free, 1-2 Planar, 0 Prescribed / fixed rigid, 6 free-rigid member
    Index owner = -1;    // prescribed set or rigid body index
    Matrix3 basis = Matrix3::Identity();  // Planar: first ndof columns span the allowed motion
    std::vector<Index> planes;            // Planar: indices into problem.planar
  };
  struct RigidInfo {
    RigidBody::Kind kind;
    RigidMotion motion;
    Vector3 center = Vector3::Zero();
    std::vector<Index> members;
    Index dof = -1;
  };
  /// Columns of dx_a/dq (3 x ndof) at the state.
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6> node_jacobian(const State& state, Index a) const;
  void place_rigid_members(State& state, std::size_t r) const;

  const Problem& problem_;
  std::vector<NodeInfo> node_;
  std::vector<RigidInfo> rigid_;
  Index num_dofs_ = 0;

  // reduced pattern
  std::uint64_t bound_version_ = 0;
  SparseMatrix pattern_;
  std::vector<Index> block_target_offset_;  // per H block, into targets_
  std::vector<Index> targets_;              // value indices into K, row-major per block
  std::vector<Index> diagonal_target_;      // per dof, value index of (i, i)
};

}  // namespace sinew::fem
