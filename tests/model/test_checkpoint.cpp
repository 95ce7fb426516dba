/// @file test_checkpoint.cpp
/// model/checkpoint.hpp: a checkpoint file holds a run's snapshot exactly; a model resumed from
/// any snapshot of a run ends where the run ended (static with the tangent predictor and an
/// adaptive penalty, implicit dynamics); the fingerprint tells scenes apart; every kind of bad
/// checkpoint is refused with a message that names the file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/contact_scenes.hpp"
#include "support/files.hpp"
#include "support/temp_dir.hpp"
#include "sinew/core/error.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/model/checkpoint.hpp"
#include "sinew/model/solve_model.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::model {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

/// The stacked blocks (examples/stacked-blocks.json) in 6 increments at a penalty 100 times
/// below the automatic one, with the adaptive penalty growing it between steps.
json static_scene() {
  json scene = json::parse(sinew::testing::read_text(std::string(SINEW_SOURCE_DIR) + "/examples/stacked-blocks.json"));
  scene["contact"]["penalty"] = 0.0636;
  scene["contact"]["enforcement"] = {{"method", "adaptive-penalty"}, {"penetration_tolerance", 0.002}};
  scene["solver"]["increments"] = 6;
  return scene;
}

/// A soft box dropped onto a rigid plate (implicit Euler).
/// The same box dropped onto the plate (implicit Euler).
json dynamic_scene() {
  json scene = sinew::testing::box_on_plate_scene();
  scene["bodies"][0]["regions"]["gel"]["density"] = 1.0;
  scene["bodies"][0]["transform"] = {{"translate", {0, 0, 0.02}}};
  scene["loads"] = {{"gravity", {0, 0, -9.81}}};
  scene["dynamics"] = {{"integrator", "implicit-euler"}, {"end_time", 0.2}, {"output_interval", 0.05}, {"time_step", 0.01}, {"max_time_step", 0.01}};
  return scene;
}

Model built_model(const json& scene) { return build_model(scene::parse_scene(scene, "")); }

struct SolvedRun {
  solver::StepperResult result;
  std::vector<RunSnapshot> snapshots;
};

SolvedRun solve(Model& model, const RunSnapshot* resume = nullptr) {
  SolvedRun run;
  solver::StepperCallbacks callbacks;
  callbacks.on_accepted = [&](const solver::StepperSnapshot& s) { run.snapshots.push_back(take_snapshot(model, s)); };
  run.result = solve_model(model, callbacks, resume);
  return run;
}

Checkpoint checkpoint_of(const RunSnapshot& snapshot) {
  Checkpoint c;
  c.fingerprint = 0x0123456789abcdefull;
  c.snapshot = snapshot;
  c.counters = {{"steps", 3}, {"newton", 17}};
  c.series = {{0.0, "vtu/increment_0000.vtu"}, {0.5, "vtu/increment_0001.vtu"}};
  return c;
}

void expect_same(const RunSnapshot& a, const RunSnapshot& b) {
  EXPECT_EQ(a.stepper.state.x, b.stepper.state.x);
  EXPECT_EQ(a.stepper.state.lambda, b.stepper.state.lambda);
  ASSERT_EQ(a.stepper.state.rigid.size(), b.stepper.state.rigid.size());
  for (std::size_t r = 0; r < a.stepper.state.rigid.size(); ++r) {
    EXPECT_EQ(a.stepper.state.rigid[r].R, b.stepper.state.rigid[r].R);
    EXPECT_EQ(a.stepper.state.rigid[r].t, b.stepper.state.rigid[r].t);
  }
  EXPECT_EQ(a.stepper.t, b.stepper.t);
  EXPECT_EQ(a.stepper.next_step, b.stepper.next_step);
  EXPECT_EQ(a.stepper.segment, b.stepper.segment);
  EXPECT_EQ(a.stepper.segment_done, b.stepper.segment_done);
  EXPECT_EQ(a.stepper.record.newton_iterations, b.stepper.record.newton_iterations);
  EXPECT_EQ(a.stepper.record.energy, b.stepper.record.energy);
  EXPECT_EQ(a.stepper.counts.steps, b.stepper.counts.steps);
  EXPECT_EQ(a.stepper.counts.newton_iterations, b.stepper.counts.newton_iterations);
  EXPECT_EQ(a.stepper.counts.min_step, b.stepper.counts.min_step);
  EXPECT_EQ(a.stepper.scheme.previous.x, b.stepper.scheme.previous.x);
  EXPECT_EQ(a.stepper.scheme.tangent, b.stepper.scheme.tangent);
  EXPECT_EQ(a.stepper.scheme.velocity, b.stepper.scheme.velocity);
  EXPECT_EQ(a.stepper.record.dissipated, b.stepper.record.dissipated);
  EXPECT_EQ(a.stepper.counts.stabilized_steps, b.stepper.counts.stabilized_steps);
  EXPECT_EQ(a.stepper.counts.dissipated, b.stepper.counts.dissipated);
  EXPECT_EQ(a.stepper.scheme.stabilized, b.stepper.scheme.stabilized);
  EXPECT_EQ(a.contact_penalty, b.contact_penalty);
  EXPECT_EQ(a.contact_pressure, b.contact_pressure);
}

