/// Benchmark: collision detection and contact assembly on a self-contact scene, against the
/// time of one full Newton iteration (dissertation section 5.4 and docs/theory.md).
///
/// Scene (lengths in mm, stresses in kPa): one Mooney-Rivlin slab (C1 = 0.4, C2 = 0.1, a = 2),
/// 208 x 8 x 4 cubes of edge h = 1 mm split into 6 tets each (39,936 tets), wrapped around the
/// y axis by 450 degrees along a slowly widening spiral: after one turn the radius has grown by
/// (1 - 0.3) times the thickness, so the last quarter turn penetrates the first one by 30 % of
/// the thickness (1.2 mm, below the 2 mm medial sheet), and by 0.2 mm sideways. On the first
/// turn the mid-surface keeps its length and the faces are stretched / compressed by 7.5 %
/// (tet volume ratios stay in [0.92, 1.21]: no tet is inverted, the elastic energy is finite). The
/// cross-section at the middle of the slab is held. Material depth: exact distance to the
/// slab's rest boundary. Self-contact penalty ε = 10 kPa/mm.
///
/// One "Newton iteration" at a slightly perturbed copy of that configuration (so the contact
/// term must refit, query and clip again) is: full gradient, energy (one line-search
/// evaluation), Objective::hessian (elastic + contact Hessians, reduction to q-space), CHOLMOD
/// factorization + solve by solver::newton_direction itself (with the diagonal shift and its hint when K is not positive
/// definite). The phases are timed through a timing wrapper around each energy term. Printed:
/// Google Benchmark counters (mean ms per phase), then a per-phase table with the contact share
/// of the iteration and the seed's three-way split (forces and stiffness / collision / linear
/// solve, dissertation: 63 / 22 / 15 %). Timings are measured here, never asserted in tests.
///
/// Usage: bench_contact_self [--threads=N] [Google Benchmark flags]; --threads limits TBB, and
/// OPENBLAS_NUM_THREADS limits CHOLMOD's BLAS. On a loaded machine compare the "CPU time" row
/// with the wall clock before trusting absolute numbers; the shares are more stable.

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "sinew/collision/material_depth.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/contact_report.hpp"
#include "sinew/fem/dof_map.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/problem.hpp"
#include "sinew/material/material_spec.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/solver/linear_solver.hpp"
#include "sinew/solver/newton_direction.hpp"
#include "sinew/solver/objective.hpp"

using namespace sinew;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
/// CPU time of the whole process (all threads), seconds.
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// ---------------------------------------------------------------------------------------------
// Scene

struct SlabParams {
  int nx = 208, ny = 8, nz = 4;  ///< cubes along the length, width, thickness
  double h = 1.0;                ///< cube edge (mm)
  double extra_turn = 0.25;      ///< wrap angle = 2 pi (1 + extra_turn)
  double overlap = 0.3;          ///< penetration of the second turn into the first / thickness
  double lateral_shift = 0.2;    ///< sideways shift per turn / h (avoids flush side walls)
  double penalty = 10.0;         ///< ε (kPa / mm)
};

/// Structured box [0, nx h] x [0, ny h] x [0, nz h], each cube split into 6 positively oriented
/// tets along its main diagonal (Kuhn subdivision, conforming).
mesh::TetMesh structured_box(const SlabParams& p) {
  const int nx = p.nx, ny = p.ny, nz = p.nz;
  mesh::TetMesh m;
  auto id = [&](int i, int j, int k) { return static_cast<Index>(i + (nx + 1) * (j + (ny + 1) * k)); };
  m.rest.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.rest.row(id(i, j, k)) = p.h * Vector3(i, j, k).transpose();
  const std::array<std::array<int, 3>, 6> orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  m.tets.resize(6 * nx * ny * nz, 4);
  Index t = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& order : orders) {
          std::array<int, 3> c{i, j, k};
          m.tets(t, 0) = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[static_cast<std::size_t>(order[static_cast<std::size_t>(s)])];
            m.tets(t, s + 1) = id(c[0], c[1], c[2]);
          }
          if (mesh::signed_volume(m.rest, m.tets, t) < 0) std::swap(m.tets(t, 2), m.tets(t, 3));
          ++t;
        }
  m.region = IndexVector::Zero(m.tets.rows());
  m.region_names = {"slab"};
  return m;
}

