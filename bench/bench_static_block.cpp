/// Benchmark (issue 2): a Mooney-Rivlin block of about 10k nodes / 40k tets compressed 30 % in
/// 10 increments. Prints the total time, Newton iterations and the split between forces and
/// stiffness, linear solve and line search, factorizations and lagged-CG iterations, for each
/// predictor, with and without lagged factorizations, and for PETSc's MUMPS and CG + GAMG.
/// Timings are measured here, never asserted in tests.

#include <benchmark/benchmark.h>

#include <chrono>

#include "sinew/model/solve_model.hpp"

using namespace sinew;

namespace {

scene::SceneConfig block_scene(double element_size) {
  scene::SceneConfig s;
  s.name = "bench-block";
  material::MaterialSpec rubber;
  rubber.base = material::MooneyRivlinParams{0.4, 0.1, 2.0};
  s.materials["rubber"] = rubber;
  scene::BodyConfig body;
  body.name = "block";
  mesh::Shape box;
  box.kind = mesh::Shape::Kind::Box;
  box.min = Vector3(0, 0, 0);
  box.max = Vector3(20, 20, 20);
  body.mesh.parts.push_back({"rubber", box});
  body.mesh.generate.element_size = element_size;
  scene::RegionConfig region;
  region.material = "rubber";
  body.regions["rubber"] = region;
  s.bodies.push_back(body);
  scene::BoundaryConditionConfig bottom;
  bottom.name = "bottom";
  bottom.kind = scene::BoundaryConditionConfig::Kind::Fixed;
  bottom.nodes.kind = scene::NodeSelector::Kind::Plane;
  bottom.nodes.body = "block";
  bottom.nodes.point = Vector3(0, 0, 0);
  bottom.nodes.normal = Vector3::UnitZ();
  bottom.nodes.tolerance = 1e-6;
  s.boundary_conditions.push_back(bottom);
  scene::BoundaryConditionConfig top = bottom;
  top.name = "top";
  top.kind = scene::BoundaryConditionConfig::Kind::Prescribed;
  top.nodes.point = Vector3(0, 0, 20);
  top.motion.translation = Vector3(0, 0, -6);
  s.boundary_conditions.push_back(top);
  s.solver.stepping.increments = 10;
  return s;
}

void BM_CompressBlock(benchmark::State& state, solver::LoadSteppingOptions::Predictor predictor,
                      solver::LinearSolverOptions::Kind linear, int lagged_iterations) {
  scene::SceneConfig scene = block_scene(0.95);  // about 9k nodes, 43k tets
  scene.solver.stepping.predictor = predictor;
  scene.solver.linear.kind = linear;
  scene.solver.linear.lagged_iterations = lagged_iterations;
  if (linear == solver::LinearSolverOptions::Kind::PetscGamg) {
    scene.solver.linear.tolerance = 1e-6;  // Newton converges quadratically, as with a direct solve
    scene.solver.linear.max_iterations = 500;
  } else if (linear != solver::LinearSolverOptions::Kind::Cholmod && linear != solver::LinearSolverOptions::Kind::PetscMumps) {
    scene.solver.linear.max_iterations = 500;
    scene.solver.newton.max_iterations = 200;
  }
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    model::Model model = model::build_model(scene);
    const double mesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const fem::Problem& problem = *model.problem;
    const auto start = std::chrono::steady_clock::now();
    const auto result = model::solve_model(model);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    if (!result.success) state.SkipWithError(result.message.c_str());
    const auto& t = result.times;
    state.counters["nodes"] = problem.mesh.num_nodes();
    state.counters["tets"] = problem.mesh.num_tets();
    state.counters["newton_its"] = result.newton_iterations;
    state.counters["factorizations"] = result.linear.factorizations;
    state.counters["linear_its"] = result.linear.linear_iterations;
    state.counters["steps"] = result.steps;
    state.counters["solve_s"] = seconds;
    state.counters["forces_stiffness_s"] = t.forces_and_stiffness;
    state.counters["linear_solve_s"] = t.linear_solve;
    state.counters["line_search_s"] = t.line_search;
    state.counters["collision_s"] = t.collision;
    state.counters["other_s"] = std::max(0.0, seconds - t.total());
    state.counters["mesh_s"] = mesh_seconds;
  }
}

using P = solver::LoadSteppingOptions::Predictor;
using L = solver::LinearSolverOptions::Kind;
// The lagged variants alternate with the plain one (this machine is shared: compare within a run).
BENCHMARK_CAPTURE(BM_CompressBlock, tangent_cholmod, P::Tangent, L::Cholmod, 0)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_CompressBlock, tangent_cholmod_lagged10, P::Tangent, L::Cholmod, 10)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_CompressBlock, tangent_cholmod_lagged20, P::Tangent, L::Cholmod, 20)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_CompressBlock, tangent_cholmod_lagged40, P::Tangent, L::Cholmod, 40)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
// PETSc's solvers on one process (issue 19), between CHOLMOD runs.
BENCHMARK_CAPTURE(BM_CompressBlock, tangent_petsc_mumps, P::Tangent, L::PetscMumps, 0)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_CompressBlock, tangent_cholmod_again, P::Tangent, L::Cholmod, 0)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_CompressBlock, tangent_petsc_gamg, P::Tangent, L::PetscGamg, 0)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_CompressBlock, two_point_cholmod, P::TwoPoint, L::Cholmod, 0)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_CompressBlock, two_point_cholmod_lagged20, P::TwoPoint, L::Cholmod, 20)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
