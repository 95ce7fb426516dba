#include "sinew/fem/dof_map.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>
#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::fem {
namespace {

Matrix3 cross_matrix(const Vector3& v) {
  Matrix3 M;
  M << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return M;
}

Matrix3 rotation_from_vector(const Vector3& w) {
  const double angle = w.norm();
  if (angle == 0) return Matrix3::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

Vector3 rotation_to_vector(const Matrix3& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

}  // namespace

DofMap::DofMap(const Problem& problem) : problem_(problem) {
  const Index n = problem.mesh.num_nodes();
  node_.assign(static_cast<std::size_t>(n), NodeInfo{});

  // Rigid bodies claim the nodes of their tets.
  rigid_.resize(problem.rigid_bodies.size());
  for (std::size_t r = 0; r < problem.rigid_bodies.size(); ++r) {
    const RigidBody& body = problem.rigid_bodies[r];
    RigidInfo& info = rigid_[r];
    info.kind = body.kind;
    info.motion = body.motion;
    std::vector<Index> members;
    for (Index t : body.tets)
      for (int i = 0; i < 4; ++i) members.push_back(problem.mesh.tets(t, i));
    std::sort(members.begin(), members.end());
    members.erase(std::unique(members.begin(), members.end()), members.end());
    for (Index a : members) {
      NodeInfo& node = node_[a];
      if (node.kind == NodeKind::RigidMember)
        throw InputError(fmt::format("node {} belongs to two rigid bodies, \"{}\" and \"{}\"; a node can follow "
                                     "only one rigid body",
                                     a, problem.rigid_bodies[node.owner].name, body.name));
      node.kind = NodeKind::RigidMember;
      node.owner = static_cast<Index>(r);
      node.ndof = 0;
      info.center += problem.mesh.rest.row(a).transpose();
    }
    if (members.empty()) throw InputError(fmt::format("rigid body \"{}\" has no nodes", body.name));
    info.center /= static_cast<double>(members.size());
    info.members = std::move(members);
  }

  for (std::size_t s = 0; s < problem.prescribed.size(); ++s) {
    const PrescribedNodes& set = problem.prescribed[s];
    for (Index a : set.nodes) {
      NodeInfo& node = node_[a];
      if (node.kind == NodeKind::RigidMember)
        throw InputError(fmt::format("boundary condition \"{}\" prescribes node {}, which belongs to rigid body "
                                     "\"{}\"; prescribe the rigid body's motion instead",
                                     set.name, a, problem.rigid_bodies[node.owner].name));
      if (node.kind == NodeKind::Prescribed && node.owner != static_cast<Index>(s))
        throw InputError(fmt::format("node {} is prescribed by both \"{}\" and \"{}\"", a,
                                     problem.prescribed[node.owner].name, set.name));
      node.kind = NodeKind::Prescribed;
      node.owner = static_cast<Index>(s);
      node.ndof = 0;
    }
  }

  for (std::size_t p = 0; p < problem.planar.size(); ++p) {
    const PlanarNodes& set = problem.planar[p];
    if (!(set.normal.norm() > 0)) throw InputError(fmt::format("planar constraint \"{}\" has a zero normal", set.name));
    for (Index a : set.nodes) {
      NodeInfo& node = node_[a];
      if (node.kind == NodeKind::RigidMember)
        throw InputError(fmt::format("planar constraint \"{}\" holds node {}, which belongs to rigid body \"{}\"",
                                     set.name, a, problem.rigid_bodies[node.owner].name));
      if (node.kind == NodeKind::Prescribed) continue;  // fully prescribed wins
      node.kind = NodeKind::Planar;
      if (node.planar < 0) {
        node.planar = static_cast<Index>(planar_.size());
        planar_.emplace_back();
      }
      planar_[static_cast<std::size_t>(node.planar)].planes.push_back(static_cast<Index>(p));
    }
  }

  // Planar bases: orthonormal complement of the constraint normals.
  for (Index a = 0; a < n; ++a) {
    NodeInfo& node = node_[a];
    if (node.kind != NodeKind::Planar) continue;
    PlanarInfo& held = planar_[static_cast<std::size_t>(node.planar)];
    const int k = static_cast<int>(held.planes.size());
    Eigen::Matrix<double, Eigen::Dynamic, 3> N(k, 3);
    for (int i = 0; i < k; ++i) N.row(i) = problem.planar[held.planes[i]].normal.normalized().transpose();
    Eigen::JacobiSVD<Eigen::Matrix<double, Eigen::Dynamic, 3>> svd(N, Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();
    int rank = 0;
    for (int i = 0; i < sv.size(); ++i)
      if (sv[i] > 1e-8) ++rank;
    if (rank < k)
      throw InputError(fmt::format("node {} is held by parallel planar constraints (\"{}\" and others); use one "
                                   "planar constraint per direction",
                                   a, problem.planar[held.planes[0]].name));
    node.ndof = 3 - rank;
    const Matrix3 V = svd.matrixV();
    held.basis.setZero();
    for (int j = 0; j < node.ndof; ++j) held.basis.col(j) = V.col(rank + j);
    if (node.ndof == 0) node.kind = NodeKind::Prescribed, node.owner = -1;
  }

  // Number the DOFs: nodes in order, then free rigid bodies.
  Index next = 0;
  for (Index a = 0; a < n; ++a) {
    NodeInfo& node = node_[a];
    if (node.kind == NodeKind::Free || node.kind == NodeKind::Planar) {
      node.dof = next;
      next += node.ndof;
    }
  }
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    if (rigid_[r].kind != RigidBody::Kind::Free) continue;
    rigid_[r].dof = next;
    next += 6;
    for (Index a : rigid_[r].members) {
      node_[a].dof = rigid_[r].dof;
      node_[a].ndof = 6;
    }
  }
  num_dofs_ = next;
}

const Matrix3& DofMap::basis(const NodeInfo& node) const {
  static const Matrix3 identity = Matrix3::Identity();
  return node.planar < 0 ? identity : planar_[static_cast<std::size_t>(node.planar)].basis;
}

Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6> DofMap::node_jacobian(const State& state, Index a) const {
  const NodeInfo& node = node_[a];
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6> J(3, node.ndof);
  if (node.kind == NodeKind::RigidMember) {
    if (node.ndof == 0) return J;
    const std::size_t r = static_cast<std::size_t>(node.owner);
    const Vector3 arm = state.x.row(a).transpose() - (rigid_[r].center + state.rigid[r].t);
    J.leftCols<3>().setIdentity();
    J.rightCols<3>() = -cross_matrix(arm);  // d(w x arm)/dw = -[arm]x
  } else {
    const Matrix3& allowed = basis(node);
    for (int j = 0; j < node.ndof; ++j) J.col(j) = allowed.col(j);
  }
  return J;
}

void DofMap::place_rigid_members(State& state, std::size_t r) const {
  const RigidInfo& info = rigid_[r];
  const RigidPose& pose = state.rigid[r];
  for (Index a : info.members)
    state.x.row(a) =
        (pose.R * (problem_.mesh.rest.row(a).transpose() - info.center) + info.center + pose.t).transpose();
}

const Positions& DofMap::start_positions() const { return has_start() ? start_x_ : problem_.mesh.rest; }

void DofMap::set_start(const State& start) {
  const Positions& X = problem_.mesh.rest;
  if (start.x.rows() != X.rows() || start.x.cols() != 3)
    throw InputError(fmt::format("the start state has {} node positions, the mesh has {} nodes", start.x.rows(), X.rows()));
  if (start.rigid.size() != rigid_.size())
    throw InputError(fmt::format("the start state has {} rigid bodies, the scene has {}", start.rigid.size(), rigid_.size()));
  if (!start.x.allFinite()) throw InputError("the start state has positions that are not finite");
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    const RigidInfo& info = rigid_[r];
    const RigidPose& pose = start.rigid[r];
    if (!pose.R.allFinite() || !pose.t.allFinite() || !(pose.R.transpose() * pose.R).isIdentity(1e-9) ||
        !(pose.R.determinant() > 0))
      throw InputError(fmt::format("the start pose of rigid body \"{}\" is not a rotation and a translation",
                                   problem_.rigid_bodies[r].name));
    double size = 0, misfit = 0;
    for (Index a : info.members) {
      const Vector3 rest = X.row(a).transpose();
      size = std::max(size, (rest - info.center).norm());
      const Vector3 placed = pose.R * (rest - info.center) + info.center + pose.t;
      misfit = std::max(misfit, (start.x.row(a).transpose() - placed).norm());
    }
    if (misfit > 1e-6 * std::max(size, 1e-300))
      throw InputError(fmt::format("in the start state the nodes of rigid body \"{}\" are {:.3g} (length) away from a "
                                   "rigid motion of its rest shape: was it deformable in the run it comes from?",
                                   problem_.rigid_bodies[r].name, misfit));
  }
  start_x_ = start.x;
  start_pose_ = start.rigid;
}

State DofMap::initial_state(double lambda) const {
  State state;
  state.x = start_positions();
  state.rigid = has_start() ? start_pose_ : std::vector<RigidPose>(rigid_.size(), RigidPose{});
  sync(state, lambda);
  return state;
}

double DofMap::largest_prescribed_turn(double from, double to) const {
  double turn = 0;
  for (const PrescribedNodes& set : problem_.prescribed) turn = std::max(turn, set.motion.largest_turn(from, to));
  for (const RigidInfo& info : rigid_)
    if (info.kind == RigidBody::Kind::Prescribed) turn = std::max(turn, info.motion.largest_turn(from, to));
  return turn;
}

void DofMap::sync(State& state, double lambda) const {
  state.lambda = lambda;
  const Positions& X = start_positions();
  for (const PrescribedNodes& set : problem_.prescribed) {
    const Matrix3 R = set.motion.rotation(lambda);
    const Vector3 t = set.motion.offset(lambda);
    for (Index a : set.nodes) state.x.row(a) = (R * X.row(a).transpose() + t).transpose();
  }
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    const RigidInfo& info = rigid_[r];
    if (info.kind != RigidBody::Kind::Free) {
      // The motion applied to the start pose: x = M_R (R0 (X - c) + c + t0) + M_t.
      const RigidPose start = has_start() ? start_pose_[r] : RigidPose{};
      const Matrix3 R = info.kind == RigidBody::Kind::Fixed ? Matrix3::Identity() : info.motion.rotation(lambda);
      const Vector3 offset = info.kind == RigidBody::Kind::Fixed ? Vector3::Zero() : info.motion.offset(lambda);
      state.rigid[r].R = R * start.R;
      state.rigid[r].t = R * (info.center + start.t) + offset - info.center;
    }
    place_rigid_members(state, r);
  }
  // Planar nodes: minimal-norm correction onto the intersection of their planes.
  for (Index a = 0; a < static_cast<Index>(node_.size()); ++a) {
    const NodeInfo& node = node_[a];
    if (node.planar < 0 || (node.kind != NodeKind::Planar && node.kind != NodeKind::Prescribed)) continue;
    if (node.kind == NodeKind::Prescribed && node.owner >= 0) continue;  // set by a prescribed set
    const std::vector<Index>& planes = planar_[static_cast<std::size_t>(node.planar)].planes;
    const int k = static_cast<int>(planes.size());
    Eigen::Matrix<double, Eigen::Dynamic, 3> N(k, 3);
    VectorX residual(k);
    const Vector3 u = (state.x.row(a) - X.row(a)).transpose();
    for (int i = 0; i < k; ++i) {
      const PlanarNodes& plane = problem_.planar[planes[i]];
      const Vector3 nrm = plane.normal.normalized();
      N.row(i) = nrm.transpose();
      residual[i] = plane.displacement * plane.amplitude(lambda) - nrm.dot(u);
    }
    const Vector3 correction = N.transpose() * (N * N.transpose()).ldlt().solve(residual);
    state.x.row(a) += correction.transpose();
  }
}

