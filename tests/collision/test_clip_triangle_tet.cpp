#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <iostream>
#include <random>

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/collision/polygon_quadrature.hpp"
#include "support/tet_geometry.hpp"

using namespace sinew;
using namespace sinew::collision;

namespace {

using sinew::testing::polygon_area;
using sinew::testing::random_tet;
using sinew::testing::reference_barycentric;
using sinew::testing::TetMatrix;
using sinew::testing::triangle_area;
using sinew::testing::unit_tet;

bool inside_closed(const Vector3& x, const TetMatrix& tet, double tol) {
  const Eigen::Vector4d xi = reference_barycentric(x, tet);
  return (xi.array() >= -tol).all();
}

/// Area of triangle ∩ tet by point-in-tet tests at the centroids of the n² sub-triangles of a
/// uniform subdivision of the triangle.
double sampled_area(const Matrix3& tri, const TetMatrix& tet, int n) {
  const Vector3 q0 = tri.row(0), q1 = tri.row(1), q2 = tri.row(2);
  Eigen::Matrix4d m;
  m.topRows<3>() = tet.transpose();
  m.row(3).setOnes();
  const Eigen::Matrix4d inv = m.inverse();
  long inside = 0;
  auto test = [&](double u, double v) {
    const Vector3 x = q0 + u * (q1 - q0) + v * (q2 - q0);
    Eigen::Vector4d rhs;
    rhs << x, 1.0;
    if (((inv * rhs).array() >= 0.0).all()) ++inside;
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; i + j < n; ++j) {
      test((i + 1.0 / 3) / n, (j + 1.0 / 3) / n);
      if (i + j + 1 < n) test((i + 2.0 / 3) / n, (j + 2.0 / 3) / n);
    }
  }
  return triangle_area(tri) * static_cast<double>(inside) / (static_cast<double>(n) * n);
}

Matrix3 random_triangle(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::RowVector3d c(0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng));
  Matrix3 t;
  for (int i = 0; i < 3; ++i) t.row(i) = c + size * Eigen::RowVector3d(u(rng), u(rng), u(rng));
  return t;
}

/// The properties every clip result must have, whatever the input.
void expect_sane(const ClipPolygon& p, const Matrix3& tri, const TetMatrix& tet, double tol) {
  ASSERT_GE(p.count, 0);
  ASSERT_LE(p.count, kMaxClipVertices);
  ASSERT_NE(p.count, 1);
  ASSERT_NE(p.count, 2);
  const double area = polygon_area(p);
  EXPECT_TRUE(std::isfinite(area));
  EXPECT_GE(area, 0.0);
  EXPECT_LE(area, triangle_area(tri) * (1 + 1e-12) + 1e-15);
  for (int k = 0; k < p.count; ++k) {
    EXPECT_TRUE(p.vertices[k].allFinite());
    EXPECT_TRUE(p.barycentric[k].allFinite());
    EXPECT_TRUE((p.barycentric[k].array() >= 0.0).all() && (p.barycentric[k].array() <= 1.0).all());
    EXPECT_NEAR(p.barycentric[k].sum(), 1.0, 1e-14);
    EXPECT_TRUE(inside_closed(p.vertices[k], tet, tol))
        << reference_barycentric(p.vertices[k], tet).transpose();
    // Barycentric coordinates consistent with the position.
    const Vector3 x = tet.transpose() * p.barycentric[k];
    EXPECT_LT((x - p.vertices[k]).norm(), 1e-12) << k;
    // Provenance indices in range.
    const auto& pr = p.provenance[k];
    switch (pr.kind) {
      case ClipVertexKind::TriangleVertex:
        EXPECT_TRUE(pr.a >= 0 && pr.a < 3 && pr.b == -1 && pr.face == -1);
        break;
      case ClipVertexKind::TriangleEdgeTetFace:
        EXPECT_TRUE(pr.a >= 0 && pr.a < pr.b && pr.b < 3 && pr.face >= 0 && pr.face < 4);
        break;
      case ClipVertexKind::TetEdgeTrianglePlane:
        EXPECT_TRUE(pr.a >= 0 && pr.a < pr.b && pr.b < 4 && pr.face == -1);
        break;
    }
  }
}

