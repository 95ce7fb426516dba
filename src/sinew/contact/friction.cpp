#include "sinew/contact/friction.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sinew/contact/node_pair_key.hpp"
#include "sinew/core/error.hpp"

namespace sinew::contact {
namespace {

using Basis = Eigen::Matrix<double, 3, 2>;

/// Two orthonormal directions orthogonal to the unit vector n.
Basis tangent_basis(const Vector3& n) {
  const Vector3 helper = std::abs(n.x()) < 0.6 ? Vector3::UnitX() : Vector3::UnitY();
  const Vector3 t1 = n.cross(helper).normalized();
  Basis T;
  T.col(0) = t1;
  T.col(1) = n.cross(t1);
  return T;
}

/// The combination Σ β x (triangle) - Σ ξ x (tet) of the point's 7 nodes at x.
Vector3 relative_position(const FrictionPoint& p, const std::array<Index, 7>& nodes, const Positions& x) {
  Vector3 d = Vector3::Zero();
  for (int k = 0; k < 3; ++k) d += p.triangle_weights[k] * x.row(nodes[static_cast<std::size_t>(k)]).transpose();
  for (int k = 0; k < 4; ++k) d -= p.tet_weights[k] * x.row(nodes[static_cast<std::size_t>(3 + k)]).transpose();
  return d;
}

/// The 7 coefficients c of the point's nodes in its relative position (β, then -ξ).
std::array<double, 7> node_coefficients(const FrictionPoint& p) {
  return {p.triangle_weights[0], p.triangle_weights[1], p.triangle_weights[2], -p.tet_weights[0],
          -p.tet_weights[1],     -p.tet_weights[2],     -p.tet_weights[3]};
}

}  // namespace

double friction_f0(double s, double eps) {
  if (s >= eps) return s;
  return s * s / eps - s * s * s / (3 * eps * eps) + eps / 3;
}

double friction_f1_over_s(double s, double eps) {
  if (s >= eps) return 1 / s;
  return 2 / eps - s / (eps * eps);
}

std::vector<FrictionPoint> friction_points(const ContactEnergy& contact, const MatrixX& mu) {
  std::vector<FrictionPoint> points;
  const CollisionSet& set = contact.collisions();
  const ContactGeometry& g = set.geometry();
  const Positions& x = set.positions();
  const VectorX& pressure = set.pressure();
  for (const ActivePair& pair : set.pairs()) {
    const double m = mu(g.surface_body[pair.triangle], g.tet_body[pair.tet]);
    if (!(m > 0)) continue;
    const PairGeometry pg = set.pair_geometry_at(x, pair);
    const Vector3 a = pg.triangle.row(0), b = pg.triangle.row(1), c = pg.triangle.row(2);
    const Vector3 triangle_normal = (b - a).cross(c - a);
    const double twice_area = triangle_normal.norm();
    if (!(twice_area > 0)) continue;
    // The sliding surface is the triangle's: its normal, not the depth gradient of the tet, which
    // in a coarse mesh points toward the body's middle rather than across the surface.
    const Vector3 normal = triangle_normal / twice_area;
    // The pressure the pair exerts is (ε g + p r'(g)) |∇g|: the force density of
    // (ε/2) g² + p r(g) on a point of the triangle is (ε g + p r'(g)) ∇g, r'(g) = min(1, g / δ)
    // with the multipliers' onset ramp (pair_integral.hpp).
    const double gradient_norm = depth_gradient(pg).norm();
    FrictionPoint point;
    point.triangle = pair.triangle;
    point.tet = pair.tet;
    point.basis = tangent_basis(normal);
    point.mu = m;
    Vector3 nodal_pressure = Vector3::Zero();
    if (pressure.size() > 0)
      for (int k = 0; k < 3; ++k) nodal_pressure[k] = pressure[g.surface(pair.triangle, k)];
    auto add = [&](const Vector3& beta, const Eigen::Vector4d& xi, double weight) {
      const double depth = xi.dot(pg.depth);
      const double normal_force =
          weight * (pair.penalty * depth + onset_ramp_slope(depth, pg.multiplier_onset) * beta.dot(nodal_pressure)) *
          gradient_norm;
      if (!(normal_force > 0)) return;
      point.triangle_weights = beta;
      point.tet_weights = xi;
      point.normal_force = normal_force;
      points.push_back(point);
    };
    if (set.method() == ContactMethod::Area) {
      const collision::ClipPolygon& polygon = pair.support.polygon;
      const Vector3 unit_normal = triangle_normal / twice_area;
      for (int j = 1; j + 1 < polygon.count; ++j) {
        const auto J = static_cast<std::size_t>(j);
        const Vector3& p0 = polygon.vertices[0];
        const Vector3& p1 = polygon.vertices[J];
        const Vector3& p2 = polygon.vertices[J + 1];
        const double area = 0.5 * unit_normal.dot((p1 - p0).cross(p2 - p0));
        if (!(area > 0)) continue;
        const Vector3 centroid = (p0 + p1 + p2) / 3;
        const Eigen::Vector4d xi = (polygon.barycentric[0] + polygon.barycentric[J] + polygon.barycentric[J + 1]) / 3;
        add(triangle_shape_functions(pg, centroid), xi, area);
      }
    } else {
      const collision::CollocationPoints& inside = pair.support.points;
      for (int k = 0; k < inside.count; ++k) {
        Vector3 beta = Vector3::Zero();
        beta[inside.vertex[static_cast<std::size_t>(k)]] = 1;
        add(beta, inside.barycentric[static_cast<std::size_t>(k)], twice_area / 6);
      }
    }
  }
  return points;
}

FrictionEnergy::FrictionEnergy(ContactEnergy& contact, FrictionOptions options)
    : contact_(contact), options_(std::move(options)) {
  const Index bodies = contact.num_bodies();
  const MatrixX& mu = options_.mu;
  if (mu.rows() != bodies || mu.cols() != bodies)
    throw InputError(fmt::format("friction: a {}x{} coefficient matrix for {} bodies", mu.rows(), mu.cols(), bodies));
  for (Index a = 0; a < bodies; ++a)
    for (Index b = 0; b < bodies; ++b)
      if (!std::isfinite(mu(a, b)) || mu(a, b) < 0 || mu(a, b) != mu(b, a))
        throw InputError(fmt::format("friction coefficient of bodies {} and {}: {} (must be finite, >= 0 and "
                                     "symmetric)",
                                     a, b, mu(a, b)));
  if (!std::isfinite(options_.slip_threshold) || !(options_.slip_threshold > 0))
    throw InputError(fmt::format("friction slip threshold {} must be finite and > 0", options_.slip_threshold));
  if (!std::isfinite(options_.slip_velocity_threshold) || options_.slip_velocity_threshold < 0)
    throw InputError(fmt::format("friction slip velocity threshold {} must be finite and >= 0",
                                 options_.slip_velocity_threshold));
}

void FrictionEnergy::set_time_step(double h) {
  if (options_.slip_velocity_threshold > 0 && h > 0 && std::isfinite(h))
    options_.slip_threshold = options_.slip_velocity_threshold * h;
}

std::array<Index, 7> FrictionEnergy::nodes(const FrictionPoint& p) const {
  return pair_nodes(contact_.geometry(), p.triangle, p.tet);
}

void FrictionEnergy::lag(const Positions& x) {
  contact_.update(x);
  points_ = friction_points(contact_, options_.mu);
  bool grew = false;
  for (const FrictionPoint& p : points_) {
    const auto n = nodes(p);
    for (std::size_t i = 0; i < 7; ++i)
      for (std::size_t j = i + 1; j < 7; ++j)
        if (n[i] != n[j] && pattern_.insert(node_pair_key(n[i], n[j])).second) grew = true;
  }
  if (grew) ++revision_;
}

void FrictionEnergy::begin_step(const Positions& x) {
  start_ = x;
  lag(x);
}

double FrictionEnergy::refresh(const Positions& x) {
  double before = 0, after = 0;
  for (const FrictionPoint& p : points_) before += p.normal_force;
  lag(x);
  for (const FrictionPoint& p : points_) after += p.normal_force;
  const double scale = std::max(before, after);
  return scale > 0 ? std::abs(after - before) / scale : 0.0;
}

std::vector<Eigen::Vector2d> FrictionEnergy::slips(const Positions& x) const {
  std::vector<Eigen::Vector2d> u;
  u.reserve(points_.size());
  for (const FrictionPoint& p : points_) {
    const auto n = nodes(p);
    u.emplace_back(p.basis.transpose() * (relative_position(p, n, x) - relative_position(p, n, start_)));
  }
  return u;
}

std::vector<Vector3> FrictionEnergy::body_pair_forces(const Positions& x) const {
  const Index bodies = contact_.num_bodies();
  std::vector<Vector3> forces(static_cast<std::size_t>(bodies * bodies), Vector3::Zero());
  const ContactGeometry& g = contact_.geometry();
  const auto u = slips(x);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const FrictionPoint& p = points_[k];
    const double s = u[k].norm();
    // dD/dd: the triangle's body gets -F (Σ β = 1), the tet's body +F (Σ ξ = 1).
    const Vector3 F = p.basis * (p.mu * p.normal_force * friction_f1_over_s(s, options_.slip_threshold) * u[k]);
    const Index a = g.surface_body[p.triangle], b = g.tet_body[p.tet];
    if (a < b) forces[static_cast<std::size_t>(a * bodies + b)] -= F;
    if (b < a) forces[static_cast<std::size_t>(b * bodies + a)] += F;
  }
  return forces;
}

