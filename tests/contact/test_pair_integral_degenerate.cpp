/// @file test_pair_integral_degenerate.cpp
/// The pair integral on adversarial and degenerate pairs: finite, non-negative values and
/// derivatives, and covariance under scaling.

#include <gtest/gtest.h>

#include "contact/pair_integral_support.hpp"

namespace sinew::contact {
namespace {

using namespace pair_testing;
namespace st = sinew::testing;

// ---------------------------------------------------------------------------------------------
// Degenerate and adversarial pairs

struct Case {
  std::string name;
  Matrix3 triangle;
  TetVertices tet;
};

std::vector<Case> adversarial_cases() {
  std::vector<Case> cases;
  auto add = [&](const std::string& name, std::initializer_list<double> v) {
    Matrix3 m;
    auto it = v.begin();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = *it++;
    cases.push_back({name, m, unit_tet()});
  };
  const double e = 1e-12;
  add("coplanar with face z=0, equal to it", {0, 0, 0, 1, 0, 0, 0, 1, 0});
  add("coplanar with face z=0, larger", {-1, -1, 0, 3, -1, 0, -1, 3, 0});
  add("coplanar with face z=0, partly", {0.2, 0.2, 0, 2, 0.2, 0, 0.2, 2, 0});
  add("coplanar with the slanted face", {1, 0, 0, 0, 1, 0, 0, 0, 1});
  add("coplanar with the slanted face, larger", {2, -0.5, -0.5, -0.5, 2, -0.5, -0.5, -0.5, 2});
  add("edge through a tet vertex", {-1, 0, 1, 1, 0, 1, 0.1, 0.5, 0.2});
  add("edge through a tet vertex, other side", {-0.5, 0.5, 0.5, 0.5, -0.5, 1.5, 0.3, 0.3, 0.1});
  add("vertex on a tet vertex", {0, 0, 1, 0.3, 0.3, 0.3, -0.2, 0.5, 0.3});
  add("vertex on a tet edge", {0.5, 0, 0, 0.2, 0.3, 0.4, 0.1, 0.1, 0.6});
  add("vertex on a tet face", {0.2, 0.2, 0, 0.2, 0.2, 0.5, 0.5, 0.2, 0.3});
  add("tet vertex on the triangle, touching", {-1, -1, 1, 2, -1, 1, -1, 2, 1});
  add("tet vertex inside the triangle, tilted", {-1, -1, 2.5, 2, -1, -3.5, -1, 2, 4});
  add("triangle plane contains a tet edge", {-1, -1, -1, 3, 0.5, 0.5, -1, 2, 2});
  add("edge along a tet edge", {0, 0, 0, 1, 0, 0, 0.3, -0.5, 0.5});
  add("edge along a tet edge, in a face", {0, 0, 0, 1, 0, 0, 0.3, 0.0, 0.5});
  add("edge longer than a tet edge", {-1, 0, 0, 2, 0, 0, 0.3, 0.3, 0.3});
  add("through three tet vertices", {1, 0, 0, 0, 1, 0, 0, 0, 1});
  add("through two tet vertices", {1, 0, 0, 0, 0, 1, 0.2, 0.6, 0.2});
  add("plane at 1e-12 to face z=0, inside", {-1, -1, e, 3, -1, 2 * e, -1, 3, 3 * e});
  add("plane at 1e-12 to face z=0, crossing", {-1, -1, -e, 3, -1, e, -1, 3, 2 * e});
  add("plane at 1e-12 to face z=0, just outside", {-1, -1, -e, 3, -1, -2 * e, -1, 3, -3 * e});
  add("edge at 1e-12 to tet edge 0-1", {-1, -e, 0, 2, 2 * e, 0, 0.3, 0.3, 0.3});
  add("edge at 1e-12 to tet edge 0-1, in face", {-1, -e, 0, 2, 2 * e, 0, 0.3, 0.3, 0.0});
  add("edge at 1e-12 to tet edge 0-1, out of face", {-1, -e, 0, 2, 2 * e, 0, 0.3, -0.5, 0.5});
  add("edge at 1e-12 to the slanted face", {-0.2, 0.6, 0.6 + e, 1.2, -0.4, 0.2, 0.2, 0.2, 0.2});
  add("tiny triangle at a tet vertex", {0, 0, 1, e, 0, 1, 0, e, 1});
  add("tiny triangle inside", {0.2, 0.2, 0.2, 0.2 + e, 0.2, 0.2, 0.2, 0.2 + e, 0.2});
  add("touching along an edge only", {0, 0, 0, 1, 0, 0, 0.5, -1, -0.5});
  // A nearly flat tet (sliver) against an ordinary triangle.
  Case sliver{"sliver tet", Matrix3(), unit_tet()};
  sliver.triangle << -1, -1, 1e-7, 3, -1, 1e-7, -1, 3, 1e-7;
  sliver.tet.row(3) << 0.3, 0.3, 2e-7;
  cases.push_back(sliver);
  return cases;
}

Matrix3 moved(const Matrix3& m, const Matrix3& r, const Vector3& shift, double scale) {
  Matrix3 out;
  for (int i = 0; i < 3; ++i) out.row(i) = (scale * (r * m.row(i).transpose() + shift)).transpose();
  return out;
}

TetVertices moved(const TetVertices& m, const Matrix3& r, const Vector3& shift, double scale) {
  TetVertices out;
  for (int i = 0; i < 4; ++i) out.row(i) = (scale * (r * m.row(i).transpose() + shift)).transpose();
  return out;
}

/// Value, gradient and both Hessians of both methods are finite, the value is >= 0, and the area
/// value agrees with the collision module's quadrature of the same polygon.
void expect_finite_everything(const PairGeometry& pg, const std::string& where) {
  const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
  const CollocationPoints pts = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
  const double L = std::max(pg.triangle.cwiseAbs().maxCoeff(), pg.tet.cwiseAbs().maxCoeff());
  for (const bool area : {true, false}) {
    const double I = area ? area_integral(pg, p) : point_integral(pg, pts);
    EXPECT_TRUE(std::isfinite(I)) << where << " " << method_name(area);
    EXPECT_GE(I, 0.0) << where << " " << method_name(area);
    PairVector g;
    if (area)
      area_integral_gradient(pg, p, g);
    else
      point_integral_gradient(pg, pts, g);
    EXPECT_TRUE(g.allFinite()) << where << " " << method_name(area) << " gradient " << g.transpose();
    for (const PairHessian kind : {PairHessian::Exact, PairHessian::GaussNewton}) {
      PairVector gh;
      PairMatrix H;
      const double Ih = area ? area_integral_hessian(pg, p, kind, gh, H) : point_integral_hessian(pg, pts, kind, gh, H);
      const char* kname = kind == PairHessian::Exact ? "exact" : "Gauss-Newton";
      EXPECT_TRUE(std::isfinite(Ih)) << where << " " << method_name(area) << " " << kname;
      EXPECT_TRUE(gh.allFinite()) << where << " " << method_name(area) << " " << kname;
      EXPECT_TRUE(H.allFinite()) << where << " " << method_name(area) << " " << kname;
    }
  }
  if (p.count >= 3) {
    const double ref = collision::polygon_quadratic_integral(p, pg.depth).integral;
    const double dmax = pg.depth.maxCoeff();
    EXPECT_NEAR(area_integral(pg, p), ref, 1e-9 * (L * L * dmax * dmax) + 1e-12 * ref) << where;
  }
}

TEST(PairIntegralDegenerate, AdversarialPairsGiveFiniteNonNegativeValuesAndDerivatives) {
  std::mt19937 rng(811);
  std::uniform_real_distribution<double> u(-1, 1);
  int nonempty = 0;
  for (const Case& c : adversarial_cases()) {
    for (const double scale : {1.0, 1e-9, 1e6}) {
      for (const bool zero_depth : {false, true}) {
        PairGeometry pg;
        pg.depth = zero_depth ? Eigen::Vector4d(Eigen::Vector4d::Zero())
                              : Eigen::Vector4d(Eigen::Vector4d(0.1, 0.4, 0.7, 1.0) * scale);
        // As given (exact zeros), then after random rigid motions (round-off instead of zeros).
        pg.triangle = scale * c.triangle;
        pg.tet = scale * c.tet;
        const std::string where = c.name + " scale " + std::to_string(scale) + (zero_depth ? " zero depth" : "");
        expect_finite_everything(pg, where);
        if (zero_depth) {
          EXPECT_EQ(area_integral(pg, collision::clip_triangle_tet(pg.triangle, pg.tet)), 0.0) << where;
          EXPECT_EQ(point_integral(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet)), 0.0) << where;
        }
        nonempty += collision::clip_triangle_tet(pg.triangle, pg.tet).count >= 3;
        for (int r = 0; r < 4; ++r) {
          const Matrix3 rot = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
          const Vector3 shift(u(rng), u(rng), u(rng));
          PairGeometry q = pg;
          q.triangle = moved(c.triangle, rot, shift, scale);
          q.tet = moved(c.tet, rot, shift, scale);
          expect_finite_everything(q, where + " moved " + std::to_string(r));
        }
        // Reversed triangle orientation and permuted tet vertices.
        PairGeometry f = pg;
        f.triangle.row(1).swap(f.triangle.row(2));
        f.tet.row(0).swap(f.tet.row(3));
        std::swap(f.depth[0], f.depth[3]);
        expect_finite_everything(f, where + " flipped");
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
  EXPECT_GT(nonempty, 30);
}

TEST(PairIntegralDegenerate, RandomTrianglesWithVerticesOnTetFeatures) {
  // Triangle vertices at tet vertices, on tet edges and faces, or outside; optional rigid motion
  // and scaling to 1e-9 or 1e6.
  std::mt19937 rng(912);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 5);
  const std::array<double, 3> scales{1.0, 1e-9, 1e6};
  for (int trial = 0; trial < 600; ++trial) {
    const TetVertices tet = random_tet(rng);
    Matrix3 tri;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector4d xi(u(rng), u(rng), u(rng), u(rng));
      const int zeros = pick(rng);
      for (int z = 0; z < std::min(zeros, 3); ++z) xi[(i + z + trial) % 4] = 0.0;
      if (zeros >= 4) xi[(i + trial) % 4] = -0.5 * u(rng);
      xi /= xi.sum();
      tri.row(i) = (tet.transpose() * xi).transpose();
    }
    const double scale = scales[static_cast<std::size_t>(trial % 3)];
    const Matrix3 rot =
        trial % 2 ? Matrix3(Eigen::Quaterniond::UnitRandom().toRotationMatrix()) : Matrix3(Matrix3::Identity());
    const Vector3 shift = trial % 2 ? Vector3(u(rng), u(rng), u(rng)) : Vector3::Zero();
    PairGeometry pg;
    pg.triangle = moved(tri, rot, shift, scale);
    pg.tet = moved(tet, rot, shift, scale);
    pg.depth = scale * Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng));
    if (trial % 5 == 0) pg.depth.setZero();
    expect_finite_everything(pg, "trial " + std::to_string(trial));
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "trial " << trial << "\n" << pg.triangle << "\n" << pg.tet;
      return;
    }
  }
}

