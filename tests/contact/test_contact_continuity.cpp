// Evidence for the material-depth contact energy (docs/theory.md) at the level of
// ContactEnergy: the force along a sweep of one body through another is continuous for the area
// method (its largest jump between neighbouring samples shrinks with the spacing) and not for
// point collocation; the energy is continuous; self-contact of a bent bar; zero depths and zero
// penalties and the rest in test_contact_methods.cpp.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <vector>

#include "sinew/collision/broad_phase.hpp"
#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/collision/material_depth.hpp"
#include "sinew/collision/polygon_quadrature.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/contact_report.hpp"
#include "support/box_mesh.hpp"
#include "support/contact_fixtures.hpp"
#include "support/fd_check.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

const char* method_name(ContactMethod m) { return m == ContactMethod::Area ? "area" : "point"; }

using st::gradient_at;
using st::hessian_at;

// ---------------------------------------------------------------------------------------------
// Sweep of body 1 of two_boxes through body 0 along a straight line

/// Body 1 (a rotated copy of the unit box, 2 x 2 x 2 cubes) translated along a straight path from
/// `from` to `to` (offsets), s in [0, 1]; deep enough that its vertices cross many of body 0's
/// tets (and body 0's vertices cross body 1's tets).
class Sweep {
 public:
  explicit Sweep(ContactMethod method)
      : base_(st::two_boxes(2, Vector3::Zero(), 0.3, 1.0, /*self_contact=*/false)),
        energy_(base_.geometry, {method, PairHessian::GaussNewton}),
        body1_(static_cast<Index>(base_.x.rows() / 2)) {}

  struct Sample {
    Vector3 force;  ///< net contact force on body 1 (force unit)
    double energy;
  };

  Sample at(double s) {
    Positions x = base_.x;
    const Vector3 offset = from_ + s * (to_ - from_);
    for (Index a = body1_; a < x.rows(); ++a) x.row(a) += offset.transpose();
    energy_.update(x);
    Sample out;
    out.energy = energy_.value(x);
    NodalVectors g = NodalVectors::Zero(x.rows(), 3);
    energy_.add_gradient(x, g);
    out.force = -g.bottomRows(x.rows() - body1_).colwise().sum().transpose();
    return out;
  }

  struct Jumps {
    double force = 0;   ///< max |F(s_k+1) - F(s_k)|
    double energy = 0;  ///< max |E(s_k+1) - E(s_k)|
    double where = 0;   ///< s_k of the largest force jump
    double max_force = 0;
  };

  /// The samples s_k = k / K, k = 0..K.
  std::vector<Sample> samples(int K) {
    std::vector<Sample> out;
    out.reserve(static_cast<std::size_t>(K) + 1);
    for (int k = 0; k <= K; ++k) out.push_back(at(static_cast<double>(k) / K));
    return out;
  }

  /// Jumps between neighbours on the coarser grid s_k = k stride / K of `fine` (K + 1 samples).
  static Jumps jumps(const std::vector<Sample>& fine, int stride) {
    Jumps j;
    const int K = static_cast<int>(fine.size()) - 1;
    for (int k = 0; k + stride <= K; k += stride) {
      const Sample& a = fine[static_cast<std::size_t>(k)];
      const Sample& b = fine[static_cast<std::size_t>(k + stride)];
      const double df = (b.force - a.force).norm();
      if (df > j.force) {
        j.force = df;
        j.where = static_cast<double>(k) / K;
      }
      j.energy = std::max(j.energy, std::abs(b.energy - a.energy));
      j.max_force = std::max(j.max_force, b.force.norm());
    }
    return j;
  }

  /// Starting from [s0, s0 + width], halves the interval `steps` times, keeping the half with
  /// the larger force jump; returns the force jump over the final interval.
  double bisected_jump(double s0, double width, int steps) {
    double a = s0, b = s0 + width;
    Sample fa = at(a), fb = at(b);
    for (int i = 0; i < steps; ++i) {
      const double m = 0.5 * (a + b);
      const Sample fm = at(m);
      if ((fm.force - fa.force).norm() >= (fb.force - fm.force).norm()) {
        b = m;
        fb = fm;
      } else {
        a = m;
        fa = fm;
      }
    }
    return (fb.force - fa.force).norm();
  }