VectorX FrictionEnergy::slip_ratio(const Positions& x) const {
  VectorX ratio = VectorX::Zero(x.rows());
  const ContactGeometry& g = contact_.geometry();
  const auto u = slips(x);
  for (std::size_t k = 0; k < points_.size(); ++k)
    for (int v = 0; v < 3; ++v) {
      const Index node = g.surface(points_[k].triangle, v);
      ratio[node] = std::max(ratio[node], u[k].norm() / options_.slip_threshold);
    }
  return ratio;
}

double FrictionEnergy::value(const Positions& x) const {
  double total = 0;
  const double eps = options_.slip_threshold;
  const auto u = slips(x);
  for (std::size_t k = 0; k < points_.size(); ++k)
    total += points_[k].mu * points_[k].normal_force * friction_f0(u[k].norm(), eps);
  return total;
}

void FrictionEnergy::add_gradient(const Positions& x, NodalVectors& grad) const {
  const double eps = options_.slip_threshold;
  const auto u = slips(x);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const FrictionPoint& p = points_[k];
    const double s = u[k].norm();
    const Vector3 force = p.basis * (p.mu * p.normal_force * friction_f1_over_s(s, eps) * u[k]);  // dD/dd
    const auto n = nodes(p);
    const auto c = node_coefficients(p);
    for (std::size_t i = 0; i < 7; ++i) grad.row(n[i]) += c[i] * force.transpose();
  }
}

