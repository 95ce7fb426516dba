// run_stepper on its own: segments, step halving and growth, the minimum step, the two start
// modes and the two growth rules, driven by a scheme that makes every step longer than a
// threshold fail (its Newton start is an inverted state) on uniaxial tension; and a refinement
// whose re-solve fails: tried again with a softer change, or the step keeps its converged state.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "sinew/solver/stepper.hpp"
#include "support/solver_rig.hpp"

using namespace sinew;
namespace st = sinew::testing;

namespace {

/// Load stepping without a predictor; a step longer than `longest` starts Newton from an
/// inverted state, so Newton fails at once ("the starting state is illegal").
class ThresholdScheme final : public solver::StepScheme {
 public:
  ThresholdScheme(solver::Objective& objective, double longest) : objective_(objective), longest_(longest) {}

  fem::State start() override {
    fem::State state = objective_.dofs().initial_state(0.0);
    objective_.set_load_parameter(0.0);
    objective_.begin_step(state);
    return state;
  }
  fem::State predict(const fem::State& current, double t, double t_new, solver::NewtonSolver&) override {
    fem::State trial = current;
    objective_.dofs().sync(trial, t_new);
    objective_.set_load_parameter(t_new);
    if (t_new - t > longest_ * (1 + 1e-12)) trial.x *= -1.0;  // every tet inverted
    return trial;
  }
  void accept(const fem::State&, const fem::State&, double h) override { accepted.push_back(h); }
  void reject(const fem::State& current) override { objective_.set_load_parameter(current.lambda); }
  solver::SchemeMemory memory(const fem::State&, solver::NewtonSolver&) override { return {}; }
  void restore(const fem::State& current, const solver::SchemeMemory&) override {
    objective_.set_load_parameter(current.lambda);
    objective_.begin_step(current);
  }
  double bound_step(double, double h, double) const override { return h; }
  std::string start_failed(const std::string& why) const override { return "start: " + why; }
  std::string turn_too_fast(double, double) const override { return "turn"; }
  std::string step_too_small(double t, double, double, const std::string&) const override {
    return "too small at " + std::to_string(t);
  }
  std::string solved(const solver::StepperResult&) const override { return "solved"; }

  std::vector<double> accepted;  ///< sizes of the accepted steps

 private:
  solver::Objective& objective_;
  double longest_;
};

struct StepperRun {
  solver::StepperResult result;
  std::vector<double> segment_ends;  ///< t at each on_segment call (0 first)
  std::vector<int> steps_seen;       ///< StepRecord::step of each on_step call
  std::vector<double> sizes;         ///< accepted step sizes
  int cuts_seen = 0;
};

StepperRun run_threshold(double longest, const solver::StepperOptions& options) {
  st::SolverRig rig(st::uniaxial_problem(1.3, 0.5, 0.2, 1.5));
  solver::NewtonSolver newton(*rig.objective, {}, {.characteristic_length = std::sqrt(3.0), .reference_force = 1.0});
  ThresholdScheme scheme(*rig.objective, longest);
  StepperRun r;
  solver::StepperCallbacks callbacks;
  callbacks.on_segment = [&](int k, const solver::StepRecord& step, const fem::State&, const NodalVectors&) {
    EXPECT_EQ(k, static_cast<int>(r.segment_ends.size()));
    r.segment_ends.push_back(k == 0 ? 0.0 : step.t);
  };
  callbacks.on_step = [&](const solver::StepRecord& step, const fem::State&, const NodalVectors&) {
    r.steps_seen.push_back(step.step);
  };
  callbacks.on_cut = [&](const solver::StepRecord&, const std::string& why) {
    ++r.cuts_seen;
    EXPECT_NE(why.find("illegal"), std::string::npos) << why;
  };
  r.result = solver::run_stepper(newton, scheme, options, callbacks);
  r.sizes = scheme.accepted;
  return r;
}

solver::StepperOptions four_segments() {
  solver::StepperOptions o;
  o.end = 1;
  o.segment_length = 0.25;
  o.first_step = 0.25;
  o.max_step = 0.25;
  o.min_step = 1e-3;
  o.growth = 2;
  o.easy_iterations = 100;  // every converged step is easy
  return o;
}

}  // namespace