/// The bending map: rest (s, y, z) -> a spiral around the y axis, angle θ = s / R0 with R0 such
/// that the slab covers 2π (1 + extra_turn), radius R0 + (z - H/2) + Δ θ / 2π with
/// Δ = (1 - overlap) H, sideways shift lateral_shift h θ / 2π. Orientation preserving
/// (det = r / R0 > 0).
Positions wrap_slab(const Positions& rest, const SlabParams& p) {
  const double L = p.nx * p.h, H = p.nz * p.h;
  const double turns = 1.0 + p.extra_turn;
  const double R0 = L / (2 * std::numbers::pi * turns);
  const double delta = (1.0 - p.overlap) * H;
  Positions x(rest.rows(), 3);
  for (Index a = 0; a < rest.rows(); ++a) {
    const double s = rest(a, 0), y = rest(a, 1), z = rest(a, 2);
    const double theta = s / R0;
    const double turn = theta / (2 * std::numbers::pi);
    const double r = R0 + (z - 0.5 * H) + delta * turn;
    x.row(a) = Vector3(r * std::cos(theta), y + p.lateral_shift * p.h * turn, -r * std::sin(theta)).transpose();
  }
  return x;
}

struct Scene {
  SlabParams params;
  fem::Problem problem;
  Positions x0;  ///< the wrapped configuration
  contact::ContactGeometry geometry;
  std::vector<material::MaterialPtr> tet_material;
  double min_volume_ratio = 0, max_volume_ratio = 0;
  double depth_seconds = 0;
  double max_depth = 0;
};

const Scene& scene() {
  static const Scene s = [] {
    Scene out;
    const SlabParams& p = out.params;
    fem::Problem& problem = out.problem;
    problem.mesh = structured_box(p);
    problem.bodies.push_back({"slab", 0, problem.mesh.num_nodes(), 0, problem.mesh.num_tets()});
    material::MaterialSpec rubber;
    rubber.base = material::MooneyRivlinParams{0.4, 0.1, 2.0};
    problem.region_material = {material::make_material(rubber)};
    problem.region_density = {0.0};
    // Hold the cross-section at the middle of the slab (removes the rigid modes).
    fem::PrescribedNodes held;
    held.name = "middle";
    for (Index a = 0; a < problem.mesh.num_nodes(); ++a)
      if (std::abs(problem.mesh.rest(a, 0) - 0.5 * p.nx * p.h) < 1e-9) held.nodes.push_back(a);
    problem.prescribed.push_back(held);
    out.tet_material.assign(static_cast<std::size_t>(problem.mesh.num_tets()), problem.region_material[0]);

    out.x0 = wrap_slab(problem.mesh.rest, p);
    out.min_volume_ratio = std::numeric_limits<double>::infinity();
    for (Index t = 0; t < problem.mesh.num_tets(); ++t) {
      const double ratio = mesh::signed_volume(out.x0, problem.mesh.tets, t) /
                           mesh::signed_volume(problem.mesh.rest, problem.mesh.tets, t);
      out.min_volume_ratio = std::min(out.min_volume_ratio, ratio);
      out.max_volume_ratio = std::max(out.max_volume_ratio, ratio);
    }

    auto& g = out.geometry;
    g.surface = mesh::boundary_triangles(problem.mesh.tets);
    g.surface_body = IndexVector::Zero(g.surface.rows());
    g.tets = problem.mesh.tets;
    g.tet_body = IndexVector::Zero(g.tets.rows());
    std::vector<Index> nodes(static_cast<std::size_t>(problem.mesh.num_nodes()));
    for (Index a = 0; a < problem.mesh.num_nodes(); ++a) nodes[static_cast<std::size_t>(a)] = a;
    const auto t0 = Clock::now();
    g.depth = collision::material_depth(problem.mesh.rest, g.surface, nodes);
    out.depth_seconds = seconds_since(t0);
    out.max_depth = g.depth.maxCoeff();
    g.penalty = MatrixX::Constant(1, 1, p.penalty);
    return out;
  }();
  return s;
}

// ---------------------------------------------------------------------------------------------
// Timing wrapper around an energy term (the sink is owned by the benchmark, not the term).

