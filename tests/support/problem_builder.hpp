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

}  // namespace sinew::testing