TEST(Stepper, EverySegmentEndsExactlyOnItsTargetAndStepsNeverCrossIt) {
  const StepperRun r = run_threshold(1.0, four_segments());
  ASSERT_TRUE(r.result.success) << r.result.message;
  EXPECT_EQ(r.result.message, "solved");
  ASSERT_EQ(r.segment_ends.size(), 5u);
  for (int k = 0; k <= 4; ++k) EXPECT_EQ(r.segment_ends[static_cast<std::size_t>(k)], 0.25 * k);
  EXPECT_EQ(r.result.t, 1.0);
  EXPECT_EQ(r.result.segments_completed, 4);
  EXPECT_EQ(r.result.steps, 4);
  EXPECT_EQ(r.result.cuts, 0);
  EXPECT_EQ(r.result.last_state.lambda, 1.0);
}

TEST(Stepper, AFailedStepIsHalvedUntilItConvergesAndEasyStepsGrowBackToTheLimit) {
  // Steps longer than 0.07 fail. Per segment of 0.25: 0.25 and 0.125 fail, 0.0625 converges
  // and grows the step to 0.125, which fails again twice more; the last 0.0625 lands on the
  // segment end and grows the step back to 0.25: four steps and four cuts per segment.
  const StepperRun r = run_threshold(0.07, four_segments());
  ASSERT_TRUE(r.result.success) << r.result.message;
  EXPECT_EQ(r.result.steps, 16);
  for (double h : r.sizes) EXPECT_DOUBLE_EQ(h, 0.0625);
  EXPECT_EQ(r.result.cuts, r.cuts_seen);
  EXPECT_EQ(r.result.cuts, 16);
  EXPECT_EQ(r.result.min_step, 0.0625);
  EXPECT_EQ(r.result.max_step, 0.0625);
}

TEST(Stepper, ACutBelowTheMinimumStepStopsTheRunAtTheLastConvergedState) {
  solver::StepperOptions o = four_segments();
  o.min_step = 0.1;
  const StepperRun r = run_threshold(0.07, o);  // 0.25 fails, 0.125 fails, 0.0625 < min_step
  EXPECT_FALSE(r.result.success);
  EXPECT_EQ(r.result.message, "too small at 0.000000");
  EXPECT_EQ(r.result.steps, 0);
  EXPECT_EQ(r.result.cuts, 2);
  EXPECT_EQ(r.result.last_state.lambda, 0.0);
  EXPECT_EQ(r.result.segments_completed, 0);
  EXPECT_EQ(r.result.min_step, 0.0);
}

TEST(Stepper, AGivenStartIsReportedAsStepZeroAndASolvedStartIsNot) {
  solver::StepperOptions o = four_segments();
  o.start = solver::StepperOptions::Start::GivenState;
  const StepperRun given = run_threshold(1.0, o);
  ASSERT_TRUE(given.result.success);
  ASSERT_FALSE(given.steps_seen.empty());
  EXPECT_EQ(given.steps_seen.front(), 0);
  o.start = solver::StepperOptions::Start::SolveEquilibrium;
  const StepperRun solved = run_threshold(1.0, o);
  ASSERT_TRUE(solved.result.success);
  EXPECT_EQ(solved.steps_seen.front(), 1);
  EXPECT_EQ(solved.steps_seen.size(), given.steps_seen.size() - 1);
}

TEST(Stepper, TheFullStepRuleDoesNotGrowAfterAStepShortenedToLandOnASegmentEnd) {
  // Segments of 0.5, first step 0.2, growth 2, no cap that matters (1.0).
  solver::StepperOptions o;
  o.end = 1;
  o.segment_length = 0.5;
  o.first_step = 0.2;
  o.max_step = 1.0;
  o.min_step = 1e-3;
  o.growth = 2;
  o.easy_iterations = 100;
  // After every easy step: 0.2 (-> 0.4), 0.3 shortened to land on 0.5 (-> 0.8), 0.5 (capped by
  // the segment end).
  o.growth_rule = solver::StepperOptions::Growth::AfterEasyStep;
  const StepperRun always = run_threshold(1.0, o);
  ASSERT_TRUE(always.result.success) << always.result.message;
  ASSERT_EQ(always.sizes.size(), 3u);
  EXPECT_NEAR(always.sizes[0], 0.2, 1e-12);
  EXPECT_NEAR(always.sizes[1], 0.3, 1e-12);
  EXPECT_NEAR(always.sizes[2], 0.5, 1e-12);
  // After full easy steps only: the shortened 0.3 does not grow the step, so the next is 0.4,
  // and the last 0.1 lands on 1.
  o.growth_rule = solver::StepperOptions::Growth::AfterEasyFullStep;
  const StepperRun full = run_threshold(1.0, o);
  ASSERT_TRUE(full.result.success) << full.result.message;
  ASSERT_EQ(full.sizes.size(), 4u);
  EXPECT_NEAR(full.sizes[0], 0.2, 1e-12);
  EXPECT_NEAR(full.sizes[1], 0.3, 1e-12);
  EXPECT_NEAR(full.sizes[2], 0.4, 1e-12);
  EXPECT_NEAR(full.sizes[3], 0.1, 1e-12);
}