struct TermTimes {
  double update = 0, valid = 0, value = 0, gradient = 0, hessian = 0;
};

class TimedEnergy final : public Energy {
 public:
  TimedEnergy(Energy& inner, TermTimes& sink) : inner_(inner), sink_(&sink) {}
  std::string_view name() const override { return inner_.name(); }
  double value(const Positions& x) const override {
    const auto t0 = Clock::now();
    const double v = inner_.value(x);
    sink_->value += seconds_since(t0);
    return v;
  }
  void add_gradient(const Positions& x, NodalVectors& grad) const override {
    const auto t0 = Clock::now();
    inner_.add_gradient(x, grad);
    sink_->gradient += seconds_since(t0);
  }
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override {
    const auto t0 = Clock::now();
    inner_.add_hessian(x, H);
    sink_->hessian += seconds_since(t0);
  }
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override { inner_.hessian_pattern(pairs); }
  void bind_pattern(const BlockSparseMatrix& H) override { inner_.bind_pattern(H); }
  bool is_valid(const Positions& x) const override {
    const auto t0 = Clock::now();
    const bool ok = inner_.is_valid(x);
    sink_->valid += seconds_since(t0);
    return ok;
  }
  void set_load_parameter(double lambda) override { inner_.set_load_parameter(lambda); }
  bool has_hessian() const override { return inner_.has_hessian(); }
  void update(const Positions& x) override {
    const auto t0 = Clock::now();
    inner_.update(x);
    sink_->update += seconds_since(t0);
  }
  void begin_step(const Positions& x) override { inner_.begin_step(x); }
  std::uint64_t pattern_revision() const override { return inner_.pattern_revision(); }

 private:
  Energy& inner_;
  TermTimes* sink_;
};

// ---------------------------------------------------------------------------------------------
// Per-phase sums over the timed iterations, and the results kept for the final table.

struct Phases {
  double refit = 0, query = 0, clip = 0, bookkeeping = 0;  ///< collision (contact update)
  double contact_value = 0, contact_gradient = 0, contact_hessian = 0;
  double elastic_forces = 0, elastic_hessian = 0;  ///< value + validity + gradient; Hessian
  double reduce = 0;        ///< H reset + q-space reduction of H and g (Objective::hessian minus the terms)
  double analyze = 0;       ///< CHOLMOD symbolic analysis (only when the pattern changed)
  double factorize = 0, solve = 0;
  double wall = 0;          ///< the iteration, wall clock
  double cpu = 0;           ///< the iteration, CPU time of all threads
  double candidates = 0, pairs = 0, factorizations = 0, pattern_rebuilds = 0;
  double regularized = 0;   ///< iterations whose K needed a diagonal shift
  double relative_residual = 0;

  /// Every field, for the sums and means below.
  static constexpr std::array<double Phases::*, 21> kFields{
      &Phases::refit, &Phases::query, &Phases::clip, &Phases::bookkeeping, &Phases::contact_value,
      &Phases::contact_gradient, &Phases::contact_hessian, &Phases::elastic_forces, &Phases::elastic_hessian,
      &Phases::reduce, &Phases::analyze, &Phases::factorize, &Phases::solve, &Phases::wall, &Phases::cpu, &Phases::candidates,
      &Phases::pairs, &Phases::factorizations, &Phases::pattern_rebuilds, &Phases::regularized,
      &Phases::relative_residual};
  Phases& operator+=(const Phases& o) {
    for (auto f : kFields) this->*f += o.*f;
    return *this;
  }
  Phases& operator/=(double n) {
    for (auto f : kFields) this->*f /= n;
    return *this;
  }
  double collision() const { return refit + query + clip + bookkeeping; }
  double contact_integrate() const { return contact_value + contact_gradient; }
  double contact() const { return collision() + contact_integrate() + contact_hessian; }
  double elastic() const { return elastic_forces + elastic_hessian; }
  double linear() const { return analyze + factorize + solve; }
  double total() const { return contact() + elastic() + reduce + linear(); }
};

struct RunInfo {
  Phases mean;
  int iterations = 0;
  Index dofs = 0, k_nonzeros = 0, elastic_blocks = 0, contact_blocks = 0;
  double build_seconds = 0;  ///< begin_step: BVH build + first update
  contact::ContactReport stats;
};