/// The vertex recomputed from its provenance and the raw node positions.
Vector3 reconstruct(const ClipVertexProvenance& pr, const Matrix3& tri, const TetMatrix& tet) {
  switch (pr.kind) {
    case ClipVertexKind::TriangleVertex:
      return tri.row(pr.a).transpose();
    case ClipVertexKind::TriangleEdgeTetFace: {
      Vector3 face[3];
      int n = 0;
      for (int a = 0; a < 4; ++a) {
        if (a != pr.face) face[n++] = tet.row(a).transpose();
      }
      const Vector3 m = (face[1] - face[0]).cross(face[2] - face[0]);
      const Vector3 qi = tri.row(pr.a).transpose(), qj = tri.row(pr.b).transpose();
      const double t = m.dot(face[0] - qi) / m.dot(qj - qi);
      return qi + t * (qj - qi);
    }
    case ClipVertexKind::TetEdgeTrianglePlane: {
      const Vector3 q0 = tri.row(0).transpose();
      const Vector3 n = (tri.row(1) - tri.row(0)).cross(tri.row(2) - tri.row(0)).transpose();
      const Vector3 pa = tet.row(pr.a).transpose(), pb = tet.row(pr.b).transpose();
      const double s = n.dot(q0 - pa) / n.dot(pb - pa);
      return pa + s * (pb - pa);
    }
  }
  return Vector3::Constant(std::nan(""));
}

Matrix3 rotate(const Matrix3& m, const Matrix3& r, const Vector3& shift) {
  Matrix3 out;
  for (int i = 0; i < 3; ++i) out.row(i) = (r * m.row(i).transpose() + shift).transpose();
  return out;
}

TetMatrix rotate(const TetMatrix& m, const Matrix3& r, const Vector3& shift) {
  TetMatrix out;
  for (int i = 0; i < 4; ++i) out.row(i) = (r * m.row(i).transpose() + shift).transpose();
  return out;
}

}  // namespace

TEST(ClipTriangleTet, AreaMatchesFineSampling) {
  std::mt19937 rng(7);
  int nonempty = 0;
  double max_error = 0;  // relative to the tolerance
  for (int trial = 0; trial < 60; ++trial) {
    const TetMatrix tet = random_tet(rng);
    // Centered near the tet's centroid so that most pairs intersect.
    Matrix3 tri = random_triangle(rng, trial % 2 ? 0.6 : 1.5);
    const Eigen::RowVector3d shift = tet.colwise().mean() - tri.colwise().mean();
    for (int i = 0; i < 3; ++i) tri.row(i) += 0.8 * shift;
    const ClipPolygon p = clip_triangle_tet(tri, tet);
    expect_sane(p, tri, tet, 1e-12);
    const int n = 600;
    const double reference = sampled_area(tri, tet, n);
    // Sampling error: of the order of one row of cells along the polygon's boundary.
    const double tolerance = 0.2 * triangle_area(tri) / n;
    EXPECT_NEAR(polygon_area(p), reference, tolerance) << "trial " << trial;
    max_error = std::max(max_error, std::abs(polygon_area(p) - reference) / tolerance);
    nonempty += p.count > 0;
  }
  EXPECT_GT(nonempty, 40);
  std::cout << "max sampling error / tolerance: " << max_error << "\n";
}