TEST(Checkpoint, AFileHoldsTheSnapshotExactly) {
  Model model = built_model(static_scene());
  const SolvedRun run = solve(model);
  ASSERT_TRUE(run.result.success) << run.result.message;
  ASSERT_GE(run.snapshots.size(), 6u);
  RunSnapshot snapshot = run.snapshots[2];
  EXPECT_GT(snapshot.stepper.scheme.tangent.size(), 0);  // the tangent predictor's direction
  EXPECT_FALSE(snapshot.stepper.scheme.stabilized);
  // As a stabilized run would have them (solver.stabilization).
  snapshot.stepper.scheme.stabilized = true;
  snapshot.stepper.record.dissipated = 0.25;
  snapshot.stepper.counts.stabilized_steps = 7;
  snapshot.stepper.counts.dissipated = 1.5;
  EXPECT_GT(snapshot.stepper.scheme.previous.x.rows(), 0);
  sinew::testing::TempDir directory;
  const std::string path = (directory / kCheckpointFile).string();
  write_checkpoint(path, checkpoint_of(snapshot));
  const Checkpoint read = read_checkpoint(path);
  EXPECT_EQ(read.fingerprint, 0x0123456789abcdefull);
  expect_same(read.snapshot, snapshot);
  EXPECT_EQ(read.counters, (std::map<std::string, long long>{{"steps", 3}, {"newton", 17}}));
  EXPECT_EQ(read.series, checkpoint_of(snapshot).series);
  EXPECT_NO_THROW(check_snapshot_fits(model, read.snapshot, "the checkpoint"));
}

TEST(Checkpoint, AProcessThatWritesNoFilesLeavesNoCheckpoint) {
  // The MPI ranks other than 0 (io::set_files_written(false)), which skip encoding it too.
  Model model = built_model(static_scene());
  const SolvedRun run = solve(model);
  ASSERT_TRUE(run.result.success) << run.result.message;
  sinew::testing::TempDir directory;
  const std::string path = (directory / kCheckpointFile).string();
  io::set_files_written(false);
  write_checkpoint(path, checkpoint_of(run.snapshots.back()));
  io::set_files_written(true);
  EXPECT_FALSE(std::filesystem::exists(path));
  write_checkpoint(path, checkpoint_of(run.snapshots.back()));
  expect_same(read_checkpoint(path).snapshot, run.snapshots.back());
}