std::map<std::string, RunInfo>& results() {
  static std::map<std::string, RunInfo> r;
  return r;
}
std::vector<std::string>& result_order() {
  static std::vector<std::string> r;
  return r;
}

/// Deterministic small perturbation of x (1e-6 h per coordinate) so the contact term must
/// recompute its pairs, as it does at every Newton iterate.
Positions perturbed(const Positions& x, double h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1e-6 * h, 1e-6 * h);
  Positions y = x;
  for (Index i = 0; i < y.rows(); ++i)
    for (int c = 0; c < 3; ++c) y(i, c) += u(rng);
  return y;
}

/// The linear solver with the time of each call added to a Phases record.
class TimedLinearSolver final : public solver::LinearSolver {
 public:
  explicit TimedLinearSolver(std::unique_ptr<solver::LinearSolver> inner) : inner_(std::move(inner)) {}
  void analyze(const fem::SparseMatrix& K) override {
    const auto t0 = Clock::now();
    inner_->analyze(K);
    if (phases_) phases_->analyze += seconds_since(t0);
  }
  bool factorize(const fem::SparseMatrix& K) override {
    const auto t0 = Clock::now();
    const bool ok = inner_->factorize(K);
    if (phases_) phases_->factorize += seconds_since(t0);
    return ok;
  }
  solver::LinearSolveStats solve(const VectorX& b, VectorX& x) override {
    const auto t0 = Clock::now();
    const solver::LinearSolveStats stats = inner_->solve(b, x);
    if (phases_) {
      phases_->solve += seconds_since(t0);
      last_relative_residual_ = stats.relative_residual;
    }
    return stats;
  }
  const char* name() const override { return inner_->name(); }
  int factorizations() const override { return inner_->factorizations(); }
  /// Where the times go (null: nowhere).
  void record_into(Phases* phases) { phases_ = phases; }
  double last_relative_residual() const { return last_relative_residual_; }

 private:
  std::unique_ptr<solver::LinearSolver> inner_;
  Phases* phases_ = nullptr;
  double last_relative_residual_ = 0;
};

/// K dq = -g by the Newton loop's own solver::newton_direction (diagonal shift when K is not
/// positive definite, starting from the hint of the previous iteration), timed per phase.
/// Returns the shift hint for the next iteration.
double timed_newton_direction(const fem::SparseMatrix& K, bool fresh, const VectorX& g, TimedLinearSolver& linear,
                              double shift_hint, Phases& ph) {
  linear.record_into(&ph);
  const solver::Direction d = solver::newton_direction(K, fresh, g, linear, solver::ShiftStart{.first = shift_hint});
  linear.record_into(nullptr);
  ph.factorizations += d.factorizations;
  if (d.regularization > 0) ph.regularized += 1;
  ph.relative_residual += linear.last_relative_residual();
  return std::isfinite(d.regularization) ? d.regularization / 100 : 0;
}