// Regression: a zero-area triangle (collinear or coincident vertices) whose clip has count >= 3
// used to give a NaN area integral (0.5 / |n| = inf times a zero fan area) and NaN gradients for
// both methods (d|n| = n / |n| at n = 0), so a collapsed surface triangle inside another body
// made ContactEnergy::value NaN. It contributes nothing: value 0, finite derivatives.
TEST(PairIntegralDegenerate, ZeroAreaTriangleGivesFiniteValues) {
  PairGeometry pg;
  pg.tet = unit_tet();
  pg.depth << 0.1, 0.4, 0.7, 1.0;
  std::vector<Matrix3> triangles(3);
  triangles[0] << 0.1, 0.1, 0.1, 0.2, 0.2, 0.2, 0.3, 0.3, 0.3;   // collinear, inside
  triangles[1] << -1, 0.2, 0.2, 2, 0.2, 0.2, 0.5, 0.2, 0.2;      // collinear, crossing
  triangles[2] << 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.3, 0.2, 0.1;   // two coincident vertices
  for (const Matrix3& t : triangles) {
    pg.triangle = t;
    const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
    const CollocationPoints c = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
    PairVector g;
    PairMatrix H;
    EXPECT_EQ(area_integral(pg, p), 0.0);
    area_integral_gradient(pg, p, g);
    EXPECT_TRUE(g.allFinite());
    area_integral_hessian(pg, p, PairHessian::Exact, g, H);
    EXPECT_TRUE(H.allFinite());
    EXPECT_EQ(point_integral(pg, c), 0.0);
    point_integral_gradient(pg, c, g);
    EXPECT_TRUE(g.allFinite());
    point_integral_hessian(pg, c, PairHessian::Exact, g, H);
    EXPECT_TRUE(H.allFinite());
  }
}