 private:
  st::TwoBoxes base_;
  ContactEnergy energy_;
  Index body1_;
  Vector3 from_{1.0, 0.13, 0.07};
  Vector3 to_{0.1, 0.1, 0.02};
};

/// The sweep sampled at K = 400 (the K = 200 and K = 100 grids are every 2nd and 4th sample),
/// computed once per method.
const std::vector<Sweep::Sample>& sweep_samples(ContactMethod method) {
  static const std::vector<Sweep::Sample> area = Sweep(ContactMethod::Area).samples(400);
  static const std::vector<Sweep::Sample> point = Sweep(ContactMethod::Point).samples(400);
  return method == ContactMethod::Area ? area : point;
}

constexpr std::array<int, 3> kSweepK{100, 200, 400};

std::array<Sweep::Jumps, 3> sweep_jumps(ContactMethod method) {
  std::array<Sweep::Jumps, 3> j{};
  for (std::size_t i = 0; i < kSweepK.size(); ++i) j[i] = Sweep::jumps(sweep_samples(method), 400 / kSweepK[i]);
  return j;
}

TEST(ContactContinuity, AreaForceJumpsShrinkWithTheSpacingPointForceJumpsDoNot) {
  const std::array<Sweep::Jumps, 3> area = sweep_jumps(ContactMethod::Area);
  const std::array<Sweep::Jumps, 3> point = sweep_jumps(ContactMethod::Point);
  const auto precision = std::cout.precision(4);
  for (std::size_t i = 0; i < kSweepK.size(); ++i)
    std::cout << "[sweep] K=" << kSweepK[i] << "  max force jump: area " << area[i].force << " (at s=" << area[i].where
              << "), point " << point[i].force << " (at s=" << point[i].where << ");  max |F|: area "
              << area[i].max_force << ", point " << point[i].max_force << "\n";
  // Both sweeps see real contact forces.
  EXPECT_GT(area[2].max_force, 0.05);
  EXPECT_GT(point[2].max_force, 0.05);
  // Area: continuous force, the largest jump halves with the spacing (Lipschitz).
  EXPECT_LT(area[1].force, 0.6 * area[0].force);
  EXPECT_LT(area[2].force, 0.6 * area[1].force);
  EXPECT_LT(area[2].force, 0.35 * area[0].force);
  // Point collocation: the largest jump does not shrink (a discontinuity), and it is far larger
  // than the area method's at the same spacing.
  EXPECT_GT(point[2].force, 0.6 * point[0].force);
  EXPECT_GT(point[2].force, 0.6 * point[1].force);
  EXPECT_GT(point[2].force, 10 * area[2].force);

  // Zoom in on the largest jump at K = 400: 30 bisections (interval ~1e-11 in offset) keep the
  // point method's jump; the area method's jump vanishes.
  const double width = 1.0 / kSweepK[2];
  Sweep area_sweep(ContactMethod::Area), point_sweep(ContactMethod::Point);
  const double point_zoom = point_sweep.bisected_jump(point[2].where, width, 30);
  const double area_zoom = area_sweep.bisected_jump(area[2].where, width, 30);
  std::cout << "[sweep] after 30 bisections of the largest K=400 interval: point jump " << point_zoom
            << ", area jump " << area_zoom << "\n";
  std::cout.precision(precision);
  EXPECT_GT(point_zoom, 0.5 * point[2].force);
  EXPECT_LT(area_zoom, 1e-6 * area[2].max_force);
}