TEST(Stepper, AResumedRunGoesOnFromEverySnapshotExactlyAsTheUninterruptedOne) {
  // Steps longer than 0.07 fail: four steps and four cuts per segment, so snapshots fall
  // before, at and after segment ends and the step size they carry matters.
  const solver::StepperOptions options = four_segments();
  std::vector<solver::StepperSnapshot> snapshots;
  std::vector<double> segment_ends, step_ts;
  solver::StepperResult full;
  {
    st::SolverRig rig(st::uniaxial_problem(1.3, 0.5, 0.2, 1.5));
    solver::NewtonSolver newton(*rig.objective, {}, {.characteristic_length = std::sqrt(3.0), .reference_force = 1.0});
    ThresholdScheme scheme(*rig.objective, 0.07);
    solver::StepperCallbacks callbacks;
    callbacks.on_accepted = [&](const solver::StepperSnapshot& s) { snapshots.push_back(s); };
    callbacks.on_segment = [&](int, const solver::StepRecord& step, const fem::State&, const NodalVectors&) {
      segment_ends.push_back(step.t);
    };
    callbacks.on_step = [&](const solver::StepRecord& step, const fem::State&, const NodalVectors&) {
      step_ts.push_back(step.t);
    };
    full = solver::run_stepper(newton, scheme, options, callbacks);
  }
  ASSERT_TRUE(full.success);
  ASSERT_EQ(snapshots.size(), 16u);
  EXPECT_TRUE(snapshots[3].segment_done);
  EXPECT_FALSE(snapshots[4].segment_done);
  // Each snapshot carries the phase times so far: they grow and end at most at the run's.
  EXPECT_GT(snapshots.front().times.forces_and_stiffness, 0);
  for (std::size_t i = 1; i < snapshots.size(); ++i)
    EXPECT_GE(snapshots[i].times.total(), snapshots[i - 1].times.total()) << i;
  EXPECT_LE(snapshots.back().times.total(), full.times.total());
  for (std::size_t i = 0; i < snapshots.size(); ++i) {
    SCOPED_TRACE("resumed after step " + std::to_string(i + 1));
    st::SolverRig rig(st::uniaxial_problem(1.3, 0.5, 0.2, 1.5));
    solver::NewtonSolver newton(*rig.objective, {}, {.characteristic_length = std::sqrt(3.0), .reference_force = 1.0});
    ThresholdScheme scheme(*rig.objective, 0.07);
    solver::StepperOptions resumed_options = options;
    resumed_options.resume = &snapshots[i];
    std::vector<double> ends, ts;
    solver::StepperCallbacks callbacks;
    callbacks.on_segment = [&](int, const solver::StepRecord& step, const fem::State&, const NodalVectors&) {
      ends.push_back(step.t);
    };
    callbacks.on_step = [&](const solver::StepRecord& step, const fem::State&, const NodalVectors&) {
      ts.push_back(step.t);
    };
    const solver::StepperResult r = solver::run_stepper(newton, scheme, resumed_options, callbacks);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.steps, full.steps);
    EXPECT_EQ(r.cuts, full.cuts);
    EXPECT_EQ(r.newton_iterations, full.newton_iterations);
    EXPECT_EQ(r.segments_completed, 4);
    EXPECT_EQ(r.min_step, full.min_step);
    EXPECT_NEAR((r.last_state.x - full.last_state.x).norm(), 0.0, 1e-12);
    // The steps after the snapshot, and the segment ends not yet reported, exactly once each.
    EXPECT_EQ(ts, std::vector<double>(step_ts.begin() + static_cast<std::ptrdiff_t>(i + 1), step_ts.end()));
    const std::size_t reported = static_cast<std::size_t>(snapshots[i].counts.segments_completed);
    EXPECT_EQ(ends, std::vector<double>(segment_ends.begin() + static_cast<std::ptrdiff_t>(reported + 1),
                                        segment_ends.end()));
  }
}