TEST(ClipTriangleTet, ProvenanceReconstructsEveryVertex) {
  std::mt19937 rng(11);
  int kinds[3] = {0, 0, 0};
  for (int trial = 0; trial < 400; ++trial) {
    const TetMatrix tet = random_tet(rng);
    const Matrix3 tri = random_triangle(rng, trial % 3 == 0 ? 2.5 : 0.8);
    const ClipPolygon p = clip_triangle_tet(tri, tet);
    expect_sane(p, tri, tet, 1e-12);
    for (int k = 0; k < p.count; ++k) {
      ++kinds[static_cast<int>(p.provenance[k].kind)];
      const Vector3 y = reconstruct(p.provenance[k], tri, tet);
      EXPECT_LT((y - p.vertices[k]).norm(), 1e-12) << "trial " << trial << " vertex " << k;
    }
  }
  EXPECT_GT(kinds[0], 20);
  EXPECT_GT(kinds[1], 20);
  EXPECT_GT(kinds[2], 20);
}

TEST(ClipTriangleTet, LargeTriangleGivesTheTetCrossSection) {
  // The plane z = 0.25 cuts the unit tet in a triangle with vertices on the edges 0-3, 1-3, 2-3.
  const TetMatrix tet = unit_tet();
  Matrix3 tri;
  tri << -5, -5, 0.25, 10, -5, 0.25, -5, 10, 0.25;
  const ClipPolygon p = clip_triangle_tet(tri, tet);
  expect_sane(p, tri, tet, 1e-12);
  ASSERT_EQ(p.count, 3);
  EXPECT_NEAR(polygon_area(p), 0.5 * 0.75 * 0.75, 1e-14);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(p.provenance[k].kind, ClipVertexKind::TetEdgeTrianglePlane);
    EXPECT_EQ(p.provenance[k].b, 3);
    EXPECT_NEAR(p.barycentric[k][3], 0.25, 1e-15);
  }
}

TEST(ClipTriangleTet, TriangleInsideIsReturnedWhole) {
  const TetMatrix tet = unit_tet();
  Matrix3 tri;
  tri << 0.1, 0.1, 0.1, 0.3, 0.1, 0.1, 0.1, 0.3, 0.2;
  const ClipPolygon p = clip_triangle_tet(tri, tet);
  ASSERT_EQ(p.count, 3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(p.provenance[k].kind, ClipVertexKind::TriangleVertex);
    EXPECT_EQ(p.provenance[k].a, k);
    EXPECT_EQ(p.vertices[k], Vector3(tri.row(k).transpose()));
  }
}

TEST(ClipTriangleTet, EmptyWhenOutsideOneFace) {
  const TetMatrix tet = unit_tet();
  Matrix3 far;
  far << 5, 5, 5, 6, 5, 5, 5, 6, 5;
  EXPECT_TRUE(clip_triangle_tet(far, tet).empty());
  // Overlaps the tet's bounding box but lies beyond the slanted face x + y + z = 1.
  Matrix3 beyond;
  beyond << 0.9, 0.9, 0.1, 0.5, 0.9, 0.5, 0.9, 0.5, 0.5;
  EXPECT_TRUE(clip_triangle_tet(beyond, tet).empty());
  // Degenerate tet.
  TetMatrix flat = tet;
  flat.row(3) << 0.5, 0.5, 0.0;
  Matrix3 tri;
  tri << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  EXPECT_TRUE(clip_triangle_tet(tri, flat).empty());
}