void BM_SelfContactNewtonIteration(benchmark::State& state, contact::ContactMethod method,
                                   contact::PairHessian hessian, const char* label) {
  const Scene& sc = scene();
  const fem::Problem& problem = sc.problem;
  const Index n = problem.mesh.num_nodes();

  fem::DofMap dofs(problem);
  fem::ElasticEnergy elastic(problem.mesh.rest, problem.mesh.tets, sc.tet_material);
  contact::ContactEnergy contact(sc.geometry, contact::ContactOptions{method, hessian});
  TermTimes elastic_times, contact_times;
  TimedEnergy timed_elastic(elastic, elastic_times), timed_contact(contact, contact_times);
  solver::Objective objective(dofs, {&timed_elastic, &timed_contact}, n);
  TimedLinearSolver linear(solver::make_linear_solver(solver::LinearSolverOptions{}));
  double shift_hint = 0;

  RunInfo info;
  fem::State st;
  st.x = sc.x0;
  {
    const auto t0 = Clock::now();
    objective.begin_step(st);
    info.build_seconds = seconds_since(t0);
  }
  info.stats = contact::contact_report(contact, sc.x0);

  // Warm-up iteration at x0: builds the Hessian pattern and CHOLMOD's analysis.
  fem::SparseMatrix K;
  {
    Phases warm;
    const NodalVectors g = objective.full_gradient(st);
    const bool fresh = objective.hessian(st, g, VectorX(), K);
    shift_hint = timed_newton_direction(K, fresh, dofs.reduce_gradient(st, g), linear, shift_hint, warm);
  }

  Phases sum;
  unsigned seed = 1;
  for (auto _ : state) {
    st.x = perturbed(sc.x0, sc.params.h, seed++);
    elastic_times = {};
    contact_times = {};
    Phases ph;
    const auto t_iter = Clock::now();
    const double cpu_iter = process_cpu_seconds();

    const NodalVectors g = objective.full_gradient(st);  // triggers the contact update
    const auto& ct = contact.last_update_times();
    ph.refit = ct.refit;
    ph.query = ct.query;
    ph.clip = ct.clip;
    ph.candidates = static_cast<double>(ct.candidates);
    const double energy = objective.value(st);  // one line-search evaluation
    if (!std::isfinite(energy)) {
      state.SkipWithError("the energy is not finite (inverted element?)");
      break;
    }
    const std::uint64_t pattern_before = objective.full_hessian().pattern_version();
    const auto t_hess = Clock::now();
    const bool fresh = objective.hessian(st, g, VectorX(), K);
    const VectorX gq = dofs.reduce_gradient(st, g);
    const double hess_seconds = seconds_since(t_hess);
    if (objective.full_hessian().pattern_version() != pattern_before) ph.pattern_rebuilds += 1;
    shift_hint = timed_newton_direction(K, fresh, gq, linear, shift_hint, ph);
    ph.wall = seconds_since(t_iter);
    ph.cpu = process_cpu_seconds() - cpu_iter;
    ph.pairs = static_cast<double>(contact.active_pairs().size());

    ph.bookkeeping = std::max(0.0, contact_times.update - (ct.refit + ct.query + ct.clip));
    ph.contact_value = contact_times.value;
    ph.contact_gradient = contact_times.gradient;
    ph.contact_hessian = contact_times.hessian;
    ph.elastic_forces = elastic_times.value + elastic_times.valid + elastic_times.gradient + elastic_times.update;
    ph.elastic_hessian = elastic_times.hessian;
    ph.reduce = std::max(0.0, hess_seconds - elastic_times.hessian - contact_times.hessian);
    state.SetIterationTime(ph.wall);

    sum += ph;
    ++info.iterations;
  }
  if (info.iterations == 0) return;
  sum /= info.iterations;
  info.mean = sum;
  info.dofs = dofs.num_dofs();
  info.k_nonzeros = K.nonZeros();
  {
    std::vector<std::pair<Index, Index>> pairs;
    elastic.hessian_pattern(pairs);
    info.elastic_blocks = static_cast<Index>(pairs.size());
    pairs.clear();
    contact.hessian_pattern(pairs);
    info.contact_blocks = static_cast<Index>(pairs.size());
  }

  const Phases& m = info.mean;
  auto ms = [](double s) { return benchmark::Counter(1e3 * s); };
  state.counters["tets"] = static_cast<double>(problem.mesh.num_tets());
  state.counters["candidates"] = m.candidates;
  state.counters["pairs"] = m.pairs;
  state.counters["refit_ms"] = ms(m.refit);
  state.counters["query_ms"] = ms(m.query);
  state.counters["clip_ms"] = ms(m.clip);
  state.counters["c_integrate_ms"] = ms(m.contact_integrate());
  state.counters["c_hessian_ms"] = ms(m.contact_hessian);
  state.counters["elastic_ms"] = ms(m.elastic());
  state.counters["reduce_ms"] = ms(m.reduce);
  state.counters["linsolve_ms"] = ms(m.linear());
  state.counters["contact_share"] = m.contact() / m.total();

  if (!results().contains(label)) result_order().push_back(label);
  results()[label] = info;
}

