#include "sinew/collision/point_triangle_distance.hpp"

#include <algorithm>
#include <array>

namespace sinew::collision {

Vector3 closest_point_on_segment(const Vector3& p, const Vector3& a, const Vector3& b, double& t) {
  const Vector3 ab = b - a;
  const double len2 = ab.squaredNorm();
  t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  if (t == 0.0) return a;
  if (t == 1.0) return b;
  return a + t * ab;
}

namespace {

PointTriangleResult make(const Vector3& p, const Vector3& closest, const Vector3& bary, TriangleRegion region) {
  PointTriangleResult r;
  r.closest = closest;
  r.barycentric = bary;
  r.region = region;
  r.squared_distance = (p - closest).squaredNorm();
  return r;
}

/// Degenerate triangle: nearest point on the three edges.
PointTriangleResult closest_on_edges(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c) {
  const std::array<const Vector3*, 3> v{&a, &b, &c};
  const std::array<TriangleRegion, 3> edge_region{TriangleRegion::EdgeAB, TriangleRegion::EdgeBC,
                                                  TriangleRegion::EdgeCA};
  const std::array<TriangleRegion, 3> vertex_region{TriangleRegion::VertexA, TriangleRegion::VertexB,
                                                    TriangleRegion::VertexC};
  PointTriangleResult best;
  bool have = false;
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = (e + 1) % 3;
    double t = 0.0;
    const Vector3 q = closest_point_on_segment(p, *v[i], *v[j], t);
    Vector3 bary = Vector3::Zero();
    bary[i] = 1.0 - t;
    bary[j] = t;
    const TriangleRegion region = t == 0.0 ? vertex_region[i] : (t == 1.0 ? vertex_region[j] : edge_region[e]);
    PointTriangleResult r = make(p, q, bary, region);
    if (!have || r.squared_distance < best.squared_distance) {
      best = r;
      have = true;
    }
  }
  return best;
}

}  // namespace

PointTriangleResult closest_point_on_triangle(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c) {
  const Vector3 ab = b - a, ac = c - a, bc = c - b;
  const double max_edge2 = std::max({ab.squaredNorm(), ac.squaredNorm(), bc.squaredNorm()});
  const double area2 = ab.cross(ac).squaredNorm();  // (2 * area)^2
  if (!(area2 > 1e-24 * max_edge2 * max_edge2)) return closest_on_edges(p, a, b, c);

  // Ericson's Voronoi-region tests; every denominator below is positive for a
  // non-degenerate triangle (|ab|^2, |ac|^2, |bc|^2, or |ab x ac|^2 up to rounding).
  const Vector3 ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return make(p, a, Vector3(1, 0, 0), TriangleRegion::VertexA);

  const Vector3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return make(p, b, Vector3(0, 1, 0), TriangleRegion::VertexB);

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return make(p, a + v * ab, Vector3(1 - v, v, 0), TriangleRegion::EdgeAB);
  }

  const Vector3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return make(p, c, Vector3(0, 0, 1), TriangleRegion::VertexC);

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return make(p, a + w * ac, Vector3(1 - w, 0, w), TriangleRegion::EdgeCA);
  }

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return make(p, b + w * bc, Vector3(0, 1 - w, w), TriangleRegion::EdgeBC);
  }

  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return make(p, a + v * ab + w * ac, Vector3(1 - v - w, v, w), TriangleRegion::Face);
}

}  // namespace sinew::collision