TEST(Checkpoint, AStaticRunResumedFromAnyStepEndsWhereTheRunEnded) {
  Model model = built_model(static_scene());
  const SolvedRun full = solve(model);
  ASSERT_TRUE(full.result.success) << full.result.message;
  // The adaptive penalty grew the pair's penalty: a resume must bring it back.
  EXPECT_GT(full.snapshots.back().contact_penalty.maxCoeff(), 0.0636);
  for (const std::size_t k : {std::size_t{0}, full.snapshots.size() / 2, full.snapshots.size() - 2}) {
    SCOPED_TRACE("resumed after step " + std::to_string(k + 1));
    Model fresh = built_model(static_scene());
    const SolvedRun resumed = solve(fresh, &full.snapshots[k]);
    ASSERT_TRUE(resumed.result.success) << resumed.result.message;
    EXPECT_EQ(resumed.result.steps, full.result.steps);
    EXPECT_EQ(resumed.result.newton_iterations, full.result.newton_iterations);
    EXPECT_EQ(resumed.result.cuts, full.result.cuts);
    EXPECT_LT((resumed.result.last_state.x - full.result.last_state.x).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_TRUE(resumed.snapshots.back().contact_penalty.isApprox(full.snapshots.back().contact_penalty, 1e-12));
  }
}

TEST(Checkpoint, AnImplicitDynamicRunResumedEndsWithTheSameStateAndVelocity) {
  Model model = built_model(dynamic_scene());
  const SolvedRun full = solve(model);
  ASSERT_TRUE(full.result.success) << full.result.message;
  ASSERT_GE(full.snapshots.size(), 10u);
  const RunSnapshot& middle = full.snapshots[full.snapshots.size() / 2];
  EXPECT_EQ(middle.stepper.scheme.velocity.rows(), model.problem->mesh.num_nodes());
  Model fresh = built_model(dynamic_scene());
  const SolvedRun resumed = solve(fresh, &middle);
  ASSERT_TRUE(resumed.result.success) << resumed.result.message;
  EXPECT_EQ(resumed.result.steps, full.result.steps);
  EXPECT_EQ(resumed.result.t, full.result.t);
  EXPECT_LT((resumed.result.last_state.x - full.result.last_state.x).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((resumed.result.last_velocity - full.result.last_velocity).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Checkpoint, TheFingerprintTellsScenesAndMeshesApart) {
  const Model a = built_model(static_scene());
  const Model b = built_model(static_scene());
  EXPECT_EQ(model_fingerprint(a, "scene text"), model_fingerprint(b, "scene text"));
  EXPECT_NE(model_fingerprint(a, "scene text"), model_fingerprint(a, "scene text 2"));
  json finer = static_scene();
  finer["bodies"][0]["mesh"]["generate"]["element_size"] =
      0.8 * finer["bodies"][0]["mesh"]["generate"]["element_size"].get<double>();
  EXPECT_NE(model_fingerprint(a, "scene text"), model_fingerprint(built_model(finer), "scene text"));
}

std::string read_error(const std::string& path) {
  try {
    read_checkpoint(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Checkpoint, MissingForeignOldAndDamagedFilesAreRefusedByName) {
  sinew::testing::TempDir directory;
  const std::string path = (directory / kCheckpointFile).string();
  EXPECT_THAT(read_error(path), HasSubstr("no checkpoint at \"" + path + "\""));

  sinew::testing::write_text(path, "plain text, not CBOR");
  EXPECT_THAT(read_error(path), HasSubstr("is not a usable sinew checkpoint (it does not parse"));

  auto write_json = [&](const json& j) {
    const std::vector<std::uint8_t> bytes = json::to_cbor(j);
    sinew::testing::write_text(path, std::string(bytes.begin(), bytes.end()));
  };
  write_json({{"format", "something-else"}});
  EXPECT_THAT(read_error(path), HasSubstr("it was not written by sinew"));
  write_json({{"format", "sinew-checkpoint"}, {"version", 99}});
  EXPECT_THAT(read_error(path), HasSubstr("it has format version 99, this sinew reads version 1"));
  write_json({{"format", "sinew-checkpoint"}, {"version", 1}, {"fingerprint", 1}});
  EXPECT_THAT(read_error(path), HasSubstr("it is damaged (no \"stepper\")"));

  // A real checkpoint cut short, and one with a matrix of the wrong size.
  Model model = built_model(static_scene());
  const SolvedRun run = solve(model);
  ASSERT_FALSE(run.snapshots.empty());
  write_checkpoint(path, checkpoint_of(run.snapshots.front()));
  const std::string whole = sinew::testing::read_text(path);
  sinew::testing::write_text(path, whole.substr(0, whole.size() / 2));
  EXPECT_THAT(read_error(path), HasSubstr("is not a usable sinew checkpoint"));
  json j = json::from_cbor(whole);
  j["stepper"]["state"]["x"]["rows"] = 5;
  write_json(j);
  EXPECT_THAT(read_error(path), HasSubstr("it is damaged (\"x\" is not a 5 x 3 matrix)"));
  j["stepper"]["state"]["x"]["rows"] = 1LL << 40;  // rows x cols would overflow
  j["stepper"]["state"]["x"]["cols"] = 1LL << 40;
  write_json(j);
  EXPECT_THAT(read_error(path), HasSubstr("is not a 1099511627776 x 1099511627776 matrix"));
}

TEST(Checkpoint, ASnapshotOfAnotherModelDoesNotFit) {
  Model model = built_model(static_scene());
  const SolvedRun run = solve(model);
  ASSERT_FALSE(run.snapshots.empty());
  RunSnapshot snapshot = run.snapshots.front();
  auto fit_error = [&](const RunSnapshot& s) {
    try {
      check_snapshot_fits(model, s, "the checkpoint in \"out\"");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  RunSnapshot fewer_nodes = snapshot;
  fewer_nodes.stepper.state.x.conservativeResize(4, 3);
  EXPECT_THAT(fit_error(fewer_nodes), HasSubstr("the checkpoint in \"out\" does not fit this scene (4 nodes"));
  RunSnapshot tangent = snapshot;
  tangent.stepper.scheme.tangent.resize(3);
  EXPECT_THAT(fit_error(tangent), HasSubstr("another number of unknowns"));
  RunSnapshot dynamic = snapshot;
  dynamic.stepper.scheme.velocity = NodalVectors::Zero(snapshot.stepper.state.x.rows(), 3);
  EXPECT_THAT(fit_error(dynamic), HasSubstr("a static and a dynamic analysis"));
  RunSnapshot bodies = snapshot;
  bodies.contact_penalty = MatrixX::Ones(3, 3);
  EXPECT_THAT(fit_error(bodies), HasSubstr("another number of contact bodies"));
  RunSnapshot nan = snapshot;
  nan.stepper.state.x(0, 0) = std::nan("");
  EXPECT_THAT(fit_error(nan), HasSubstr("not finite"));
}

TEST(Checkpoint, ExplicitIntegrationCannotResume) {
  json scene = dynamic_scene();
  scene["dynamics"]["integrator"] = "explicit";
  scene["dynamics"]["end_time"] = 1e-4;
  Model model = built_model(scene);
  Model other = built_model(static_scene());
  const SolvedRun run = solve(other);
  ASSERT_FALSE(run.snapshots.empty());
  try {
    solve_model(model, {}, &run.snapshots.front());
    FAIL() << "resumed";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("explicit integration cannot resume"));
  }
}

}  // namespace
}  // namespace sinew::model