TEST(PairIntegralDegenerate, ScaleCovariance) {
  // Lengths and depths scaled by s: I scales by s^4, the gradient by s^3, the Hessian by s^2.
  std::mt19937 rng(1013);
  for (int trial = 0; trial < 30; ++trial) {
    const PairGeometry pg = trial % 2 ? random_pair(rng) : random_point_pair(rng, 1 + (trial / 2) % 3);
    if (min_abs_barycentric(pg) < 1e-6) continue;
    for (const double s : {1e-9, 1e6}) {
      PairGeometry q = pg;
      q.triangle *= s;
      q.tet *= s;
      q.depth *= s;
      for (const bool area : {true, false}) {
        const Derivatives a = pair_hessian(pg, area, PairHessian::Exact);
        const Derivatives b = pair_hessian(q, area, PairHessian::Exact);
        EXPECT_NEAR(b.value / std::pow(s, 4), a.value, 1e-10 * std::max(1e-3, a.value)) << method_name(area);
        EXPECT_LT(st::relative_error(b.gradient / std::pow(s, 3), a.gradient, 1e-3), 1e-10) << method_name(area);
        EXPECT_LT(st::relative_error(b.hessian / (s * s), a.hessian, 1e-3), 1e-9) << method_name(area);
      }
    }
  }
}

}  // namespace
}  // namespace sinew::contact
