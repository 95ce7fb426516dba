#include "sinew/collision/clip_triangle_tet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew::collision {

namespace {

using TetMatrix = Eigen::Matrix<double, 4, 3>;

/// Vertices of tet face f (the face opposite vertex f).
constexpr int kFace[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

/// Working capacity: clipping an n-gon by one plane gives at most n + n/2 vertices when
/// round-off makes it slightly non-convex (3 -> 4 -> 6 -> 9 -> 13), at most n + 1 otherwise.
constexpr int kWork = 16;

/// Supports (the lines carrying polygon edges): 0..2 triangle edge k = (k, k+1 mod 3),
/// 3..6 the line where the triangle's plane meets tet face f = support - 3.
constexpr std::int8_t kFaceSupport = 3;

struct WorkVertex {
  Vector3 x;
  Eigen::Vector4d xi;
  std::int8_t out = 0;            ///< support of the edge from this vertex to the next
  ClipVertexProvenance origin;    ///< provenance when created (fallback for degenerate pairs)
};

struct WorkPolygon {
  std::array<WorkVertex, kWork> v;
  int n = 0;
  void push(const WorkVertex& w) {
    if (n < kWork) v[static_cast<std::size_t>(n++)] = w;
  }
};

double snap(double value) { return std::abs(value) <= kClipSnap ? 0.0 : value; }

/// Provenance of a vertex between an edge with support `in` and one with support `out`.
ClipVertexProvenance provenance_from_supports(int in, int out) {
  ClipVertexProvenance p;
  if (in < kFaceSupport && out < kFaceSupport) {
    // Two triangle edges meet at their common vertex.
    for (const int v : {in, (in + 1) % 3}) {
      if (v == out || v == (out + 1) % 3) {
        p.kind = ClipVertexKind::TriangleVertex;
        p.a = static_cast<std::int8_t>(v);
        return p;
      }
    }
  }
  if (in < kFaceSupport || out < kFaceSupport) {
    const int edge = in < kFaceSupport ? in : out;
    const int face = (in < kFaceSupport ? out : in) - kFaceSupport;
    const int i = edge, j = (edge + 1) % 3;
    p.kind = ClipVertexKind::TriangleEdgeTetFace;
    p.a = static_cast<std::int8_t>(std::min(i, j));
    p.b = static_cast<std::int8_t>(std::max(i, j));
    p.face = static_cast<std::int8_t>(face);
    return p;
  }
  // Two face lines meet on the tet edge shared by both faces: the two other tet vertices.
  const int f = in - kFaceSupport, g = out - kFaceSupport;
  p.kind = ClipVertexKind::TetEdgeTrianglePlane;
  for (int a = 0; a < 4; ++a) {
    if (a == f || a == g) continue;
    if (p.a < 0) {
      p.a = static_cast<std::int8_t>(a);
    } else {
      p.b = static_cast<std::int8_t>(a);
    }
  }
  return p;
}

/// Sutherland-Hodgman step: keeps the part of `in` with xi_f >= 0 (snapped values).
void clip_by_face(const WorkPolygon& in, WorkPolygon& out, int f) {
  out.n = 0;
  const auto face_support = static_cast<std::int8_t>(kFaceSupport + f);
  auto crossing = [&](const WorkVertex& c, const WorkVertex& d, std::int8_t out_support) {
    const double dc = c.xi[f], dd = d.xi[f];
    const double t = std::clamp(dc / (dc - dd), 0.0, 1.0);  // dc, dd of strictly opposite signs
    WorkVertex w;
    w.x = c.x + t * (d.x - c.x);
    w.xi = c.xi + t * (d.xi - c.xi);
    for (int a = 0; a < 4; ++a) w.xi[a] = snap(w.xi[a]);
    w.xi[f] = 0.0;
    w.out = out_support;
    w.origin = provenance_from_supports(c.out, face_support);
    return w;
  };
  for (int k = 0; k < in.n; ++k) {
    const WorkVertex& c = in.v[static_cast<std::size_t>(k)];
    const WorkVertex& d = in.v[static_cast<std::size_t>((k + 1) % in.n)];
    const double dc = c.xi[f], dd = d.xi[f];
    const bool c_in = dc >= 0.0, d_in = dd >= 0.0;
    if (c_in) {
      out.push(c);
      if (!d_in) {
        if (dc == 0.0) {
          // c itself lies on the plane: the polygon leaves along the face line from c.
          out.v[static_cast<std::size_t>(out.n - 1)].out = face_support;
        } else {
          out.push(crossing(c, d, face_support));
        }
      }
    } else if (d_in && dd != 0.0) {
      // Re-entry; when d lies on the plane it is emitted as an inside vertex next.
      out.push(crossing(c, d, c.out));
    }
  }
}

/// Removes the vertex of smallest turning area until n <= kMaxClipVertices (only reached for
/// polygons made slightly non-convex by round-off, whose extra vertices are near-collinear).
void reduce_to_capacity(WorkPolygon& poly) {
  while (poly.n > kMaxClipVertices) {
    int worst = 0;
    double worst_area = std::numeric_limits<double>::infinity();
    for (int k = 0; k < poly.n; ++k) {
      const Vector3& p = poly.v[static_cast<std::size_t>((k + poly.n - 1) % poly.n)].x;
      const Vector3& c = poly.v[static_cast<std::size_t>(k)].x;
      const Vector3& q = poly.v[static_cast<std::size_t>((k + 1) % poly.n)].x;
      const double area = (c - p).cross(q - c).norm();
      if (area < worst_area) {
        worst_area = area;
        worst = k;
      }
    }
    for (int k = worst; k + 1 < poly.n; ++k) {
      poly.v[static_cast<std::size_t>(k)] = poly.v[static_cast<std::size_t>(k + 1)];
    }
    --poly.n;
  }
}

Eigen::Vector4d clamp_barycentric(Eigen::Vector4d xi) {
  for (int a = 0; a < 4; ++a) xi[a] = std::clamp(xi[a], 0.0, 1.0);
  const double sum = xi.sum();
  if (sum > 0.0) {
    xi /= sum;
  } else {
    xi.setConstant(0.25);
  }
  return xi;
}

/// Per-face data of the barycentric map xi_f(x) = n_f.(x - p_f) / D_f. The normal n_f and the
/// point p_f are computed from the face's three vertices sorted lexicographically by position, so
/// two tets sharing a face compute bitwise the same plane (only the sign of D_f differs): the
/// numerator n_f.(x - p_f), and with it the classification of x as inside, outside or on the
/// face, is the same for both, and a point on the face is given to exactly one of them.
struct FaceFrames {
  std::array<Vector3, 4> normal;
  std::array<Vector3, 4> point;
  std::array<double, 4> denominator{};
  /// |n_f.(x - p_f)| <= tolerance[f] (L³) puts x on the plane: kClipSnap times |n_f|_1 times the
  /// face's longest edge (about kClipSnap x height x |D_f| / height), from the face alone.
  std::array<double, 4> tolerance{};
};

bool lexicographically_less(const Vector3& a, const Vector3& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

FaceFrames face_frames(const TetMatrix& tet) {
  FaceFrames frames;
  for (int f = 0; f < 4; ++f) {
    std::array<Vector3, 3> v{tet.row(kFace[f][0]).transpose(), tet.row(kFace[f][1]).transpose(),
                             tet.row(kFace[f][2]).transpose()};
    std::sort(v.begin(), v.end(), lexicographically_less);
    const Vector3 e1 = v[1] - v[0], e2 = v[2] - v[0], e3 = v[2] - v[1];
    const auto fs = static_cast<std::size_t>(f);
    frames.normal[fs] = e1.cross(e2);
    frames.point[fs] = v[0];
    frames.denominator[fs] = frames.normal[fs].dot(tet.row(f).transpose() - v[0]);
    const double edge = std::max({e1.cwiseAbs().maxCoeff(), e2.cwiseAbs().maxCoeff(), e3.cwiseAbs().maxCoeff()});
    frames.tolerance[fs] = kClipSnap * frames.normal[fs].cwiseAbs().sum() * edge;
  }
  return frames;
}

Eigen::Vector4d barycentric_with(const FaceFrames& frames, const Vector3& x) {
  Eigen::Vector4d xi;
  for (std::size_t f = 0; f < 4; ++f) {
    xi[static_cast<Eigen::Index>(f)] =
        frames.normal[f].dot(x - frames.point[f]) / frames.denominator[f];
  }
  return xi;
}

bool usable_tet(const FaceFrames& frames) {
  for (const double d : frames.denominator) {
    if (!(std::abs(d) > 0.0) || !std::isfinite(d) || !std::isfinite(1.0 / d)) return false;
  }
  return true;
}

/// Barycentric coordinates of x with the ones of points on a face plane (within the face's
/// tolerance) set to exactly 0.
Eigen::Vector4d snapped_barycentric(const FaceFrames& frames, const Vector3& x) {
  Eigen::Vector4d xi;
  for (std::size_t f = 0; f < 4; ++f) {
    const double numerator = frames.normal[f].dot(x - frames.point[f]);
    xi[static_cast<Eigen::Index>(f)] =
        std::abs(numerator) <= frames.tolerance[f] ? 0.0 : numerator / frames.denominator[f];
  }
  return xi;
}

/// +1 when moving a point on face f's plane along `direction` enters the tet's side of the plane,
/// -1 when it leaves it, 0 when `direction` lies in the plane (to round-off: the same value for
/// both tets sharing the face, with opposite signs).
int side_of(const FaceFrames& frames, int f, const Vector3& direction) {
  const auto fs = static_cast<std::size_t>(f);
  const double along = frames.normal[fs].dot(direction);
  if (along == 0.0) return 0;
  return (along > 0.0) == (frames.denominator[fs] > 0.0) ? 1 : -1;
}

/// The half-open rule for a point on face f's plane (docs/contact.md): it belongs to the tet when
/// it moves into the tet under the perturbation x + δ d0 + δ² d1 + δ³ d2 + δ⁴ d3 (δ -> 0+), d0 the
/// outward normal of the triangle (`outward`, pointing away from the triangle's own body) and
/// d1..d3 tie_break_directions(). The first direction not in the plane decides.
bool on_face_counts(const FaceFrames& frames, int f, const Vector3& outward) {
  if (const int s = side_of(frames, f, outward); s != 0) return s > 0;
  for (const Vector3& d : tie_break_directions()) {
    if (const int s = side_of(frames, f, d); s != 0) return s > 0;
  }
  return false;  // unreachable: the tie-break directions span space
}

}  // namespace

const std::array<Vector3, 3>& tie_break_directions() {
  static const std::array<Vector3, 3> directions{Vector3(1.0, std::sqrt(2.0), std::sqrt(3.0)), Vector3::UnitX(),
                                                 Vector3::UnitY()};
  return directions;
}

Eigen::Vector4d tet_barycentric(const Vector3& x, const TetMatrix& tet) {
  return barycentric_with(face_frames(tet), x);
}

ClipPolygon clip_triangle_tet(const Matrix3& triangle, const TetMatrix& tet) {
  ClipPolygon result;
  const FaceFrames frames = face_frames(tet);
  if (!usable_tet(frames)) return result;

  // Snapped barycentric coordinates of the triangle vertices, one row per vertex.
  Eigen::Matrix<double, 3, 4> d;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector4d xi = snapped_barycentric(frames, triangle.row(i).transpose());
    for (int a = 0; a < 4; ++a) {
      if (!std::isfinite(xi[a])) return result;
      d(i, a) = xi[a];
    }
  }
  const Vector3 plane_normal =
      (triangle.row(1) - triangle.row(0)).cross(triangle.row(2) - triangle.row(0)).transpose();
  for (int f = 0; f < 4; ++f) {
    // Early exit: the triangle lies strictly outside one face plane.
    if (d(0, f) < 0.0 && d(1, f) < 0.0 && d(2, f) < 0.0) return result;
    // The triangle lies in the face plane: the half-open rule gives it to the tet on the side of
    // its outward normal only (a shared face counts once; a boundary face it touches from outside
    // counts, with the depth of that face).
    if (d(0, f) == 0.0 && d(1, f) == 0.0 && d(2, f) == 0.0 && !on_face_counts(frames, f, plane_normal))
      return result;
  }

  WorkPolygon a, b;
  for (int i = 0; i < 3; ++i) {
    WorkVertex w;
    w.x = triangle.row(i).transpose();
    w.xi = d.row(i).transpose();
    w.out = static_cast<std::int8_t>(i);
    w.origin.kind = ClipVertexKind::TriangleVertex;
    w.origin.a = static_cast<std::int8_t>(i);
    a.push(w);
  }
  WorkPolygon* cur = &a;
  WorkPolygon* next = &b;
  for (int f = 0; f < 4; ++f) {
    // Faces that every current vertex is inside of cannot clip.
    bool all_inside = true;
    for (int k = 0; k < cur->n; ++k) {
      all_inside = all_inside && cur->v[static_cast<std::size_t>(k)].xi[f] >= 0.0;
    }
    if (all_inside) continue;
    clip_by_face(*cur, *next, f);
    std::swap(cur, next);
    if (cur->n < 3) return result;
  }
  reduce_to_capacity(*cur);

  // Length scale for the consistency check of the canonical reconstruction.
  double scale = 0.0;
  for (int i = 0; i < 3; ++i) scale = std::max(scale, triangle.row(i).cwiseAbs().maxCoeff());
  for (int i = 0; i < 4; ++i) scale = std::max(scale, tet.row(i).cwiseAbs().maxCoeff());
  const double tolerance = 1e-9 * std::max(scale, std::numeric_limits<double>::min());

  const int n = cur->n;
  result.count = n;
  for (int k = 0; k < n; ++k) {
    const WorkVertex& w = cur->v[static_cast<std::size_t>(k)];
    const int in_support = cur->v[static_cast<std::size_t>((k + n - 1) % n)].out;
    const ClipVertexProvenance prov =
        in_support != w.out ? provenance_from_supports(in_support, w.out) : w.origin;

    // Recompute the vertex from its provenance (the formula derivatives will differentiate);
    // keep the clipped value if the canonical formula is ill-conditioned here.
    Vector3 x = w.x;
    Eigen::Vector4d xi = w.xi;
    if (prov.kind == ClipVertexKind::TriangleVertex) {
      x = triangle.row(prov.a).transpose();
      xi = d.row(prov.a).transpose();
    } else if (prov.kind == ClipVertexKind::TriangleEdgeTetFace) {
      const double di = d(prov.a, prov.face), dj = d(prov.b, prov.face);
      const double t = di / (di - dj);
      if (std::isfinite(t) && t >= -1e-9 && t <= 1.0 + 1e-9) {
        const double tc = std::clamp(t, 0.0, 1.0);
        const Vector3 qi = triangle.row(prov.a).transpose();
        const Vector3 qj = triangle.row(prov.b).transpose();
        const Vector3 y = qi + tc * (qj - qi);
        if ((y - w.x).norm() <= tolerance) {
          x = y;
          xi = (d.row(prov.a) + tc * (d.row(prov.b) - d.row(prov.a))).transpose();
          xi[prov.face] = 0.0;
        }
      }
    } else {
      const Vector3 q0 = triangle.row(0).transpose();
      const Vector3 pa = tet.row(prov.a).transpose();
      const Vector3 pb = tet.row(prov.b).transpose();
      const double ha = plane_normal.dot(pa - q0), hb = plane_normal.dot(pb - q0);
      const double s = ha / (ha - hb);
      if (std::isfinite(s) && s >= -1e-9 && s <= 1.0 + 1e-9) {
        const double sc = std::clamp(s, 0.0, 1.0);
        const Vector3 y = pa + sc * (pb - pa);
        if ((y - w.x).norm() <= tolerance) {
          x = y;
          xi.setZero();
          xi[prov.a] = 1.0 - sc;
          xi[prov.b] = sc;
        }
      }
    }
    const auto ks = static_cast<std::size_t>(k);
    result.vertices[ks] = x;
    result.barycentric[ks] = clamp_barycentric(xi);
    result.provenance[ks] = prov;
  }
  return result;
}

CollocationPoints triangle_vertices_in_tet(const Matrix3& triangle, const TetMatrix& tet) {
  CollocationPoints points;
  const FaceFrames frames = face_frames(tet);
  if (!usable_tet(frames)) return points;
  const Vector3 outward =
      (triangle.row(1) - triangle.row(0)).cross(triangle.row(2) - triangle.row(0)).transpose();
  for (int i = 0; i < 3; ++i) {
    const Vector3 x = triangle.row(i).transpose();
    const Eigen::Vector4d snapped = snapped_barycentric(frames, x);
    bool inside = true;
    for (int a = 0; a < 4 && inside; ++a) {
      inside = std::isfinite(snapped[a]) && snapped[a] >= 0.0;
      // On a face plane: the half-open rule decides (one tet of a conforming mesh gets the point).
      if (inside && snapped[a] == 0.0) inside = on_face_counts(frames, a, outward);
    }
    if (!inside) continue;
    const Eigen::Vector4d xi = barycentric_with(frames, x);
    const auto k = static_cast<std::size_t>(points.count++);
    points.vertex[k] = static_cast<std::int8_t>(i);
    points.barycentric[k] = clamp_barycentric(xi);
  }
  return points;
}

}  // namespace sinew::collision
