#include "sinew/contact/pair_integral.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "sinew/contact/dual.hpp"
#include "sinew/contact/gradient_tape.hpp"
#include "sinew/contact/tape.hpp"
#include "sinew/core/psd_projection.hpp"

namespace sinew::contact {
namespace {

using collision::ClipVertexKind;

/// A 3-vector over any scalar type (double, Dual, TapeScalar); Eigen needs NumTraits for custom
/// scalars, a plain struct does not.
template <class S>
struct Vec {
  S x, y, z;
  friend Vec operator+(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec operator-(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec operator*(const Vec& a, const S& s) { return {a.x * s, a.y * s, a.z * s}; }
};
template <class S>
S dot(const Vec<S>& a, const Vec<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class S>
Vec<S> cross(const Vec<S>& a, const Vec<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// The 7 nodes of a pair as scalars of type S (independent variables for the dual types).
template <class S>
struct Nodes {
  std::array<Vec<S>, 3> tri;
  std::array<Vec<S>, 4> tet;
};

template <class S>
S make_variable(double value, int index) {
  if constexpr (std::is_same_v<S, double>) {
    (void)index;
    return value;
  } else {
    return S::variable(value, index);
  }
}

/// The pair's nodes; those of `unknowns` are the variables, numbered in order from 0 (the
/// triangle's first when both vary), the others constants.
template <class S>
Nodes<S> make_nodes(const PairGeometry& pair, PairUnknowns unknowns = PairUnknowns::All) {
  const bool triangle_varies = unknowns != PairUnknowns::Tet, tet_varies = unknowns != PairUnknowns::Triangle;
  const int first_tet_variable = triangle_varies ? 9 : 0;
  const auto coordinate = [](double value, bool varies, int index) {
    return varies ? make_variable<S>(value, index) : S(value);
  };
  Nodes<S> n;
  for (int k = 0; k < 3; ++k)
    n.tri[k] = {coordinate(pair.triangle(k, 0), triangle_varies, 3 * k),
                coordinate(pair.triangle(k, 1), triangle_varies, 3 * k + 1),
                coordinate(pair.triangle(k, 2), triangle_varies, 3 * k + 2)};
  for (int k = 0; k < 4; ++k)
    n.tet[k] = {coordinate(pair.tet(k, 0), tet_varies, first_tet_variable + 3 * k),
                coordinate(pair.tet(k, 1), tet_varies, first_tet_variable + 3 * k + 1),
                coordinate(pair.tet(k, 2), tet_varies, first_tet_variable + 3 * k + 2)};
  return n;
}

/// Position of a clip-polygon vertex as a smooth function of the nodes.
template <class S>
Vec<S> polygon_vertex(const Nodes<S>& n, const collision::ClipVertexProvenance& p) {
  switch (p.kind) {
    case ClipVertexKind::TriangleVertex:
      return n.tri[static_cast<std::size_t>(p.a)];
    case ClipVertexKind::TriangleEdgeTetFace: {
      // Plane through the three tet vertices other than `face`.
      std::array<int, 3> v{};
      int m = 0;
      for (int k = 0; k < 4; ++k)
        if (k != p.face) v[static_cast<std::size_t>(m++)] = k;
      const Vec<S>& q0 = n.tet[static_cast<std::size_t>(v[0])];
      const Vec<S> normal = cross(n.tet[static_cast<std::size_t>(v[1])] - q0, n.tet[static_cast<std::size_t>(v[2])] - q0);
      const Vec<S>& xa = n.tri[static_cast<std::size_t>(p.a)];
      const Vec<S> edge = n.tri[static_cast<std::size_t>(p.b)] - xa;
      const S s = dot(normal, q0 - xa) / dot(normal, edge);
      return xa + edge * s;
    }
    case ClipVertexKind::TetEdgeTrianglePlane: {
      const Vec<S> normal = cross(n.tri[1] - n.tri[0], n.tri[2] - n.tri[0]);
      const Vec<S>& qa = n.tet[static_cast<std::size_t>(p.a)];
      const Vec<S> edge = n.tet[static_cast<std::size_t>(p.b)] - qa;
      const S s = dot(normal, n.tri[0] - qa) / dot(normal, edge);
      return qa + edge * s;
    }
  }
  return n.tri[0];
}

/// The affine depth field of the tet: g(y) = d0 + G . (y - q0).
template <class S>
struct DepthField {
  S d0;
  Vec<S> q0;
  Vec<S> G;
  S at(const Vec<S>& y) const { return d0 + dot(G, y - q0); }
};

template <class S>
DepthField<S> depth_field(const Nodes<S>& n, const Eigen::Vector4d& depth) {
  const Vec<S> e1 = n.tet[1] - n.tet[0], e2 = n.tet[2] - n.tet[0], e3 = n.tet[3] - n.tet[0];
  const Vec<S> c1 = cross(e2, e3), c2 = cross(e3, e1), c3 = cross(e1, e2);
  const S volume6 = dot(e1, c1);
  const S inv = S(1.0) / volume6;
  Vec<S> G = c1 * S(depth[1] - depth[0]) + c2 * S(depth[2] - depth[0]) + c3 * S(depth[3] - depth[0]);
  G = G * inv;
  return {S(depth[0]), n.tet[0], G};
}

/// Depths at the polygon vertices and signed fan-triangle areas (fan from vertex 0), measured
/// along the triangle's unit normal, so they are smooth even when a fan triangle degenerates.
template <class S>
struct Fan {
  int count = 0;
  bool has_multiplier = false;  ///< q is not zero at some triangle vertex
  std::array<S, collision::kMaxClipVertices> g;
  std::array<S, collision::kMaxClipVertices> area;  ///< area[j], j = 1 .. count-2
  std::array<Vec<S>, collision::kMaxClipVertices> shape;  ///< (N0, N1, N2) of the triangle at each vertex
  std::array<S, collision::kMaxClipVertices> q;     ///< multiplier q at each vertex (when has_multiplier)
};

/// The triangle's linear shape functions (N0, N1, N2) at a point y of its plane.
template <class S>
Vec<S> triangle_shape(const Nodes<S>& n, const Vec<S>& normal, const S& inv_normal_sq, const Vec<S>& y) {
  const Vec<S> ya = y - n.tri[0];
  const S n1 = dot(cross(ya, n.tri[2] - n.tri[0]), normal) * inv_normal_sq;
  const S n2 = dot(cross(n.tri[1] - n.tri[0], ya), normal) * inv_normal_sq;
  return {S(1.0) - n1 - n2, n1, n2};
}

/// The fan of the polygon: depths, areas and, when `shape_functions` or the pair has
/// multipliers, the triangle's shape functions at the polygon's vertices (and q there).
template <class S>
Fan<S> make_fan(const Nodes<S>& n, const PairGeometry& pair, const collision::ClipPolygon& polygon,
                bool shape_functions = false) {
  const Eigen::Vector4d& depth = pair.depth;
  Fan<S> fan;
  fan.count = polygon.count;
  fan.has_multiplier = pair.multiplier.cwiseAbs().maxCoeff() > 0;
  if (polygon.count < 3) return fan;
  const DepthField<S> field = depth_field(n, depth);
  std::array<Vec<S>, collision::kMaxClipVertices> p;
  for (int k = 0; k < polygon.count; ++k) {
    p[static_cast<std::size_t>(k)] = polygon_vertex(n, polygon.provenance[static_cast<std::size_t>(k)]);
    fan.g[static_cast<std::size_t>(k)] = field.at(p[static_cast<std::size_t>(k)]);
  }
  const Vec<S> normal = cross(n.tri[1] - n.tri[0], n.tri[2] - n.tri[0]);
  const S half_inv_length = S(0.5) / sqrt(dot(normal, normal));
  for (int j = 1; j + 1 < polygon.count; ++j) {
    const auto J = static_cast<std::size_t>(j);
    fan.area[J] = dot(normal, cross(p[J] - p[0], p[J + 1] - p[0])) * half_inv_length;
  }
  if (fan.has_multiplier || shape_functions) {
    const S inv_normal_sq = S(1.0) / dot(normal, normal);
    for (int k = 0; k < polygon.count; ++k) {
      const auto K = static_cast<std::size_t>(k);
      const Vec<S> N = triangle_shape(n, normal, inv_normal_sq, p[K]);
      fan.shape[K] = N;
      fan.q[K] = N.x * S(pair.multiplier[0]) + N.y * S(pair.multiplier[1]) + N.z * S(pair.multiplier[2]);
    }
  }
  return fan;
}

/// ∫ over a triangle of the product of affine f and h with vertex values (a, b, c) and (u, v, w):
/// A/12 (a u + b v + c w + (a+b+c)(u+v+w)).
template <class S>
S triangle_product_integral(const S& area, const S& a, const S& b, const S& c, const S& u, const S& v,
                            const S& w) {
  return area * (a * u + b * v + c * w + (a + b + c) * (u + v + w)) * (1.0 / 12.0);
}

/// ∫ over a triangle of an affine f with vertex values a, b, c: A/12 (a² + b² + c² + (a+b+c)²).
template <class S>
S triangle_square_integral(const S& area, const S& a, const S& b, const S& c) {
  const S sum = a + b + c;
  return area * (a * a + b * b + c * c + sum * sum) * (1.0 / 12.0);
}

/// The value of a scalar of any of the types above (for comparisons).
template <class S>
double value_of(const S& s) {
  if constexpr (std::is_same_v<S, double>) {
    return s;
  } else if constexpr (requires { s.v(); }) {
    return s.v();
  } else {
    return s.v;
  }
}

/// ∫ over a triangle of q g² for affine q and g with vertex values (q0, q1, q2), (g0, g1, g2):
/// A/60 (Q G² + 2 G Σ qᵢgᵢ + Q Σ gᵢ² + 2 Σ qᵢgᵢ²), Q = Σ qᵢ, G = Σ gᵢ (from ∫ λᵢλⱼλₖ da).
template <class S>
S triangle_cubic_integral(const S& area, const std::array<S, 3>& q, const std::array<S, 3>& g) {
  const S Q = q[0] + q[1] + q[2], G = g[0] + g[1] + g[2];
  const S qg = q[0] * g[0] + q[1] * g[1] + q[2] * g[2];
  const S gg = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  const S qgg = q[0] * g[0] * g[0] + q[1] * g[1] * g[1] + q[2] * g[2] * g[2];
  return area * (Q * G * G + 2.0 * G * qg + Q * gg + 2.0 * qgg) * (1.0 / 60.0);
}

/// ∫ q r(g) da over one triangle of area A, q and g affine with the vertex values given, r the
/// onset ramp of width δ > 0 (pair_integral.hpp): the triangle is split along g = δ into the
/// part below (∫ q g² / (2δ)) and the part above (∫ q (g − δ/2)), each integrated exactly.
/// The split points lie on the edges at the parameter t where g = δ; the pieces' areas are
/// fractions of A in t, so everything stays a smooth function of the vertex values.
template <class S>
S triangle_ramp_integral(const S& area, const std::array<S, 3>& q, const std::array<S, 3>& g, double delta) {
  const auto below_part = [&](const S& a, const std::array<S, 3>& qs, const std::array<S, 3>& gs) {
    return triangle_cubic_integral(a, qs, gs) * (0.5 / delta);
  };
  const auto above_part = [&](const S& a, const std::array<S, 3>& qs, const std::array<S, 3>& gs) {
    return triangle_product_integral(a, qs[0], qs[1], qs[2], gs[0] - 0.5 * delta, gs[1] - 0.5 * delta,
                                     gs[2] - 0.5 * delta);
  };
  int above = 0;
  for (int k = 0; k < 3; ++k) above += value_of(g[static_cast<std::size_t>(k)]) >= delta ? 1 : 0;
  if (above == 0) return below_part(area, q, g);
  if (above == 3) return above_part(area, q, g);
  // The vertex alone on its side (a), then the other two (b, c) in cyclic order.
  int lone = 0;
  for (int k = 0; k < 3; ++k) {
    const bool is_above = value_of(g[static_cast<std::size_t>(k)]) >= delta;
    if (is_above == (above == 1)) lone = k;
  }
  const auto a = static_cast<std::size_t>(lone), b = static_cast<std::size_t>((lone + 1) % 3),
             c = static_cast<std::size_t>((lone + 2) % 3);
  // g crosses δ strictly between a and b and between a and c: g[b] - g[a] != 0.
  const S tb = (S(delta) - g[a]) / (g[b] - g[a]);
  const S tc = (S(delta) - g[a]) / (g[c] - g[a]);
  const S qb = q[a] + (q[b] - q[a]) * tb, qc = q[a] + (q[c] - q[a]) * tc;
  const S at_delta(delta);
  // Pieces: (a, Pb, Pc) with area tb tc A; (Pb, b, c) with (1 - tb) A; (Pb, c, Pc) with tb (1 - tc) A.
  const std::array<S, 3> q_lone{q[a], qb, qc}, g_lone{g[a], at_delta, at_delta};
  const std::array<S, 3> q_first{qb, q[b], q[c]}, g_first{at_delta, g[b], g[c]};
  const std::array<S, 3> q_second{qb, q[c], qc}, g_second{at_delta, g[c], at_delta};
  const S lone_area = area * tb * tc, first_area = area * (S(1.0) - tb), second_area = area * tb * (S(1.0) - tc);
  if (above == 1) {  // a above, b and c below
    return above_part(lone_area, q_lone, g_lone) + below_part(first_area, q_first, g_first) +
           below_part(second_area, q_second, g_second);
  }
  return below_part(lone_area, q_lone, g_lone) + above_part(first_area, q_first, g_first) +
         above_part(second_area, q_second, g_second);
}

/// ∫ (g² + 2 q r(g)) da over the fan (r(g) = g without an onset ramp).
template <class S>
S fan_integral(const Fan<S>& fan, double onset) {
  S total(0.0);
  for (int j = 1; j + 1 < fan.count; ++j) {
    const auto J = static_cast<std::size_t>(j);
    total += triangle_square_integral(fan.area[J], fan.g[0], fan.g[J], fan.g[J + 1]);
    if (!fan.has_multiplier) continue;
    if (onset > 0) {
      total += triangle_ramp_integral(fan.area[J], {fan.q[0], fan.q[J], fan.q[J + 1]},
                                      {fan.g[0], fan.g[J], fan.g[J + 1]}, onset) * 2.0;
    } else {
      total += triangle_product_integral(fan.area[J], fan.g[0], fan.g[J], fan.g[J + 1], fan.q[0], fan.q[J],
                                         fan.q[J + 1]) * 2.0;
    }
  }
  return total;
}

/// The onset ramp r(g) of a point (pair_integral.hpp).
template <class S>
S onset_ramp(const S& g, double onset) {
  if (!(onset > 0)) return g;
  if (value_of(g) >= onset) return g - 0.5 * onset;
  return g * g * (0.5 / onset);
}

template <class S>
S area_integral_t(const PairGeometry& pair, const collision::ClipPolygon& polygon,
                  PairUnknowns unknowns = PairUnknowns::All) {
  if (polygon.count < 3) return S(0.0);
  return fan_integral(make_fan(make_nodes<S>(pair, unknowns), pair, polygon), pair.multiplier_onset);
}

template <class S>
S point_integral_t(const PairGeometry& pair, const collision::CollocationPoints& points,
                   PairUnknowns unknowns = PairUnknowns::All) {
  if (points.count == 0) return S(0.0);
  const Nodes<S> n = make_nodes<S>(pair, unknowns);
  const DepthField<S> field = depth_field(n, pair.depth);
  const Vec<S> normal = cross(n.tri[1] - n.tri[0], n.tri[2] - n.tri[0]);
  const S weight = sqrt(dot(normal, normal)) * (0.5 / 3.0);
  S total(0.0);
  for (int k = 0; k < points.count; ++k) {
    const int v = points.vertex[static_cast<std::size_t>(k)];
    const S g = field.at(n.tri[static_cast<std::size_t>(v)]);
    total += weight * (g * g + S(2.0 * pair.multiplier[v]) * onset_ramp(g, pair.multiplier_onset));
  }
  return total;
}

/// A zero-area triangle (collinear or coincident vertices) has no surface to integrate over and
/// no normal to differentiate: its pairs contribute nothing.
bool degenerate_triangle(const PairGeometry& pair) {
  const Vector3 a = pair.triangle.row(0), b = pair.triangle.row(1), c = pair.triangle.row(2);
  const double scale = (b - a).squaredNorm() + (c - a).squaredNorm() + (c - b).squaredNorm();
  return !((b - a).cross(c - a).norm() > 1e-12 * scale);
}

using D1 = Dual<kPairVariables>;
using RS = ReverseScalar;

/// Exact gradient of f<ReverseScalar>() by one reverse sweep.
template <class F>
double tape_gradient(F&& f, PairVector& gradient) {
  thread_local GradientTape tape;
  const GradientTape::Scope scope(tape);
  const RS I = f();
  tape.gradient(I.node, gradient);
  return I.v;
}
/// Exact gradient and Hessian of f(TapeScalar<N>{}) (f is generic in its scalar type) by
/// reverse-over-forward differentiation, with respect to N variables that are the pair's
/// variables first .. first + N - 1; the rest of `gradient` and `hessian` is zero.
template <int N, class F>
double tape_hessian_of(F&& f, int first, PairVector& gradient, PairMatrix& hessian) {
  thread_local Tape<N> tape;
  const typename Tape<N>::Scope scope(tape);
  const TapeScalar<N> I = f(TapeScalar<N>{});
  if constexpr (N == kPairVariables) {
    tape.gradient_and_hessian(I.node, gradient, hessian);
  } else {
    Eigen::Matrix<double, N, 1> g;
    Eigen::Matrix<double, N, N> h;
    tape.gradient_and_hessian(I.node, g, h);
    gradient.setZero();
    hessian.setZero();
    gradient.template segment<N>(first) = g;
    hessian.template block<N, N>(first, first) = h;
  }
  return I.v();
}

/// tape_hessian_of for the variables of `unknowns` (Triangle: 0..8, Tet: 9..20, All: 0..20).
template <class F>
double tape_hessian(F&& f, PairUnknowns unknowns, PairVector& gradient, PairMatrix& hessian) {
  switch (unknowns) {
    case PairUnknowns::Triangle:
      return tape_hessian_of<9>(f, 0, gradient, hessian);
    case PairUnknowns::Tet:
      return tape_hessian_of<12>(f, 9, gradient, hessian);
    case PairUnknowns::All:
      break;
  }
  return tape_hessian_of<kPairVariables>(f, 0, gradient, hessian);
}

/// The tape's Hessian of `kind` for integral(scalar, unknowns) (Exact: with respect to
/// `unknowns`; Projected: all 21 variables, then projected onto the PSD cone), or nothing for
/// GaussNewton, which each method forms itself.
template <class F>
std::optional<double> tape_hessian_of_kind(F&& integral, PairHessian kind, PairUnknowns unknowns,
                                           PairVector& gradient, PairMatrix& hessian) {
  if (kind == PairHessian::GaussNewton) return std::nullopt;
  const PairUnknowns wanted = kind == PairHessian::Exact ? unknowns : PairUnknowns::All;
  const double I = tape_hessian([&]<class S>(S s) { return integral(s, wanted); }, wanted, gradient, hessian);
  if (kind == PairHessian::Projected) hessian = project_to_psd(hessian);
  return I;
}

}  // namespace

double area_integral(const PairGeometry& pair, const collision::ClipPolygon& polygon) {
  if (degenerate_triangle(pair)) return 0;
  return area_integral_t<double>(pair, polygon);
}

double area_integral_gradient(const PairGeometry& pair, const collision::ClipPolygon& polygon, PairVector& gradient) {
  if (degenerate_triangle(pair)) {
    gradient.setZero();
    return 0;
  }
  return tape_gradient([&] { return area_integral_t<RS>(pair, polygon); }, gradient);
}

double area_integral_hessian(const PairGeometry& pair, const collision::ClipPolygon& polygon, PairHessian kind,
                             PairVector& gradient, PairMatrix& hessian, PairUnknowns unknowns) {
  if (degenerate_triangle(pair)) {
    gradient.setZero();
    hessian.setZero();
    return 0;
  }
  const auto integral = [&]<class S>(S, PairUnknowns wanted) { return area_integral_t<S>(pair, polygon, wanted); };
  if (const auto I = tape_hessian_of_kind(integral, kind, unknowns, gradient, hessian)) return *I;
  // Gauss-Newton: per fan triangle, A/12 (a² + b² + c² + s²) -> A/6 (∇a∇aᵀ + ∇b∇bᵀ + ∇c∇cᵀ + ∇s∇sᵀ)
  // with the areas frozen (and clamped at 0, so the sum stays positive semi-definite).
  hessian.setZero();
  gradient.setZero();
  if (polygon.count < 3) return 0;
  // The multiplier term 2 q r(g) contributes to the gradient (through fan_integral) but not to
  // this Hessian: Gauss-Newton keeps the positive part.
  const Fan<D1> fan = make_fan(make_nodes<D1>(pair), pair, polygon);
  const D1 I = fan_integral(fan, pair.multiplier_onset);
  gradient = I.d;
  // Σ_j w_j (∇a∇aᵀ + ∇b∇bᵀ + ∇c∇cᵀ + ∇s∇sᵀ) = Gᵀ C G, G the count x 21 depth gradients at the
  // polygon vertices and C the count x count weights (cheaper than the rank-one updates).
  const int count = fan.count;
  Eigen::Matrix<double, collision::kMaxClipVertices, collision::kMaxClipVertices> C;
  C.setZero();
  for (int j = 1; j + 1 < count; ++j) {
    const double w = std::max(0.0, fan.area[static_cast<std::size_t>(j)].v) / 6.0;
    const int v[3] = {0, j, j + 1};
    for (int r = 0; r < 3; ++r) {
      C(v[r], v[r]) += w;  // ∇a∇aᵀ
      for (int c = 0; c < 3; ++c) C(v[r], v[c]) += w;  // ∇s∇sᵀ, s = a + b + c
    }
  }
  Eigen::Matrix<double, Eigen::Dynamic, kPairVariables, 0, collision::kMaxClipVertices, kPairVariables> G(count,
                                                                                                        kPairVariables);
  for (int k = 0; k < count; ++k) G.row(k) = fan.g[static_cast<std::size_t>(k)].d.transpose();
  hessian.noalias() = G.transpose() * (C.topLeftCorner(count, count) * G);
  return I.v;
}

PolygonMoments area_moments(const PairGeometry& pair, const collision::ClipPolygon& polygon) {
  PolygonMoments m;
  if (polygon.count < 3 || degenerate_triangle(pair)) return m;
  const Fan<double> fan = make_fan(make_nodes<double>(pair), pair, polygon, /*shape_functions=*/true);
  for (int k = 0; k < fan.count; ++k) m.max_depth = std::max(m.max_depth, fan.g[static_cast<std::size_t>(k)]);
  for (int j = 1; j + 1 < fan.count; ++j) {
    const auto J = static_cast<std::size_t>(j);
    m.area += fan.area[J];
    m.depth_integral += fan.area[J] * (fan.g[0] + fan.g[J] + fan.g[J + 1]) / 3.0;
    const std::array<const Vec<double>*, 3> N{&fan.shape[0], &fan.shape[J], &fan.shape[J + 1]};
    const double ga = fan.g[0], gb = fan.g[J], gc = fan.g[J + 1];
    const double shape[3][3] = {{N[0]->x, N[1]->x, N[2]->x}, {N[0]->y, N[1]->y, N[2]->y}, {N[0]->z, N[1]->z, N[2]->z}};
    for (int v = 0; v < 3; ++v) {
      const double* s = shape[v];
      m.vertex_area[v] += fan.area[J] * (s[0] + s[1] + s[2]) / 3.0;
      m.vertex_depth_integral[v] += triangle_product_integral(fan.area[J], s[0], s[1], s[2], ga, gb, gc);
    }
  }
  return m;
}

double onset_ramp_slope(double g, double onset) { return onset > 0 ? std::min(1.0, g / onset) : 1.0; }

Vector3 depth_gradient(const PairGeometry& pair) {
  const Nodes<double> n = make_nodes<double>(pair);
  const Vec<double> e1 = n.tet[1] - n.tet[0], e2 = n.tet[2] - n.tet[0], e3 = n.tet[3] - n.tet[0];
  if (!(std::abs(dot(e1, cross(e2, e3))) > 0)) return Vector3::Zero();
  const Vec<double> G = depth_field(n, pair.depth).G;
  return {G.x, G.y, G.z};
}

Vector3 triangle_shape_functions(const PairGeometry& pair, const Vector3& y) {
  const Nodes<double> n = make_nodes<double>(pair);
  const Vec<double> normal = cross(n.tri[1] - n.tri[0], n.tri[2] - n.tri[0]);
  const Vec<double> N = triangle_shape(n, normal, 1.0 / dot(normal, normal), Vec<double>{y.x(), y.y(), y.z()});
  return {N.x, N.y, N.z};
}

double point_integral(const PairGeometry& pair, const collision::CollocationPoints& points) {
  if (degenerate_triangle(pair)) return 0;
  return point_integral_t<double>(pair, points);
}

double point_integral_gradient(const PairGeometry& pair, const collision::CollocationPoints& points,
                               PairVector& gradient) {
  if (degenerate_triangle(pair)) {
    gradient.setZero();
    return 0;
  }
  return tape_gradient([&] { return point_integral_t<RS>(pair, points); }, gradient);
}

double point_integral_hessian(const PairGeometry& pair, const collision::CollocationPoints& points,
                              PairHessian kind, PairVector& gradient, PairMatrix& hessian, PairUnknowns unknowns) {
  if (degenerate_triangle(pair)) {
    gradient.setZero();
    hessian.setZero();
    return 0;
  }
  const auto integral = [&]<class S>(S, PairUnknowns wanted) { return point_integral_t<S>(pair, points, wanted); };
  if (const auto I = tape_hessian_of_kind(integral, kind, unknowns, gradient, hessian)) return *I;
  hessian.setZero();
  gradient.setZero();
  if (points.count == 0) return 0;
  const Nodes<D1> n = make_nodes<D1>(pair);
  const DepthField<D1> field = depth_field(n, pair.depth);
  const Vec<D1> normal = cross(n.tri[1] - n.tri[0], n.tri[2] - n.tri[0]);
  const D1 weight = sqrt(dot(normal, normal)) * (0.5 / 3.0);
  D1 total(0.0);
  for (int k = 0; k < points.count; ++k) {
    const int v = points.vertex[static_cast<std::size_t>(k)];
    const D1 g = field.at(n.tri[static_cast<std::size_t>(v)]);
    total += weight * (g * g + D1(2.0 * pair.multiplier[v]) * onset_ramp(g, pair.multiplier_onset));
    hessian.noalias() += (2.0 * weight.v) * g.d * g.d.transpose();
  }
  gradient = total.d;
  return total.v;
}

PolygonMoments point_moments(const PairGeometry& pair, const collision::CollocationPoints& points) {
  PolygonMoments m;
  if (points.count == 0 || degenerate_triangle(pair)) return m;
  const Nodes<double> n = make_nodes<double>(pair);
  const DepthField<double> field = depth_field(n, pair.depth);
  const Vec<double> normal = cross(n.tri[1] - n.tri[0], n.tri[2] - n.tri[0]);
  const double weight = std::sqrt(dot(normal, normal)) * (0.5 / 3.0);
  for (int k = 0; k < points.count; ++k) {
    const int v = points.vertex[static_cast<std::size_t>(k)];
    const double g = field.at(n.tri[static_cast<std::size_t>(v)]);
    m.area += weight;
    m.depth_integral += weight * g;
    m.max_depth = std::max(m.max_depth, g);
    m.vertex_area[v] += weight;
    m.vertex_depth_integral[v] += weight * g;
  }
  return m;
}

}  // namespace sinew::contact
