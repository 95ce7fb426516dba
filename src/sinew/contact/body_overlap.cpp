#include "sinew/contact/body_overlap.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "sinew/contact/collision_set.hpp"

namespace sinew::contact {

std::vector<BodyOverlap> body_overlaps(const ContactGeometry& geometry, const Positions& x, ContactMethod method,
                                       double min_depth) {
  ContactGeometry every_pair = geometry;
  every_pair.node_immovable.clear();  // find the pairs contact leaves out too
  CollisionSet collisions(std::move(every_pair), method);
  collisions.update(x);
  const ContactGeometry& g = collisions.geometry();
  std::map<std::tuple<Index, Index, bool>, BodyOverlap> found;
  for (const ActivePair& p : collisions.pairs()) {
    const double depth = collisions.integrator().moments(collisions.pair_geometry_at(x, p), p.support).max_depth;
    if (!(depth > min_depth)) continue;
    const Index a = g.surface_body[p.triangle], b = g.tet_body[p.tet];
    const bool immovable = pair_is_immovable(geometry, p.triangle, p.tet);
    BodyOverlap& o = found[{std::min(a, b), std::max(a, b), immovable}];
    o.body_a = std::min(a, b);
    o.body_b = std::max(a, b);
    o.immovable = immovable;
    ++o.pairs;
    if (depth > o.max_depth) {
      o.max_depth = depth;
      o.place = (x.row(g.surface(p.triangle, 0)) + x.row(g.surface(p.triangle, 1)) + x.row(g.surface(p.triangle, 2)))
                    .transpose() / 3.0;
    }
  }
  std::vector<BodyOverlap> overlaps;
  for (const auto& [key, o] : found) overlaps.push_back(o);
  std::stable_sort(overlaps.begin(), overlaps.end(),
                   [](const BodyOverlap& l, const BodyOverlap& r) { return l.max_depth > r.max_depth; });
  return overlaps;
}

}  // namespace sinew::contact