TEST(ClipTriangleTet, AdversarialConfigurations) {
  const TetMatrix tet = unit_tet();
  struct Case {
    const char* name;
    Matrix3 tri;
    double expected_area;  // < 0: not checked
    bool in_face_plane;     // the triangle lies in a face plane, oriented so that it counts
  };
  std::vector<Case> cases;
  auto add = [&](const char* name, std::initializer_list<double> v, double expected, bool in_face_plane = false) {
    Matrix3 m;
    auto it = v.begin();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = *it++;
    cases.push_back({name, m, expected, in_face_plane});
  };
  // Triangles in a face plane are given with their outward normal (away from their own body)
  // pointing into the tet: the half-open rule gives them to the tet, clipped by the other faces.
  add("equals face z=0", {0, 0, 0, 1, 0, 0, 0, 1, 0}, 0.5, true);
  add("in face plane, larger", {-1, -1, 0, 3, -1, 0, -1, 3, 0}, 0.5, true);
  add("in face plane, partly", {0.2, 0.2, 0, 2, 0.2, 0, 0.2, 2, 0}, 0.5 * 0.6 * 0.6, true);
  add("in slanted face plane", {1, 0, 0, 0, 0, 1, 0, 1, 0}, std::sqrt(3.0) / 2, true);
  add("vertex exactly on a face", {0.2, 0.2, 0, 0.2, 0.2, 0.5, 0.5, 0.2, 0.3}, -1);
  add("vertex on a tet vertex", {0, 0, 1, 0.3, 0.3, 0.3, -0.2, 0.5, 0.3}, -1);
  add("edge along a tet edge", {0, 0, 0, 1, 0, 0, 0.3, -0.5, 0.5}, -1);
  add("edge along a tet edge, in face", {0, 0, 0, 0.3, 0.0, 0.5, 1, 0, 0}, 0.25, true);
  add("edge longer than tet edge", {-1, 0, 0, 2, 0, 0, 0.3, 0.3, 0.3}, -1);
  add("zero area, collinear", {0.1, 0.1, 0.1, 0.2, 0.2, 0.2, 0.3, 0.3, 0.3}, 0);
  add("zero area, one point", {0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1}, 0);
  add("zero area, crossing", {-1, 0.2, 0.2, 2, 0.2, 0.2, 0.5, 0.2, 0.2}, 0);
  add("tet vertex on triangle", {-1, -1, 1, 2, -1, 1, -1, 2, 1}, 0);
  add("tet vertex inside triangle, tilted", {-1, -1, 0.9, 2, -1, 1.05, -1, 2, 1.05}, -1);
  add("through three tet vertices", {1, 0, 0, 0, 0, 1, 0, 1, 0}, std::sqrt(3.0) / 2, true);
  add("through two tet vertices, in slanted face", {1, 0, 0, 0, 0, 1, 0.2, 0.6, 0.2}, 0.3 * std::sqrt(3.0), true);
  add("nearly coplanar with face", {-1, -1, 1e-17, 3, -1, -1e-17, -1, 3, 2e-17}, 0.5, true);
  add("nearly coplanar, just outside", {-1, -1, -1e-9, 3, -1, -1e-9, -1, 3, -1e-9}, 0);
  add("tiny triangle at a vertex", {0, 0, 1, 1e-12, 0, 1, 0, 1e-12, 1}, -1);
  add("touching along an edge only", {0, 0, 0, 1, 0, 0, 0.5, -1, -0.5}, 0);

  std::mt19937 rng(3);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const ClipPolygon p = clip_triangle_tet(c.tri, tet);
    expect_sane(p, c.tri, tet, 1e-12);
    if (c.expected_area >= 0) {
      EXPECT_NEAR(polygon_area(p), c.expected_area, 1e-14);
    }
    // Both triangle orientations give the same area, except in a face plane, where the other
    // orientation's outward normal points away from the tet (nothing); all tet vertex orders
    // give the same area.
    Matrix3 flipped = c.tri;
    flipped.row(1).swap(flipped.row(2));
    const ClipPolygon pf = clip_triangle_tet(flipped, tet);
    expect_sane(pf, flipped, tet, 1e-12);
    EXPECT_NEAR(polygon_area(pf), c.in_face_plane ? 0.0 : polygon_area(p), 1e-14);
    std::array<int, 4> perm{0, 1, 2, 3};
    do {
      TetMatrix permuted;
      for (int i = 0; i < 4; ++i) permuted.row(i) = tet.row(perm[static_cast<std::size_t>(i)]);
      const ClipPolygon pp = clip_triangle_tet(c.tri, permuted);
      expect_sane(pp, c.tri, permuted, 1e-12);
      EXPECT_NEAR(polygon_area(pp), polygon_area(p), 1e-14);
    } while (std::next_permutation(perm.begin(), perm.end()));
    // Rotated and shifted (the exact zeros become round-off): still sane; the area agrees
    // except where an exact zero decides between inside and outside.
    for (int r = 0; r < 10; ++r) {
      const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
      const Matrix3 rot = q.toRotationMatrix();
      std::uniform_real_distribution<double> u(-1, 1);
      const Vector3 shift(u(rng), u(rng), u(rng));
      const Matrix3 tri_r = rotate(c.tri, rot, shift);
      const TetMatrix tet_r = rotate(tet, rot, shift);
      const ClipPolygon pr = clip_triangle_tet(tri_r, tet_r);
      expect_sane(pr, tri_r, tet_r, 1e-12);
      if (c.expected_area > 0) {
        EXPECT_NEAR(polygon_area(pr), c.expected_area, 1e-12);
      }
    }
  }
}