VectorX DofMap::reduce_gradient(const State& state, const NodalVectors& g) const {
  VectorX gq = VectorX::Zero(num_dofs_);
  for (Index a = 0; a < static_cast<Index>(node_.size()); ++a) {
    const NodeInfo& node = node_[a];
    if (node.ndof == 0) continue;
    gq.segment(node.dof, node.ndof) += node_jacobian(state, a).transpose() * g.row(a).transpose();
  }
  return gq;
}

State DofMap::apply_step(const State& base, const VectorX& dq, double alpha) const {
  State out = base;
  for (Index a = 0; a < static_cast<Index>(node_.size()); ++a) {
    const NodeInfo& node = node_[a];
    if (node.kind != NodeKind::Free && node.kind != NodeKind::Planar) continue;
    const Matrix3& allowed = basis(node);
    Vector3 dx = Vector3::Zero();
    for (int j = 0; j < node.ndof; ++j) dx += allowed.col(j) * dq[node.dof + j];
    out.x.row(a) += alpha * dx.transpose();
  }
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    if (rigid_[r].kind != RigidBody::Kind::Free) continue;
    const Index d = rigid_[r].dof;
    out.rigid[r].t += alpha * dq.segment<3>(d);
    out.rigid[r].R = rotation_from_vector(alpha * dq.segment<3>(d + 3)) * base.rigid[r].R;
    place_rigid_members(out, r);
  }
  return out;
}

State DofMap::extrapolate(const State& older, const State& newer, double s, double lambda) const {
  State out = newer;
  for (Index a = 0; a < static_cast<Index>(node_.size()); ++a) {
    const NodeKind k = node_[a].kind;
    if (k == NodeKind::Free || k == NodeKind::Planar) out.x.row(a) += s * (newer.x.row(a) - older.x.row(a));
  }
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    if (rigid_[r].kind != RigidBody::Kind::Free) continue;
    out.rigid[r].t += s * (newer.rigid[r].t - older.rigid[r].t);
    const Vector3 w = rotation_to_vector(newer.rigid[r].R * older.rigid[r].R.transpose());
    out.rigid[r].R = rotation_from_vector(s * w) * newer.rigid[r].R;
  }
  sync(out, lambda);
  return out;
}

}  // namespace sinew::fem