TEST(ContactContinuity, AreaEnergyIsContinuousAlongTheSweep) {
  const std::array<Sweep::Jumps, 3> j = sweep_jumps(ContactMethod::Area);
  std::cout << "[sweep] area, max |E(s_k+1) - E(s_k)|: K=100 " << j[0].energy << ", K=200 " << j[1].energy
            << ", K=400 " << j[2].energy << "\n";
  EXPECT_GT(j[0].energy, 0);
  EXPECT_LT(j[1].energy, 0.6 * j[0].energy);
  EXPECT_LT(j[2].energy, 0.6 * j[1].energy);
  // The energy's slope along the path is the force: |ΔE| <= max |F| |Δoffset|.
  const double path = (Vector3(1.0, 0.13, 0.07) - Vector3(0.1, 0.1, 0.02)).norm();
  for (std::size_t i = 0; i < kSweepK.size(); ++i)
    EXPECT_LE(j[i].energy, 1.0001 * j[i].max_force * path / kSweepK[i]);
}

// Body 1 shifted by exactly one cell of body 0's grid: its surface triangles lie on faces shared
// by two of body 0's tets, and its vertices on shared faces, edges and nodes (and body 0's in
// body 1's). The half-open rule (docs/contact.md) counts each once: the energy is that of a
// shift of 1e-9 more (before the rule, the area energy doubled and the point energy grew 24
// times). The area gradient has a kink here (∇g jumps across the shared faces): it is the
// one-sided gradient of a shift of 1e-9 less, which moves each surface outward, into the other
// body, as the rule does. The point method's force jumps here (its ∇g jumps between tets), so for it each
// collocation point is checked to lie in one tet.
TEST(ContactContinuity, SurfaceOnSharedTetFacesIsCountedOnce) {
  for (const ContactMethod method : {ContactMethod::Area, ContactMethod::Point}) {
    const auto aligned = st::two_boxes(2, Vector3(0.5, 0.5, 0.5), 0.0, 1.0, false);
    const auto nudged = st::two_boxes(2, Vector3(0.5 + 1e-9, 0.5 + 2e-9, 0.5 + 3e-9), 0.0, 1.0, false);
    const auto deeper = st::two_boxes(2, Vector3(0.5 - 1e-9, 0.5 - 2e-9, 0.5 - 3e-9), 0.0, 1.0, false);
    ContactEnergy a(aligned.geometry, {method, PairHessian::GaussNewton});
    ContactEnergy b(nudged.geometry, {method, PairHessian::GaussNewton});
    a.update(aligned.x);
    b.update(nudged.x);
    const double ea = a.value(aligned.x), eb = b.value(nudged.x);
    EXPECT_GT(eb, 0) << method_name(method);
    EXPECT_NEAR(ea, eb, 1e-6 * eb) << method_name(method);
    if (method == ContactMethod::Area) {
      // The whole gradient (the net force on body 1 is zero by symmetry here).
      ContactEnergy c(deeper.geometry, {method, PairHessian::GaussNewton});
      c.update(deeper.x);
      EXPECT_NEAR(c.value(deeper.x), eb, 1e-6 * eb);
      const NodalVectors ga = gradient_at(a, aligned.x), gc = gradient_at(c, deeper.x);
      EXPECT_GT(gc.norm(), 0);
      EXPECT_LT((ga - gc).norm(), 1e-6 * gc.norm());
      continue;
    }
    // Point method: every collocation point (triangle, vertex) lies in at most one tet of the
    // other body, and some lie on shared nodes (the case the rule is for).
    const auto& g = aligned.geometry;
    std::map<std::pair<Index, int>, int> tets_per_point;
    for (const auto& [f, t] : a.active_pairs()) {
      const PairGeometry pg = pair_geometry(g, aligned.x, f, t);
      const collision::CollocationPoints points = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
      for (int k = 0; k < points.count; ++k) ++tets_per_point[{f, points.vertex[static_cast<std::size_t>(k)]}];
    }
    EXPECT_FALSE(tets_per_point.empty());
    for (const auto& [point, count] : tets_per_point)
      EXPECT_EQ(count, 1) << "triangle " << point.first << ", vertex " << point.second;
  }
}

// ---------------------------------------------------------------------------------------------
// Self-contact

/// A bar of nx x 2 x 2 cubes, [0, L] x [0, h] x [0, h] at rest, wound into a helical ring of
/// more than one turn so that its end penetrates its start: (x, y, z) -> ((R + y) cos θ,
/// (R + y) sin θ, z + c θ), θ = α x, α L = 2π + 0.7, the pitch c lifting one turn by h / 3.
struct BentBar {
  Positions x;
  ContactGeometry geometry;
  double length = 0;
  Positions rest;
};

