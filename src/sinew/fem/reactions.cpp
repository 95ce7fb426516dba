#include "sinew/fem/reactions.hpp"

namespace sinew::fem {

std::vector<Reaction> compute_reactions(const Problem& problem, const DofMap& dofs, const State& state,
                                        const NodalVectors& full_gradient) {
  std::vector<Reaction> out;
  auto accumulate = [&](Reaction& r, Index a, const Vector3& f) {
    r.force += f;
    r.moment += (state.x.row(a).transpose() - r.moment_point).cross(f);
  };
  for (const PrescribedNodes& set : problem.prescribed) {
    Reaction r;
    r.name = set.name;
    r.moment_point = set.motion.apply(set.motion.axis_point, state.lambda);
    for (Index a : set.nodes) accumulate(r, a, full_gradient.row(a).transpose());
    out.push_back(r);
  }
  for (const PlanarNodes& set : problem.planar) {
    Reaction r;
    r.name = set.name;
    const Vector3 n = set.normal.normalized();
    for (Index a : set.nodes) accumulate(r, a, n * n.dot(full_gradient.row(a).transpose()));
    out.push_back(r);
  }
  for (std::size_t b = 0; b < problem.rigid_bodies.size(); ++b) {
    Reaction r;
    r.name = problem.rigid_bodies[b].name;
    r.moment_point = dofs.rigid_center(b) + state.rigid[b].t;
    for (Index a : dofs.rigid_members(b)) accumulate(r, a, full_gradient.row(a).transpose());
    out.push_back(r);
  }
  return out;
}

}  // namespace sinew::fem
