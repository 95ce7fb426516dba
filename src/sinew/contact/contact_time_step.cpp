#include "sinew/contact/contact_time_step.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace sinew::contact {

ContactTimeStep contact_critical_time_step(const ContactGeometry& geometry, const Positions& rest,
                                           const VectorX& nodal_mass) {
  // Programming error, not input: all three arrays are built over the same mesh.
  if (rest.rows() != nodal_mass.size() || rest.rows() != geometry.depth.size())
    throw std::invalid_argument("contact_critical_time_step: positions, masses and depths must have #V rows");
  const Index nodes = rest.rows();
  VectorX area = VectorX::Zero(nodes), penalty = VectorX::Zero(nodes);
  for (Index f = 0; f < geometry.surface.rows(); ++f) {
    const Vector3 a = rest.row(geometry.surface(f, 0)), b = rest.row(geometry.surface(f, 1)),
                  c = rest.row(geometry.surface(f, 2));
    const double third = 0.5 * (b - a).cross(c - a).norm() / 3;
    // The largest penalty this triangle can meet (the pair scale is the min of two factors,
    // at most the triangle's own).
    const double eps = geometry.penalty.row(geometry.surface_body[f]).maxCoeff() *
                       (geometry.surface_penalty_scale.size() > 0 ? geometry.surface_penalty_scale[f] : 1.0);
    for (int k = 0; k < 3; ++k) {
      const Index v = geometry.surface(f, k);
      area[v] += third;
      penalty[v] = std::max(penalty[v], eps);
    }
  }
  ContactTimeStep out;
  out.dt = std::numeric_limits<double>::infinity();
  for (Index v = 0; v < nodes; ++v) {
    if (!(nodal_mass[v] > 0) || penalty[v] <= 0) continue;
    const double omega = std::sqrt(2 * penalty[v] * area[v] / nodal_mass[v]);
    if (omega > out.omega_max) {
      out.omega_max = omega;
      out.critical_node = v;
      out.dt = 2 / omega;
    }
  }
  return out;
}

}  // namespace sinew::contact