using M = contact::ContactMethod;
using PH = contact::PairHessian;
BENCHMARK_CAPTURE(BM_SelfContactNewtonIteration, area_gauss_newton, M::Area, PH::GaussNewton, "area/GN")
    ->Iterations(5)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SelfContactNewtonIteration, area_exact, M::Area, PH::Exact, "area/Exact")
    ->Iterations(5)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SelfContactNewtonIteration, area_projected, M::Area, PH::Projected, "area/Projected")
    ->Iterations(5)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SelfContactNewtonIteration, point_gauss_newton, M::Point, PH::GaussNewton, "point/GN")
    ->Iterations(5)->UseManualTime()->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------------------------------------
// The readable table.

void print_table() {
  if (results().empty()) return;
  const Scene& sc = scene();
  const SlabParams& p = sc.params;
  const auto& mesh = sc.problem.mesh;
  const RunInfo& first = results()[result_order().front()];
  std::printf("\n=== Self-contact slab: one Newton iteration, mean of %d perturbed iterates ===\n", first.iterations);
  std::printf("mesh: %d x %d x %d cubes, h = %.2f mm: %ld nodes, %ld tets, %ld surface triangles; %ld dofs "
              "(%zu held nodes)\n",
              p.nx, p.ny, p.nz, p.h, static_cast<long>(mesh.num_nodes()), static_cast<long>(mesh.num_tets()),
              static_cast<long>(sc.geometry.surface.rows()), static_cast<long>(first.dofs),
              sc.problem.prescribed[0].nodes.size());
  std::printf("wrap: %.0f deg, overlap %.0f %% of the thickness (%.2f mm, max depth %.2f mm); tet volume ratio "
              "J in [%.3f, %.3f]; Mooney-Rivlin 0.4/0.1/2 kPa; eps = %.0f kPa/mm\n",
              360.0 * (1 + p.extra_turn), 100 * p.overlap, p.overlap * p.nz * p.h, sc.max_depth, sc.min_volume_ratio,
              sc.max_volume_ratio, p.penalty);
  std::printf("setup (not in the iteration): material depth %.1f ms; begin_step (BVH build + first update) %.1f ms; "
              "TBB threads %d\n",
              1e3 * sc.depth_seconds, 1e3 * first.build_seconds,
              static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
  std::printf("contact at x0 (area/GN run): %ld self-contact pairs, area %.1f mm^2, max penetration %.3f mm, "
              "mean %.3f mm, Ec = %.4g mJ\n\n",
              static_cast<long>(first.stats.pairs), first.stats.area, first.stats.max_penetration,
              first.stats.mean_penetration, first.stats.energy);

  const int cols = static_cast<int>(result_order().size());
  std::printf("%-40s", "");
  for (const auto& name : result_order()) std::printf(" | %18s", name.c_str());
  std::printf("\n");
  auto row_count = [&](const char* label, auto get) {
    std::printf("%-40s", label);
    for (const auto& name : result_order()) std::printf(" | %18.0f", get(results()[name]));
    std::printf("\n");
  };
  row_count("candidates (broad phase)", [](const RunInfo& r) { return r.mean.candidates; });
  row_count("active pairs", [](const RunInfo& r) { return r.mean.pairs; });
  row_count("contact Hessian blocks (pattern)", [](const RunInfo& r) { return double(r.contact_blocks); });
  row_count("elastic Hessian blocks", [](const RunInfo& r) { return double(r.elastic_blocks); });
  row_count("nonzeros of reduced K", [](const RunInfo& r) { return double(r.k_nonzeros); });
  std::printf("%-40s", "phase (ms, % of iteration)");
  for (int c = 0; c < cols; ++c) std::printf(" | %18s", "ms      %");
  std::printf("\n");
  std::printf("%s\n", std::string(40 + 21 * static_cast<std::size_t>(cols), '-').c_str());
  auto row = [&](const char* label, auto get) {
    std::printf("%-40s", label);
    for (const auto& name : result_order()) {
      const Phases& m = results()[name].mean;
      std::printf(" | %9.2f %6.1f %%", 1e3 * get(m), 100 * get(m) / m.total());
    }
    std::printf("\n");
  };
  row("contact refit (tet boxes + BVH)", [](const Phases& m) { return m.refit; });
  row("contact query (broad phase)", [](const Phases& m) { return m.query; });
  row("contact clip (narrow phase)", [](const Phases& m) { return m.clip; });
  row("contact pair bookkeeping / pattern", [](const Phases& m) { return m.bookkeeping; });
  row("contact integrate (value + gradient)", [](const Phases& m) { return m.contact_integrate(); });
  row("  of which value", [](const Phases& m) { return m.contact_value; });
  row("  of which gradient", [](const Phases& m) { return m.contact_gradient; });
  row("contact Hessian (add_hessian)", [](const Phases& m) { return m.contact_hessian; });
  row("elastic forces (value, validity, grad)", [](const Phases& m) { return m.elastic_forces; });
  row("elastic stiffness (add_hessian)", [](const Phases& m) { return m.elastic_hessian; });
  row("H reset + reduction to q-space", [](const Phases& m) { return m.reduce; });
  row("linear solve (CHOLMOD factor + solve)", [](const Phases& m) { return m.linear(); });
  row("  of which analyze (new pattern)", [](const Phases& m) { return m.analyze; });
  row("  of which factorize", [](const Phases& m) { return m.factorize; });
  row("  of which solve", [](const Phases& m) { return m.solve; });
  std::printf("%s\n", std::string(40 + 21 * static_cast<std::size_t>(cols), '-').c_str());
  row("sum of phases", [](const Phases& m) { return m.total(); });
  row("wall clock of the iteration", [](const Phases& m) { return m.wall; });
  row("CPU time of the iteration (all threads)", [](const Phases& m) { return m.cpu; });
  std::printf("%-40s", "factorizations / iter (shift retries)");
  for (const auto& name : result_order()) std::printf(" | %18.1f", results()[name].mean.factorizations);
  std::printf("\n%-40s", "iterations needing a diagonal shift");
  for (const auto& name : result_order()) std::printf(" | %18.1f", results()[name].mean.regularized);
  std::printf("\n%-40s", "pattern rebuilds / iteration");
  for (const auto& name : result_order()) std::printf(" | %18.1f", results()[name].mean.pattern_rebuilds);
  std::printf("\n\n");

  std::printf("per item (wall clock over all threads): query us / surface triangle, clip ns / candidate, "
              "gradient and Hessian us / pair, elastic stiffness us / tet\n");
  for (const auto& name : result_order()) {
    const Phases& m = results()[name].mean;
    std::printf("  %-12s query %.2f us, clip %.0f ns, gradient %.2f us, Hessian %.2f us, elastic stiffness %.2f us\n",
                name.c_str(), 1e6 * m.query / static_cast<double>(sc.geometry.surface.rows()),
                1e9 * m.clip / m.candidates, 1e6 * m.contact_gradient / m.pairs, 1e6 * m.contact_hessian / m.pairs,
                1e6 * m.elastic_hessian / static_cast<double>(mesh.num_tets()));
  }
  std::printf("\n");
  std::printf("contact share = contact phases / (contact + elastic + linear solve)   [target <= 25 %%]\n");
  for (const auto& name : result_order()) {
    const Phases& m = results()[name].mean;
    const double brief = m.contact() / (m.contact() + m.elastic() + m.linear());
    const double all = m.contact() / m.total();
    std::printf("  %-12s %5.1f %%  (%5.1f %% counting the q-space reduction in the denominator)\n", name.c_str(),
                100 * brief, 100 * all);
  }
  std::printf("seed split (dissertation: forces+stiffness 63 / collision 22 / linear solve 15 %%)\n");
  for (const auto& name : result_order()) {
    const Phases& m = results()[name].mean;
    const double forces = m.elastic() + m.contact_integrate() + m.contact_hessian + m.reduce;
    const double total = m.total();
    std::printf("  %-12s forces+stiffness %5.1f %% / collision %5.1f %% / linear solve %5.1f %%\n", name.c_str(),
                100 * forces / total, 100 * m.collision() / total, 100 * m.linear() / total);
  }
  std::fflush(stdout);
}

}  // namespace

/// Extra flag: --threads=N limits TBB to N threads (default: all cores). CHOLMOD's BLAS threads
/// follow OPENBLAS_NUM_THREADS.
int main(int argc, char** argv) {
  int threads = 0;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--threads=", 0) == 0)
      threads = std::stoi(arg.substr(10));
    else
      argv[kept++] = argv[i];
  }
  argc = kept;
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  print_table();
  return 0;
}