namespace {

/// A refinement whose one outer iteration asks for a load the step cannot reach in the Newton
/// budget (load parameter 3: 400 times the force); retry_softer() then asks for load parameter 2
/// (1.5 times the force) when `soften`, or goes back to the step's own load.
class OverreachingRefinement final : public solver::StepRefinement {
 public:
  OverreachingRefinement(solver::Objective& objective, bool soften) : objective_(objective), soften_(soften) {}
  bool refine(const fem::State&) override {
    if (refined_) return false;
    refined_ = true;
    objective_.set_load_parameter(3);
    return true;
  }
  bool retry_softer() override {
    ++retries;
    objective_.set_load_parameter(soften_ && retries == 1 ? 2 : 1);
    return soften_ && retries == 1;
  }
  void accept(const fem::State&) override {}
  void reject() override {}
  int retries = 0;

 private:
  solver::Objective& objective_;
  bool soften_;
  bool refined_ = false;
};

/// The unit cube on rollers pulled by a force on its x = 1 face with `amplitude`, in one step of
/// at most 6 Newton iterations, with `refinement` (null: none) built on the rig's objective.
solver::StepperResult run_pulled_cube(const fem::Amplitude& amplitude,
                                      const std::function<std::unique_ptr<solver::StepRefinement>(solver::Objective&)>&
                                          make_refinement = {}) {
  auto p = st::box_problem(3, 2, 2, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin(0.5, 0.2, 1.5));
  p.planar.push_back({"x0", st::nodes_on_plane(p.mesh, 0, 0.0), Vector3::UnitX(), 0.0, {}});
  p.planar.push_back({"y0", st::nodes_on_plane(p.mesh, 1, 0.0), Vector3::UnitY(), 0.0, {}});
  p.planar.push_back({"z0", st::nodes_on_plane(p.mesh, 2, 0.0), Vector3::UnitZ(), 0.0, {}});
  p.forces.push_back({"pull", st::nodes_on_plane(p.mesh, 0, 1.0), Vector3(0.2, 0, 0), amplitude, {}});
  st::SolverRig rig(std::move(p));
  solver::NewtonSolver newton(*rig.objective, {}, {.characteristic_length = std::sqrt(3.0), .reference_force = 1.0});
  ThresholdScheme scheme(*rig.objective, 1.0);
  solver::StepperOptions options;
  options.end = options.segment_length = options.first_step = options.max_step = 1;
  options.newton.max_iterations = 6;
  const auto refinement = make_refinement ? make_refinement(*rig.objective) : nullptr;
  return solver::run_stepper(newton, scheme, options, {}, refinement.get());
}

fem::Amplitude amplitude_of(std::vector<std::pair<double, double>> points) {
  fem::Amplitude amplitude;
  amplitude.points = std::move(points);
  return amplitude;
}

}  // namespace

TEST(Stepper, AReSolveThatFailsAfterARefinementIsTriedAgainWithASofterChange) {
  const fem::Amplitude amplitude = amplitude_of({{0, 0}, {1, 1}, {2, 1.5}, {3, 400}});
  const solver::StepperResult refined = run_pulled_cube(amplitude, [](solver::Objective& objective) {
    return std::make_unique<OverreachingRefinement>(objective, true);
  });
  ASSERT_TRUE(refined.success) << refined.message;
  EXPECT_EQ(refined.cuts, 0);
  EXPECT_EQ(refined.refinements, 2);  // the failed re-solve and the softer one
  // The step ends where the softer load (1.5 times the force) puts it.
  const solver::StepperResult direct = run_pulled_cube(amplitude_of({{0, 0}, {1, 1.5}}));
  ASSERT_TRUE(direct.success) << direct.message;
  EXPECT_LT((refined.last_state.x - direct.last_state.x).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(Stepper, WithNothingSofterLeftTheStepKeepsTheStateItHadConvergedTo) {
  const fem::Amplitude amplitude = amplitude_of({{0, 0}, {1, 1}, {2, 1.5}, {3, 400}});
  const solver::StepperResult refined = run_pulled_cube(amplitude, [](solver::Objective& objective) {
    return std::make_unique<OverreachingRefinement>(objective, false);
  });
  ASSERT_TRUE(refined.success) << refined.message;
  EXPECT_EQ(refined.cuts, 0);
  EXPECT_EQ(refined.refinements, 1);
  const solver::StepperResult direct = run_pulled_cube(amplitude_of({{0, 0}, {1, 1}}));
  ASSERT_TRUE(direct.success) << direct.message;
  EXPECT_EQ(refined.last_state.x, direct.last_state.x);
}
