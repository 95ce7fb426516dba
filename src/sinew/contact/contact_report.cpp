#include "sinew/contact/contact_report.hpp"

#include <algorithm>

namespace sinew::contact {
namespace {

/// The body of every node (#V), -1 for nodes in no contact triangle or tet; a surface
/// triangle's body wins over a tet's.
std::vector<Index> node_bodies(const ContactGeometry& g, Index nodes) {
  std::vector<Index> body(static_cast<std::size_t>(nodes), -1);
  for (Index t = 0; t < g.tets.rows(); ++t)
    for (int k = 0; k < 4; ++k) body[static_cast<std::size_t>(g.tets(t, k))] = g.tet_body[t];
  for (Index f = 0; f < g.surface.rows(); ++f)
    for (int k = 0; k < 3; ++k) body[static_cast<std::size_t>(g.surface(f, k))] = g.surface_body[f];
  return body;
}

/// |nodal force| over a third of the current area of the surface triangles around the node.
VectorX nodal_pressure(const ContactGeometry& g, const Positions& x, const NodalVectors& nodal_force) {
  VectorX node_area = VectorX::Zero(x.rows());
  for (Index f = 0; f < g.surface.rows(); ++f) {
    const Vector3 a = x.row(g.surface(f, 0)), b = x.row(g.surface(f, 1)), c = x.row(g.surface(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (int k = 0; k < 3; ++k) node_area[g.surface(f, k)] += area / 3;
  }
  VectorX pressure = VectorX::Zero(x.rows());
  for (Index a = 0; a < x.rows(); ++a)
    if (node_area[a] > 0) pressure[a] = nodal_force.row(a).norm() / node_area[a];
  return pressure;
}

}  // namespace

ContactReport contact_report(const CollisionSet& collisions) {
  const ContactGeometry& g = collisions.geometry();
  const Positions& x = collisions.positions();
  const PairIntegrator& integrator = collisions.integrator();
  const Index bodies = static_cast<Index>(g.penalty.rows());
  ContactReport r;
  r.num_bodies = bodies;
  r.body_pair_force.assign(static_cast<std::size_t>(bodies * bodies), Vector3::Zero());
  r.self_contact_force_magnitude = VectorX::Zero(bodies);
  r.body_pair_max_penetration.assign(static_cast<std::size_t>(bodies * bodies), 0.0);
  r.nodal_force = NodalVectors::Zero(x.rows(), 3);
  r.pairs = static_cast<Index>(collisions.pairs().size());
  r.energy = contact_energy_value(collisions, x);
  const std::vector<Index> node_body = node_bodies(g, x.rows());
  NodalVectors self_force = NodalVectors::Zero(x.rows(), 3);
  double depth_integral = 0;
  for (const ActivePair& p : collisions.pairs()) {
    const PairVector force = -pair_energy_gradient(collisions, p, x);
    const PolygonMoments m = integrator.moments(collisions.pair_geometry_at(x, p), p.support);
    r.area += m.area;
    depth_integral += m.depth_integral;
    r.max_penetration = std::max(r.max_penetration, m.max_depth);
    const auto nodes = collisions.nodes(p);
    const Index body_t = g.surface_body[p.triangle], body_e = g.tet_body[p.tet];
    const Index lo = std::min(body_t, body_e), hi = std::max(body_t, body_e);
    double& pair_max = r.body_pair_max_penetration[static_cast<std::size_t>(lo * bodies + hi)];
    pair_max = std::max(pair_max, m.max_depth);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Vector3 f = force.segment<3>(3 * static_cast<Index>(i));
      const Index a = nodes[i];
      r.nodal_force.row(a) += f.transpose();
      if (body_t == body_e)
        self_force.row(a) += f.transpose();
      else if (node_body[static_cast<std::size_t>(a)] == lo)
        r.body_pair_force[static_cast<std::size_t>(lo * bodies + hi)] += f;
    }
  }
  if (r.area > 0) r.mean_penetration = depth_integral / r.area;
  for (Index a = 0; a < x.rows(); ++a) {
    const Index body = node_body[static_cast<std::size_t>(a)];
    if (body >= 0) r.self_contact_force_magnitude[body] += 0.5 * self_force.row(a).norm();
  }
  r.nodal_pressure = nodal_pressure(g, x, r.nodal_force);
  return r;
}

ContactReport contact_report(const ContactEnergy& energy, const Positions& x) {
  if (energy.collisions().is_current(x)) return contact_report(energy.collisions());
  CollisionSet local(energy.collisions().shared_geometry(), energy.options().method, energy.options().candidate_cap);
  local.update(x);
  return contact_report(local);
}

}  // namespace sinew::contact