BentBar bent_bar(double penalty) {
  const int nx = 12;
  const double L = 10.0, h = 0.5, R = 1.5;
  const mesh::TetMesh bar = st::box_mesh(nx, 2, 2, Vector3::Zero(), Vector3(L, h, h));
  BentBar out;
  out.length = L;
  out.rest = bar.rest;
  const double alpha = (2 * std::numbers::pi + 0.7) / L, c = (h / 3) / (2 * std::numbers::pi);
  out.x.resize(bar.rest.rows(), 3);
  for (Index a = 0; a < bar.rest.rows(); ++a) {
    const double theta = alpha * bar.rest(a, 0), r = R + bar.rest(a, 1);
    out.x.row(a) << r * std::cos(theta), r * std::sin(theta), bar.rest(a, 2) + c * theta;
  }
  auto& g = out.geometry;
  g.surface = mesh::boundary_triangles(bar.tets);
  g.surface_body = IndexVector::Zero(g.surface.rows());
  g.tets = bar.tets;
  g.tet_body = IndexVector::Zero(g.tets.rows());
  std::vector<Index> nodes(static_cast<std::size_t>(bar.rest.rows()));
  for (Index a = 0; a < bar.rest.rows(); ++a) nodes[static_cast<std::size_t>(a)] = a;
  g.depth = collision::material_depth(bar.rest, g.surface, nodes);
  g.penalty = MatrixX::Constant(1, 1, penalty);
  return out;
}

class SelfContact : public ::testing::TestWithParam<ContactMethod> {};

TEST(SelfContactNarrowPhase, PlaneRejectionKeepsEveryPairWithAreaAndTheEnergyOfBruteForce) {
  // Every (triangle, tet) pair of the bent bar, clipped without the broad phase and without the
  // plane test: pairs whose polygon has area must all be active, active pairs must all have a
  // polygon, and the energies agree.
  const BentBar bar = bent_bar(5.0);
  const auto& g = bar.geometry;
  ContactEnergy energy(g, {ContactMethod::Area, PairHessian::Exact});
  energy.update(bar.x);
  const auto active = energy.active_pairs();
  const std::set<std::pair<Index, Index>> active_set(active.begin(), active.end());
  double brute_energy = 0;
  int with_area = 0;
  for (Index f = 0; f < g.surface.rows(); ++f)
    for (Index t = 0; t < g.tets.rows(); ++t) {
      if (collision::shares_node(g.surface, f, g.tets, t)) continue;
      PairGeometry pg;
      for (int k = 0; k < 3; ++k) pg.triangle.row(k) = bar.x.row(g.surface(f, k));
      for (int k = 0; k < 4; ++k) {
        pg.tet.row(k) = bar.x.row(g.tets(t, k));
        pg.depth[k] = g.depth[g.tets(t, k)];
      }
      if (pg.depth.maxCoeff() == 0) continue;  // g = 0 on the whole tet: skipped by design
      const collision::ClipPolygon polygon = collision::clip_triangle_tet(pg.triangle, pg.tet);
      const double area = polygon.count >= 3 ? area_moments(pg, polygon).area : 0.0;
      if (area > 1e-12) {
        ++with_area;
        EXPECT_TRUE(active_set.count({f, t})) << "pair " << f << ", " << t << " with area " << area << " is missing";
      }
      if (active_set.count({f, t})) {
        EXPECT_GE(polygon.count, 3) << "pair " << f << ", " << t;
      }
      if (polygon.count >= 3) brute_energy += 0.5 * g.penalty(0, 0) * area_integral(pg, polygon);
    }
  EXPECT_GT(with_area, 10);
  EXPECT_NEAR(energy.value(bar.x), brute_energy, 1e-12 * brute_energy);
}