void FrictionEnergy::add_hessian(const Positions& x, BlockSparseMatrix& H) const {
  const double eps = options_.slip_threshold;
  const auto u = slips(x);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const FrictionPoint& p = points_[k];
    const double s = u[k].norm();
    const double scale = p.mu * p.normal_force;
    Eigen::Matrix2d Hu;
    if (s >= eps) {
      const Eigen::Vector2d direction = u[k] / s;
      Hu = (Eigen::Matrix2d::Identity() - direction * direction.transpose()) * (scale / s);
    } else {
      Hu = Eigen::Matrix2d::Identity() * (scale * (2 / eps - s / (eps * eps)));
      if (s > 0) Hu -= u[k] * u[k].transpose() * (scale / (eps * eps * s));
    }
    const Matrix3 M = p.basis * Hu * p.basis.transpose();
    const auto n = nodes(p);
    const auto c = node_coefficients(p);
    for (std::size_t i = 0; i < 7; ++i)
      for (std::size_t j = 0; j < 7; ++j) {
        const Index b = H.find(n[i], n[j]);
        if (b < 0) throw std::logic_error("FrictionEnergy::add_hessian: a block is missing from the pattern");
        H.add(b, (c[i] * c[j]) * M);
      }
  }
}

void FrictionEnergy::hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const {
  for (const std::uint64_t key : pattern_)
    pairs.emplace_back(static_cast<Index>(key >> 32), static_cast<Index>(key & 0xffffffffu));
}

}  // namespace sinew::contact