TEST(ClipTriangleTet, RandomDegenerateConfigurationsStaySane) {
  // Triangle vertices at tet vertices, on tet edges and faces (exact zeros in some barycentric
  // coordinates, then round-off after a random rigid motion), and some coincident vertices.
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 5);
  for (int trial = 0; trial < 3000; ++trial) {
    const TetMatrix tet = random_tet(rng);
    Matrix3 tri;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector4d xi(u(rng), u(rng), u(rng), u(rng));
      const int zeros = pick(rng);  // 0..3 zeros: interior, face, edge, vertex; 4, 5: outside
      for (int z = 0; z < std::min(zeros, 3); ++z) xi[(i + z + trial) % 4] = 0.0;
      if (zeros >= 4) xi[(i + trial) % 4] = -0.5 * u(rng);
      xi /= xi.sum();
      tri.row(i) = (tet.transpose() * xi).transpose();
    }
    if (trial % 7 == 0) tri.row(2) = tri.row(1);
    if (trial % 2 == 1) {
      const Matrix3 rot = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
      const Vector3 shift(u(rng), u(rng), u(rng));
      const Matrix3 tri_r = rotate(tri, rot, shift);
      const TetMatrix tet_r = rotate(tet, rot, shift);
      expect_sane(clip_triangle_tet(tri_r, tet_r), tri_r, tet_r, 1e-12);
    } else {
      expect_sane(clip_triangle_tet(tri, tet), tri, tet, 1e-12);
    }
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "trial " << trial << "\n" << tri << "\n" << tet;
      break;
    }
  }
}

TEST(ClipTriangleTet, AreaIsContinuousAlongSweeps) {
  const TetMatrix tet = unit_tet();
  struct Sweep {
    Matrix3 tri;
    Vector3 direction;
  };
  std::vector<Sweep> sweeps;
  Matrix3 t1;  // tilted, passes through tet vertices and edges
  t1 << -0.5, -0.5, -1.0, 1.5, -0.2, -0.7, -0.3, 1.6, -0.9;
  sweeps.push_back({t1, Vector3(0, 0, 1)});
  Matrix3 t2;  // in the plane z = 0.25, slides in x: its edges sweep over tet edges
  t2 << -1.0, 0.1, 0.25, -0.5, 0.1, 0.25, -0.75, 0.6, 0.25;
  sweeps.push_back({t2, Vector3(1, 0, 0)});
  Matrix3 t3;  // an edge coplanar with the face y = 0 as it passes
  t3 << -1.0, 0.0, 0.2, -0.4, 0.0, 0.2, -0.7, 0.5, 0.5;
  sweeps.push_back({t3, Vector3(1, 0, 0.1)});
  Matrix3 t4;  // large triangle cutting the whole tet, through its apex and base vertices
  t4 << -2, -2, -0.5, 3, -2, 0.5, -2, 3, 0.5;
  sweeps.push_back({t4, Vector3(0, 0, 1)});

  const double step = 1e-3;
  for (std::size_t s = 0; s < sweeps.size(); ++s) {
    SCOPED_TRACE(s);
    double previous = -1;
    double max_area = 0;
    // Bound on |dA/ds|: length of the polygon's moving boundary, at most the perimeter of
    // the triangle plus that of the tet's faces, over the cosine of the sweep angle.
    const double lipschitz = 20.0;
    for (int i = 0; i <= 2500; ++i) {
      Matrix3 tri = sweeps[s].tri;
      for (int r = 0; r < 3; ++r) tri.row(r) += (i * step * sweeps[s].direction).transpose();
      const ClipPolygon p = clip_triangle_tet(tri, tet);
      expect_sane(p, tri, tet, 1e-12);
      const double area = polygon_area(p);
      if (previous >= 0) {
        EXPECT_LE(std::abs(area - previous), lipschitz * step) << "i " << i;
      }
      previous = area;
      max_area = std::max(max_area, area);
    }
    EXPECT_GT(max_area, 0.05);
  }
}

