#pragma once
/// @file problem_builder.hpp
/// Small fem::Problems for tests, built without the scene module.

#include "sinew/fem/problem.hpp"
#include "sinew/material/material_spec.hpp"
#include "support/box_mesh.hpp"

namespace sinew::testing {

inline material::MaterialPtr mooney_rivlin(double C1 = 1.0, double C2 = 0.3, double a = 2.0) {
  material::MaterialSpec spec;
  spec.base = material::MooneyRivlinParams{C1, C2, a};
  return material::make_material(spec);
}

/// One-region box problem with a single material (no constraints yet).
inline fem::Problem box_problem(int nx, int ny, int nz, const Vector3& lo, const Vector3& hi,
                                material::MaterialPtr law, double density = 0) {
  fem::Problem p;
  p.mesh = box_mesh(nx, ny, nz, lo, hi);
  p.bodies.push_back({"box", 0, p.mesh.num_nodes(), 0, p.mesh.num_tets()});
  p.region_material = {std::move(law)};
  p.region_density = {density};
  return p;
}

/// Per-tet materials from per-region ones.
inline std::vector<material::MaterialPtr> tet_materials(const fem::Problem& p) {
  std::vector<material::MaterialPtr> out(static_cast<std::size_t>(p.mesh.num_tets()));
  for (Index t = 0; t < p.mesh.num_tets(); ++t) out[t] = p.region_material[p.mesh.region[t]];
  return out;
}

/// Makes the tets of `p` whose centroid satisfies `inside(centroid)` a second region, rigid body
/// `name` of `kind` (region material null, density `density`), and returns the body (added to
/// p.rigid_bodies) for the caller to give a motion.
template <class Inside>
fem::RigidBody& add_rigid_region(fem::Problem& p, const std::string& name, fem::RigidBody::Kind kind,
                                 double density, Inside inside) {
  p.mesh.region_names = {"soft", name};
  p.region_material.push_back(nullptr);
  p.region_density.push_back(density);
  fem::RigidBody body;
  body.name = name;
  body.kind = kind;
  for (Index t = 0; t < p.mesh.num_tets(); ++t) {
    Vector3 centroid = Vector3::Zero();
    for (int i = 0; i < 4; ++i) centroid += p.mesh.rest.row(p.mesh.tets(t, i)).transpose() / 4;
    if (inside(centroid)) {
      p.mesh.region[t] = 1;
      body.tets.push_back(t);
    }
  }
  p.rigid_bodies.push_back(body);
  return p.rigid_bodies.back();
}

}  // namespace sinew::testing
