#pragma once
/// @file resource_estimate.hpp
/// Size of a generated mesh estimated before meshing, so a scene that would need more tets (and
/// memory) than a limit allows fails at once with a message instead of after minutes of Gmsh
/// and gigabytes of memory (a box 1e5 long meshed at element_size 1 would need ~1e16 tets).

#include "sinew/mesh/generate.hpp"
#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// Tets of a regular tetrahedral mesh per unit volume at edge length h: a regular tet of edge h
/// has volume h^3 / (6 sqrt 2), so a volume V holds about 6 sqrt(2) V / h^3 of them.
inline constexpr double kTetsPerEdgeCubed = 8.48528137423857;  // 6 sqrt(2)

/// Memory per tet (bytes), an order of magnitude for the message: `sinew validate` of
/// examples/knee-flexion.json at element_size 5 (160k tets) peaks at 214 MB, ~1.3 kB per tet for
/// meshing and the model; a run's sparse Cholesky factor adds more.
inline constexpr double kBytesPerTet = 2000;

/// An upper bound on the volume of a shape (length^3): exact for box, sphere, cylinder and
/// torus (segment); a union's is the sum of its children's, a difference's its first child's,
/// an intersection's its smallest child's. Transforms are rigid and change no volume.
double shape_volume_bound(const mesh::Shape& shape);

/// Estimated tets of a generated mesh of `parts` (GenerateOptions::element_size h and
/// elements_per_turn N): 6 sqrt(2) V / h^3 over the parts' volume bounds V, plus, for every
/// curved surface (sphere, cylinder side, torus) of area A and radius r, the layer Gmsh refines
/// to the size s = clamp(2 pi r / N, h / 10, h): 6 sqrt(2) A / s^2. An order of magnitude, not
/// a count: on the examples it is 0.7 to 17 times the tets Gmsh makes (mostly above).
double estimated_tets(const std::vector<mesh::Part>& parts, const mesh::GenerateOptions& options);

/// Estimated tets of a body: as above for a generated mesh; 0 for a mesh file (it exists, its
/// size is known when it is read).
double estimated_tets(const BodyConfig& body);

/// Throws InputError when a generated body's estimate exceeds limits.max_tets, one line per
/// such body: "bodies[<b>].mesh.generate: an estimated <n> tets (about <m> GB) at element_size
/// <h> exceed the limit of <max> tets (raise it with --max-tets); or raise element_size".
void check_resource_limits(const SceneConfig& scene);

}  // namespace sinew::scene