TEST_P(SelfContact, BentBarEndPenetratingItsStart) {
  const BentBar bar = bent_bar(5.0);
  ContactEnergy energy(bar.geometry, {GetParam(), PairHessian::Exact});
  energy.update(bar.x);
  const auto pairs = energy.active_pairs();
  ASSERT_FALSE(pairs.empty());
  const double value = energy.value(bar.x);
  EXPECT_GT(value, 0);
  // No pair shares a node, and every pair joins the two ends of the bar (nothing spurious
  // between neighbouring elements).
  const auto& g = bar.geometry;
  for (const auto& [f, t] : pairs) {
    double tri_x = 0, tet_x = 0;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 4; ++k) EXPECT_NE(g.surface(f, i), g.tets(t, k)) << "pair " << f << ", " << t;
      tri_x += bar.rest(g.surface(f, i), 0) / 3;
    }
    for (int k = 0; k < 4; ++k) tet_x += bar.rest(g.tets(t, k), 0) / 4;
    EXPECT_GT(std::abs(tri_x - tet_x), 0.5 * bar.length) << "pair " << f << ", " << t;
  }
  // The gradient is the exact gradient of the total energy: finite differences in every
  // coordinate of every node of an active pair; the gradient is exactly 0 at the other nodes.
  const NodalVectors grad = gradient_at(energy, bar.x);
  std::set<Index> involved;
  for (const auto& [f, t] : pairs) {
    for (int i = 0; i < 3; ++i) involved.insert(g.surface(f, i));
    for (int k = 0; k < 4; ++k) involved.insert(g.tets(t, k));
  }
  for (Index a = 0; a < bar.x.rows(); ++a) {
    if (involved.count(a) == 0) {
      EXPECT_EQ(grad.row(a).norm(), 0.0) << "node " << a;
    }
  }
  const std::vector<Index> nodes(involved.begin(), involved.end());
  Eigen::VectorXd x0(3 * static_cast<Index>(nodes.size())), analytic(x0.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      x0[static_cast<Index>(3 * i) + c] = bar.x(nodes[i], c);
      analytic[static_cast<Index>(3 * i) + c] = grad(nodes[i], c);
    }
  auto f = [&](const Eigen::VectorXd& v) {
    Positions x = bar.x;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (int c = 0; c < 3; ++c) x(nodes[i], c) = v[static_cast<Index>(3 * i) + c];
    energy.update(x);
    return energy.value(x);
  };
  const Eigen::VectorXd fd = st::fd_gradient(f, x0, 1e-7);
  const double err = st::relative_error(analytic, fd);
  std::cout << "[self-contact] " << method_name(GetParam()) << ": " << pairs.size() << " pairs, energy " << value
            << ", relative FD gradient error " << err << "\n";
  EXPECT_LT(err, 1e-6);
  // Zero net force and torque.
  const Vector3 net = grad.colwise().sum().transpose();
  Vector3 torque = Vector3::Zero();
  for (Index a = 0; a < bar.x.rows(); ++a) torque += Vector3(bar.x.row(a)).cross(Vector3(grad.row(a)));
  const double scale = grad.rowwise().norm().sum();
  EXPECT_GT(scale, 0);
  EXPECT_LT(net.norm(), 1e-12 * scale);
  EXPECT_LT(torque.norm(), 1e-12 * scale);
  // Without the self penalty nothing is active.
  ContactGeometry off = bar.geometry;
  off.penalty(0, 0) = 0;
  ContactEnergy none(off, {GetParam(), PairHessian::Exact});
  none.update(bar.x);
  EXPECT_TRUE(none.active_pairs().empty());
  EXPECT_EQ(none.value(bar.x), 0.0);
}

TEST_P(SelfContact, UnbentBarHasNoSelfContact) {
  const BentBar bar = bent_bar(5.0);
  ContactEnergy energy(bar.geometry, {GetParam(), PairHessian::GaussNewton});
  energy.update(bar.rest);
  EXPECT_TRUE(energy.active_pairs().empty());
  EXPECT_EQ(energy.value(bar.rest), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Methods, SelfContact, ::testing::Values(ContactMethod::Area, ContactMethod::Point),
                         [](const auto& info) { return info.param == ContactMethod::Area ? "Area" : "Point"; });

}  // namespace
}  // namespace sinew::contact
