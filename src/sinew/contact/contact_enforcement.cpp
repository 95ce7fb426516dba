#include "sinew/contact/contact_enforcement.hpp"

#include <algorithm>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace sinew::contact {

VectorX updated_contact_pressure(const CollisionSet& collisions) {
  const ContactGeometry& g = collisions.geometry();
  const Index nodes = g.depth.size();
  const Positions& x = collisions.positions();
  // Per node: the largest ε g over the supports of its triangles' pairs (-1: no pair), per thread.
  tbb::enumerable_thread_specific<VectorX> local([&] { return VectorX::Constant(nodes, -1.0); });
  const auto& pairs = collisions.pairs();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 64), [&](const auto& range) {
    VectorX& deepest = local.local();
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const ActivePair& p = pairs[k];
      const PolygonMoments m = collisions.integrator().moments(collisions.pair_geometry_at(x, p), p.support);
      if (!(m.area > 0)) continue;
      for (int v = 0; v < 3; ++v) {
        const Index node = g.surface(p.triangle, v);
        deepest[node] = std::max(deepest[node], p.penalty * m.max_depth);
      }
    }
  });
  VectorX deepest = VectorX::Constant(nodes, -1.0);
  for (const VectorX& d : local) deepest = deepest.cwiseMax(d);
  const VectorX& old = collisions.pressure();
  VectorX pressure = VectorX::Zero(nodes);
  for (Index i = 0; i < nodes; ++i)
    if (deepest[i] >= 0) pressure[i] = (old.size() > 0 ? old[i] : 0.0) + deepest[i];
  return pressure;
}

MatrixX grown_penalty(const MatrixX& penalty, const ContactReport& report, double tolerance, double max_growth) {
  MatrixX grown = penalty;
  for (Index a = 0; a < penalty.rows(); ++a)
    for (Index b = a; b < penalty.cols(); ++b) {
      const double g = report.max_penetration_between(a, b);
      if (!(penalty(a, b) > 0) || !(g > tolerance)) continue;
      const double factor = std::min(max_growth, 2.0 * g / tolerance);  // aim at half the tolerance
      grown(a, b) = grown(b, a) = penalty(a, b) * factor;
    }
  return grown;
}

double mean_surface_edge(const ContactGeometry& geometry, const Positions& x) {
  const Index triangles = geometry.surface.rows();
  if (triangles == 0) return 0;
  double sum = 0;
  for (Index f = 0; f < triangles; ++f)
    for (int k = 0; k < 3; ++k)
      sum += (x.row(geometry.surface(f, k)) - x.row(geometry.surface(f, (k + 1) % 3))).norm();
  return sum / static_cast<double>(3 * triangles);
}

}  // namespace sinew::contact