TEST(ClipTriangleTet, CollocationPointsAreTheVerticesInTheClosedTet) {
  const TetMatrix tet = unit_tet();
  Matrix3 tri;
  tri << 0.1, 0.2, 0.3, 0.25, 0.25, 0.0, 2, 0, 0;  // inside, on the face z = 0, outside
  // The triangle's outward normal for this order is -(0.075, 0.525, 0.125): it points down, out
  // of the tet, at the vertex on the face z = 0, and the half-open rule does not count it.
  const CollocationPoints c = triangle_vertices_in_tet(tri, tet);
  ASSERT_EQ(c.count, 1);
  EXPECT_EQ(c.vertex[0], 0);
  EXPECT_LT((c.barycentric[0] - Eigen::Vector4d(0.4, 0.1, 0.2, 0.3)).norm(), 1e-15);
  // The other orientation's outward normal points up, into the tet: both vertices count.
  Matrix3 flipped = tri;
  flipped.row(1).swap(flipped.row(2));
  const CollocationPoints cf = triangle_vertices_in_tet(flipped, tet);
  ASSERT_EQ(cf.count, 2);
  EXPECT_EQ(cf.vertex[0], 0);
  EXPECT_EQ(cf.vertex[1], 2);
  EXPECT_LT((cf.barycentric[1] - Eigen::Vector4d(0.5, 0.25, 0.25, 0.0)).norm(), 1e-15);

  std::mt19937 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    const TetMatrix t = random_tet(rng);
    const Matrix3 q = random_triangle(rng, 0.8);
    const CollocationPoints cp = triangle_vertices_in_tet(q, t);
    int expected = 0;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector4d xi = reference_barycentric(q.row(i).transpose(), t);
      if ((xi.array() >= 0).all()) {
        ASSERT_LT(expected, cp.count);
        EXPECT_EQ(cp.vertex[static_cast<std::size_t>(expected)], i);
        EXPECT_LT((cp.barycentric[static_cast<std::size_t>(expected)] - xi).norm(), 1e-12);
        ++expected;
      }
    }
    EXPECT_EQ(cp.count, expected);
    // Every collocation vertex is also a vertex of the clip polygon.
    const ClipPolygon p = clip_triangle_tet(q, t);
    for (int k = 0; k < cp.count; ++k) {
      bool found = false;
      for (int j = 0; j < p.count; ++j) {
        found = found || (p.provenance[j].kind == ClipVertexKind::TriangleVertex &&
                          p.provenance[j].a == cp.vertex[static_cast<std::size_t>(k)]);
      }
      EXPECT_TRUE(found);
    }
  }
}

TEST(ClipTriangleTet, BarycentricMatchesReference) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const TetMatrix t = random_tet(rng);
    const Vector3 x(u(rng), u(rng), u(rng));
    EXPECT_LT((tet_barycentric(x, t) - reference_barycentric(x, t)).norm(), 1e-13);
  }
}
