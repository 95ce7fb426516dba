/// @file test_cli_mpi.cpp
/// `mpirun -n N sinew run`: the ranks share the elements and the linear solve (docs/mpi.md) and
/// must give the run of one process: the same steps and Newton iterations, and reactions,
/// energies and penetrations equal to round-off. Rank 0 alone writes; a failure ends every rank.
/// Skipped where mpirun is missing.

#include <signal.h>
#include <sys/wait.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "parallel_run.hpp"
#include "app_test_support.hpp"
#include "mpi_test_support.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/core/error.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/quadratic_energy.hpp"
#include "sinew/fem/rigid_body_modes.hpp"
#include "sinew/mesh/tet_mesh_bytes.hpp"
#include "sinew/model/model.hpp"
#include "sinew/parallel/ranks.hpp"
#include "sinew/parallel/root_for_all.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/scene/element_size.hpp"
#include "sinew/scene/load_scene.hpp"
#include "support/files.hpp"
#include "support/temp_dir.hpp"
#include "surface/surface_fixtures.hpp"
#include "sinew/solver/linear_solver.hpp"
#include "sinew/solver/petsc_linear_solver.hpp"

namespace sinew::app_test {
namespace {

using ::testing::HasSubstr;

TEST_F(Mpi, ARigidBallPressedIntoABlockSolvesAsOnOneProcess) {
  // Contact, a rigid body, symmetry planes; CHOLMOD on every rank.
  expect_same_runs(example("hertz-ball"), {2, 4});

  // Each rank's piece is a compact part of the mesh (docs/mpi.md, "Who owns what"): the two pieces
  // of the last increment share few points. (Pieces of contiguous tet numbers shared 1,060 of the
  // 1,547 points, since Gmsh numbers the tets of a region in no spatial order; the partition 118.)
  const auto points = [](const fs::path& vtu) {
    const std::string text = read_text(vtu);
    const std::size_t at = text.find("NumberOfPoints=\"");
    return at == std::string::npos ? -1L : std::stol(text.substr(at + 16));
  };
  const fs::path run = directory / "case0";
  const long whole = points(run / "serial" / "vtu" / "increment_0005.vtu");
  const long pieces = points(run / "ranks2" / "vtu" / "increment_0005_p0.vtu") +
                      points(run / "ranks2" / "vtu" / "increment_0005_p1.vtu");
  ASSERT_GT(whole, 1000);
  EXPECT_GE(pieces, whole);
  EXPECT_LT(pieces - whole, whole / 5) << "points in both pieces";
}

/// The percentage in rank 0's "... % of the nonzeros couple two ranks; ..." (the linear solve's
/// layout, logged once), or -1 when the log has no such line.
double coupling_percentage(const std::string& log) {
  const std::size_t at = log.find(" % of the nonzeros couple two ranks");
  if (at == std::string::npos) return -1;
  const std::size_t start = log.rfind(' ', at - 1);
  return std::stod(log.substr(start + 1, at - start - 1));
}

TEST_F(Mpi, MumpsAndGamgShareTheLinearSolveAcrossRanks) {
  expect_same_runs(example("hertz-ball", "petsc-mumps"), {2, 3});
  // Each rank holds the rows of the nodes it owns (docs/mpi.md, "Who owns what"), so few of the
  // matrix's nonzeros couple two ranks: 7.4 % of the hertz-ball's on two ranks, where contiguous
  // ranges of the unknowns coupled 23.1 %.
  EXPECT_THAT(last_ranks_log, HasSubstr("rows by the mesh partition"));
  // Nor is the whole tangent summed on every rank: each adds its part into PETSc's matrix.
  EXPECT_THAT(last_ranks_log, HasSubstr("each rank adds its part of the tangent"));
  const double coupling = coupling_percentage(last_ranks_log);
  EXPECT_GT(coupling, 0) << last_ranks_log;
  EXPECT_LT(coupling, 15) << last_ranks_log;
  // GAMG's aggregates depend on the partition: solved tightly, the runs agree all the same.
  expect_same_runs(example("hertz-ball", "petsc-gamg"), {2});
}

TEST_F(Mpi, ADynamicRunHoldsTheRowsOfItsNodesInPetsc) {
  // Time steps go to Newton without a predictor's factorization first: the rows still follow the
  // mesh partition.
  json scene = example("ball-drop", "petsc-mumps");
  scene["dynamics"]["end_time"] = 0.1;
  expect_same_runs(scene, {2});
  EXPECT_THAT(last_ranks_log, HasSubstr("rows by the mesh partition"));
  EXPECT_GT(coupling_percentage(last_ranks_log), 0) << last_ranks_log;
}

TEST_F(Mpi, StackedBlocksWithFrictionSolveAsOnOneProcess) { expect_same_runs(example("stacked-blocks"), {2, 4}); }

TEST_F(Mpi, ATwistedCylinderSolvesAsOnOneProcess) { expect_same_runs(example("twisted-cylinder"), {2}); }

TEST_F(Mpi, ADynamicRunWithFrictionSolvesAsOnOneProcess) { expect_same_runs(example("block-on-incline"), {2}); }

TEST_F(Mpi, ACommandPrintsItsReportOnce) {
  const CommandResult result =
      run_sinew({"validate", (kSource / "examples" / "hertz-ball.json").string()}, directory, mpirun(2));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
  EXPECT_THAT(result.out, HasSubstr(": valid ("));
}

TEST_F(Mpi, ABadSceneIsRejectedOnceAndNothingIsWritten) {
  json scene = small_block_scene();
  scene["materials"]["rubber"]["C1"] = -1.0;
  const fs::path scene_path = directory / "bad.json";
  write_text(scene_path, scene.dump(2));
  const fs::path output = directory / "out";
  const CommandResult result =
      run_sinew({"run", scene_path.string(), "-o", output.string(), "--no-progress"}, directory, mpirun(2));
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr("C1"));
  std::size_t errors = 0;  // rank 0's message only
  for (std::size_t at = result.err.find("[error]"); at != std::string::npos; at = result.err.find("[error]", at + 1))
    ++errors;
  EXPECT_EQ(errors, 1u) << result.err;
  EXPECT_FALSE(fs::exists(output));
}

TEST_F(Mpi, AnOutputDirectoryInUseIsRefusedOnEveryRank) {
  // An earlier run's results without --overwrite: rank 0 refuses, and the other ranks stop too
  // (the run would otherwise wait for rank 0 forever).
  const fs::path scene_path = directory / "block.json";
  write_text(scene_path, small_block_scene().dump(2));
  const fs::path output = directory / "out";
  ASSERT_EQ(run_sinew({"run", scene_path.string(), "-o", output.string(), "--no-progress"}, directory).exit_code, 0);
  const std::string before = read_text(output / "summary.json");
  const CommandResult again =
      run_sinew({"run", scene_path.string(), "-o", output.string(), "--no-progress"}, directory, mpirun(2));
  EXPECT_EQ(again.exit_code, 1) << again.err;
  EXPECT_THAT(again.err, HasSubstr("--overwrite"));
  EXPECT_EQ(read_text(output / "summary.json"), before);
}

TEST_F(Mpi, AWriteThatFailsOnRankZeroEndsEveryRankWithItsExitCode) {
  // A full disk mid-run: only rank 0 writes, so only it fails; the others, waiting for it in the
  // next sum, must be ended too (MPI_Abort with exit code 3), not left hanging. Needs a small
  // tmpfs (root in a sandbox that allows mounts); skipped elsewhere.
  const fs::path output = directory / "full";
  const SmallTmpfs disk(output);
  if (!disk.mounted()) GTEST_SKIP() << "cannot mount a small tmpfs here";
  json scene = small_block_scene();
  scene["bodies"][0]["mesh"]["generate"]["element_size"] = 1.5;  // VTUs larger than the disk
  scene["solver"]["increments"] = 4;
  const fs::path scene_path = directory / "block.json";
  write_text(scene_path, scene.dump(2));
  const CommandResult result = run_sinew({"run", scene_path.string(), "-o", output.string(), "--no-progress"},
                                         directory, with_timeout(mpirun(2)));
  EXPECT_EQ(result.exit_code, 3) << result.err;  // not 124: timeout did not have to stop a hang
  EXPECT_THAT(result.err, HasSubstr("cannot write file"));
}

TEST_F(Mpi, CtrlCStopsEveryRankWithACheckpointThatResumesOnRanks) {
  // mpirun passes Ctrl-C on to the ranks as SIGTERM; the ranks agree on it after a Newton
  // iteration and rank 0 writes the checkpoint and the summary before they end.
  // mpirun passes the signal on about a second late (OpenMPI 4.1), so the run must still be
  // stepping then: ball-drop with its element sizes at 3/4 (7,504 tets, 103 time steps, about
  // 7 s of computing in the Release build on two ranks; block-on-incline over 0.4 s, used before,
  // took 5 s and then 1 s once the linear solves and the contact got faster).
  json scene = example("ball-drop");
  for (auto& body : scene["bodies"]) {
    auto& generate = body["mesh"]["generate"];
    generate["element_size"] = 0.75 * generate["element_size"].get<double>();
  }
  const fs::path scene_path = directory / "ball.json";
  write_text(scene_path, scene.dump(2));
  const auto arguments = [&](const fs::path& output) {
    return std::vector<std::string>{"run", scene_path.string(), "-o", output.string(), "--no-progress", "-j", "1"};
  };
  const fs::path serial = directory / "serial";
  const CommandResult one = run_sinew(arguments(serial), directory);
  ASSERT_EQ(one.exit_code, 0) << one.err;

  const fs::path output = directory / "interrupted";
  const SignalledRun interrupted = run_and_signal(
      arguments(output), directory, SignalPlan{.signal = SIGINT, .ready = output / "checkpoint.cbor"}, mpirun(2));
  ASSERT_TRUE(interrupted.signalled) << "the run ended before its first checkpoint: " << read_text(interrupted.log);
  const int status = interrupted.status;
  ASSERT_TRUE(WIFEXITED(status)) << "mpirun ended by a signal";
  EXPECT_NE(WEXITSTATUS(status), 0);  // mpirun's own code for a job it was told to stop (1 with OpenMPI)
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("status"), "interrupted");
  EXPECT_THAT(summary.at("message").get<std::string>(), HasSubstr("--resume"));
  EXPECT_GT(summary.at("steps").get<int>(), 0);

  const CommandResult resumed = run_sinew([&] {
    auto words = arguments(output);
    words.emplace_back("--resume");
    return words;
  }(), directory, with_timeout(mpirun(2)));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("resuming after step"));
  expect_same_table(serial / "steps.csv", output / "steps.csv", 1e-6);
  expect_same_table(serial / "rigid_bodies.csv", output / "rigid_bodies.csv", 1e-6);
}

// The rank helpers of app/parallel_run.hpp on real ranks: this test program runs itself under
// mpirun with the filter RanksUnderMpirun.* (Mpi.TheRankHelpersWorkUnderMpirun below); run
// without mpirun these tests skip.

TEST(RanksUnderMpirun, StatesThatDifferBetweenRanksStopTheRunWithAClearError) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  ASSERT_GT(parallel::size(), 1);
  fem::State state;
  state.x = Positions::Ones(5, 3);
  state.lambda = 0.5;
  EXPECT_NO_THROW(app::check_ranks_agree(state, 0.5, 3));
  if (parallel::rank() == 1) state.x(2, 1) += 1e-9;  // one rank's state drifts
  try {
    app::check_ranks_agree(state, 0.5, 4);
    ADD_FAILURE() << "rank " << parallel::rank() << ": differing states passed";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), HasSubstr("the MPI ranks' states differ after step 4"));
    EXPECT_THAT(error.what(), HasSubstr("please report it"));
  }
  // A different load parameter alone also counts.
  state.x = Positions::Ones(5, 3);
  EXPECT_THROW(app::check_ranks_agree(state, parallel::rank() == 0 ? 0.5 : 0.75, 5), Error);
}

TEST(RanksUnderMpirun, AFailureOnRankZeroIsThrownOnEveryRankWithItsKindAndMessage) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  bool ran = false;
  EXPECT_NO_THROW(parallel::on_root_for_all([&] { ran = true; }));
  EXPECT_EQ(ran, parallel::is_root());  // the step runs on rank 0 alone
  try {
    parallel::on_root_for_all([] { throw OutputError("cannot write file 'x': disk full"); });
    ADD_FAILURE() << "rank " << parallel::rank() << ": no exception";
  } catch (const OutputError& error) {  // the same kind on every rank, not just Error
    EXPECT_STREQ(error.what(), "cannot write file 'x': disk full");
  }
  EXPECT_THROW(parallel::on_root_for_all([] { throw InputError("bad scene"); }), InputError);
}

TEST(RanksUnderMpirun, EachRankHoldsOnlyItsPartOfTheHessianAndThePartsAddUpToTheWhole) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  // The hemisphere pressed halfway onto the rigid block: elastic tets, contact pairs, symmetry
  // planes and a roller, each rank evaluating its share.
  model::Model model = model::build_model(scene::parse_scene(example("hertz-ball"), ""));
  solver::Objective& objective = *model.objective;
  const fem::State state = model.dofs->initial_state(0.5);
  const NodalVectors gradient = objective.full_gradient(state);
  fem::SparseMatrix whole, part;
  objective.set_hessian_summed(true);
  objective.hessian(state, gradient, VectorX(), whole);
  const Index whole_blocks = objective.full_hessian().num_blocks();
  objective.set_hessian_summed(false);
  EXPECT_TRUE(objective.hessian(state, gradient, VectorX(), part)) << "a new pattern must be reported on every rank";
  const Index part_blocks = objective.full_hessian().num_blocks();
  // Each rank's pattern holds its part of the mesh (and every node's diagonal block): well under
  // the whole on two ranks.
  EXPECT_LT(part_blocks, whole_blocks * 3 / 4) << "rank " << parallel::rank();
  EXPECT_LT(part.nonZeros(), whole.nonZeros() * 3 / 4) << "rank " << parallel::rank();
  ASSERT_EQ(part.rows(), whole.rows());
  // Every entry of a part is in the whole pattern, and the parts add up to the summed K.
  std::vector<double> sum(static_cast<std::size_t>(whole.nonZeros()), 0.0);
  for (int column = 0; column < part.outerSize(); ++column)
    for (fem::SparseMatrix::InnerIterator entry(part, column); entry; ++entry) {
      const int* begin = whole.innerIndexPtr() + whole.outerIndexPtr()[column];
      const int* end = whole.innerIndexPtr() + whole.outerIndexPtr()[column + 1];
      const int* at = std::lower_bound(begin, end, static_cast<int>(entry.row()));
      ASSERT_TRUE(at != end && *at == entry.row()) << "(" << entry.row() << ", " << column << ") outside the whole pattern";
      sum[static_cast<std::size_t>(at - whole.innerIndexPtr())] += entry.value();
    }
  parallel::sum(sum.data(), sum.size());
  double largest = 0, difference = 0;
  for (std::size_t k = 0; k < sum.size(); ++k) {
    largest = std::max(largest, std::abs(whole.valuePtr()[k]));
    difference = std::max(difference, std::abs(sum[k] - whole.valuePtr()[k]));
  }
  EXPECT_GT(largest, 0);
  EXPECT_LE(difference, 1e-12 * largest);
}

TEST(RanksUnderMpirun, EachRankHoldsTheElasticTermOfItsOwnTetsOnlyAndTheirSumIsTheWhole) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  // ball-drop with stiffness damping, whose K0 needs the elastic stiffness of every tet.
  nlohmann::json scene = example("ball-drop");
  scene["dynamics"]["stiffness_damping"] = 0.01;
  model::Model model = model::build_model(scene::parse_scene(scene, ""));
  const Tets& tets = model.problem->mesh.tets;
  // The rank's elastic term holds exactly the deformable tets it owns (docs/mpi.md).
  std::vector<Index> own;
  for (Index t = 0; t < tets.rows(); ++t)
    if (!fem::is_rigid_tet(*model.problem, t) && model.tet_owner[static_cast<std::size_t>(t)] == parallel::rank())
      own.push_back(t);
  EXPECT_EQ(model.elastic->deformable_tets(), own);
  EXPECT_GT(own.size(), 0u);
  EXPECT_EQ(model.elastic->rest_shapes().size(), own.size());
  EXPECT_EQ(model.elastic->materials().size(), own.size());
  // Summed over the ranks, value and gradient are those of the whole term, here built by the test.
  const fem::ElasticEnergy whole(model.problem->mesh.rest, tets, fem::tet_laws(*model.problem));
  Positions x = model.problem->mesh.rest;
  for (Index i = 0; i < x.rows(); ++i)  // the same smooth deformation on every rank
    x.row(i) += 0.002 * Vector3(std::sin(40 * x(i, 2)), std::cos(30 * x(i, 0)), std::sin(50 * x(i, 1))).transpose();
  const double whole_value = whole.value(x);
  EXPECT_GT(whole_value, 0);
  EXPECT_NEAR(parallel::sum(model.elastic->value(x)), whole_value, 1e-12 * whole_value);
  NodalVectors part_gradient = NodalVectors::Zero(x.rows(), 3), whole_gradient = NodalVectors::Zero(x.rows(), 3);
  model.elastic->add_gradient(x, part_gradient);
  whole.add_gradient(x, whole_gradient);
  parallel::sum(part_gradient.data(), static_cast<std::size_t>(part_gradient.size()));
  EXPECT_LE((part_gradient - whole_gradient).cwiseAbs().maxCoeff(), 1e-12 * whole_gradient.cwiseAbs().maxCoeff());
  // The damping matrix D = a M + b K0 of every rank holds the whole K0: the ranks' parts summed.
  ASSERT_TRUE(model.dynamics && model.dynamics->viscosity);
  std::vector<std::pair<Index, Index>> pairs;
  whole.hessian_pattern(pairs);
  BlockSparseMatrix K0;
  K0.set_pattern(x.rows(), std::move(pairs));
  fem::ElasticEnergy whole_bound(model.problem->mesh.rest, tets, fem::tet_laws(*model.problem));
  whole_bound.bind_pattern(K0);
  whole_bound.add_hessian(model.problem->mesh.rest, K0);
  const BlockSparseMatrix expected = fem::linear_combination(10.0, *model.dynamics->mass, 0.01, K0);
  const BlockSparseMatrix& D = model.dynamics->viscosity->matrix();
  ASSERT_EQ(D.num_blocks(), expected.num_blocks());
  double largest = 0, difference = 0;
  for (Index k = 0; k < D.num_blocks(); ++k) {
    largest = std::max(largest, expected.values()[static_cast<std::size_t>(k)].cwiseAbs().maxCoeff());
    difference = std::max(difference, (D.values()[static_cast<std::size_t>(k)] - expected.values()[static_cast<std::size_t>(k)]).cwiseAbs().maxCoeff());
  }
  EXPECT_GT(largest, 0);
  EXPECT_LE(difference, 1e-12 * largest);
}

// The distributed PETSc solve analyzes again when a rank's part of K has another pattern, and
// solves a new K on the pattern it has. On several ranks it keeps no copy of K's row indices and
// reads the pattern back through its renumbered rows, so a pattern with the same column starts
// and nonzeros but other rows (two couplings swapped between two pairs of unknowns) must still
// count as new: taken as the old one, its values would be added at the old places and the
// solution would be wrong.
TEST(RanksUnderMpirun, APetscSolveOnRanksAnalyzesAgainWhenThePatternOfItsPartChanges) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  constexpr int n = 12;
  // Diagonally dominant, so positive definite: a tridiagonal chain and two longer couplings.
  auto matrix = [&](std::pair<int, int> first, std::pair<int, int> second, double scale) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 4.0 + 0.1 * i);
    auto couple = [&](int a, int b, double value) {
      entries.emplace_back(a, b, value);
      entries.emplace_back(b, a, value);
    };
    for (int i = 0; i + 1 < n; ++i) couple(i, i + 1, -1.0);
    couple(first.first, first.second, -0.5);
    couple(second.first, second.second, -0.25);
    fem::SparseMatrix K(n, n);
    K.setFromTriplets(entries.begin(), entries.end());
    K *= scale;
    K.makeCompressed();
    return K;
  };
  const VectorX b = VectorX::LinSpaced(n, 1.0, 2.0);
  const double share = 1.0 / parallel::size();  // each rank passes its share; PETSc adds them
  auto solve = [&](solver::LinearSolver& linear, const fem::SparseMatrix& whole) {
    fem::SparseMatrix part = whole * share;
    part.makeCompressed();
    EXPECT_TRUE(linear.factorize(part));
    VectorX x;
    EXPECT_TRUE(linear.solve(b, x).success);
    const VectorX expected = MatrixX(whole).ldlt().solve(b);
    EXPECT_LE((x - expected).norm(), 1e-10 * expected.norm()) << "rank " << parallel::rank();
  };
  const auto linear = solver::make_linear_solver({.kind = solver::LinearSolverOptions::Kind::PetscMumps});
  ASSERT_TRUE(linear->adds_ranks_parts());
  const fem::SparseMatrix A = matrix({0, 5}, {2, 9}, 1.0);
  solve(*linear, A);
  solve(*linear, matrix({0, 5}, {2, 9}, 2.0));  // the same pattern, other values
  // (0, 5) and (2, 9) become (2, 5) and (0, 9): every column keeps its number of entries.
  const fem::SparseMatrix swapped = matrix({2, 5}, {0, 9}, 1.0);
  ASSERT_EQ(swapped.nonZeros(), A.nonZeros());
  ASSERT_TRUE(std::equal(A.outerIndexPtr(), A.outerIndexPtr() + n + 1, swapped.outerIndexPtr()));
  solve(*linear, swapped);
  solve(*linear, A);  // and back
}

// GAMG's near-null space on ranks (solver::rigid_body_modes_of_rows): each rank fits the rows it
// holds, and together they are an orthonormal basis of the span one process gets.
TEST(RanksUnderMpirun, EachRankFitsTheRigidBodyModesOfItsRowsAndTogetherTheyAreOneBasis) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  model::Model model = model::build_model(scene::parse_scene(example("hertz-ball"), ""));
  const fem::DofMap& dofs = *model.dofs;
  const fem::State state = dofs.initial_state(0.5);
  const Index n = dofs.num_dofs();
  std::vector<Index> mine;
  for (Index q = 0; q < n; ++q)
    if ((q / 7) % parallel::size() == parallel::rank()) mine.push_back(q);
  const MatrixX rows = solver::rigid_body_modes_of_rows(
      [&](const std::vector<Index>& unknowns) { return fem::rigid_body_motions(dofs, state, unknowns); }, mine);
  ASSERT_EQ(rows.rows(), static_cast<Index>(mine.size()));
  const MatrixX modes = fem::rigid_body_modes(dofs, state);
  ASSERT_EQ(rows.cols(), modes.cols()) << "rank " << parallel::rank();
  ASSERT_GT(modes.cols(), 0);
  MatrixX joined = MatrixX::Zero(n, rows.cols());
  for (std::size_t i = 0; i < mine.size(); ++i) joined.row(mine[i]) = rows.row(static_cast<Index>(i));
  parallel::sum(joined.data(), static_cast<std::size_t>(joined.size()));
  EXPECT_LT((joined.transpose() * joined - MatrixX::Identity(modes.cols(), modes.cols())).norm(), 1e-12);
  EXPECT_LT((modes - joined * (joined.transpose() * modes)).norm(), 1e-10) << "not the span of one process's modes";
}

TEST(RanksUnderMpirun, GatherAllConcatenatesEveryRanksBytesInRankOrder) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  // Rank r gives r + 1 bytes of value r (rank 0 one, rank 1 two): a different length on each.
  const std::vector<char> mine(static_cast<std::size_t>(parallel::rank() + 1), static_cast<char>(parallel::rank()));
  std::vector<char> expected;
  for (int r = 0; r < parallel::size(); ++r) expected.insert(expected.end(), static_cast<std::size_t>(r + 1), static_cast<char>(r));
  EXPECT_EQ(parallel::gather_all(mine), expected);
  EXPECT_EQ(parallel::gather_all({}).size(), 0u);
}

TEST(RanksUnderMpirun, EachRankDetectsThePairsOfItsTetsAndEveryRankEndsWithAllOfThem) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  model::Model model = model::build_model(scene::parse_scene(example("hertz-ball"), ""));
  // The ball's nodes (those of the deformable tets) lowered 0.3 mm into the rigid block.
  fem::State state = model.dofs->initial_state(0.0);
  const Tets& tets = model.problem->mesh.tets;
  std::vector<char> in_ball(static_cast<std::size_t>(state.x.rows()), 0);
  for (Index e = 0; e < tets.rows(); ++e)
    if (!fem::is_rigid_tet(*model.problem, e))
      for (int k = 0; k < 4; ++k) in_ball[static_cast<std::size_t>(tets(e, k))] = 1;
  for (Index i = 0; i < state.x.rows(); ++i)
    if (in_ball[static_cast<std::size_t>(i)]) state.x(i, 2) -= 0.3;
  model.objective->full_gradient(state);  // updates the contact pairs at state.x on every rank
  const contact::CollisionSet& split = model.contact->collisions();
  ASSERT_TRUE(split.is_current(state.x));
  // The model split the detection by the tets' owners (docs/mpi.md)...
  const auto& detects = split.share().detects_tet;
  ASSERT_EQ(detects.size(), model.tet_owner.size());
  for (std::size_t t = 0; t < detects.size(); ++t) ASSERT_EQ(detects[t] != 0, model.tet_owner[t] == parallel::rank()) << t;
  // ...and every rank holds the pairs a whole detection finds, each once, with the same supports.
  contact::CollisionSet whole(split.shared_geometry(), split.method(), split.candidate_cap());
  whole.update(state.x);
  ASSERT_GT(whole.pairs().size(), 20u);
  auto sorted = [](std::vector<std::pair<Index, Index>> pairs) {
    std::sort(pairs.begin(), pairs.end());
    return pairs;
  };
  EXPECT_EQ(sorted(split.pair_indices()), sorted(whole.pair_indices()));
  EXPECT_EQ(split.times().candidates, whole.times().candidates);
  const double energy = contact::contact_energy_value(split, state.x);
  EXPECT_NEAR(energy, contact::contact_energy_value(whole, state.x), 1e-12 * std::abs(energy));
  // Both ranks detected some of them: the contact zone lies across the partition here.
  std::size_t own = 0;
  for (const auto& [f, t] : whole.pair_indices()) own += model.tet_owner[static_cast<std::size_t>(t)] == parallel::rank();
  EXPECT_GT(own, 0u) << "rank " << parallel::rank();
}

TEST(RanksUnderMpirun, RankZeroMeshesEachGeneratedBodyAndTheOtherRanksReceiveItOrItsFailure) {
  if (parallel::launched_size() <= 1) GTEST_SKIP() << "runs under mpirun (Mpi.TheRankHelpersWorkUnderMpirun)";
  parallel::start();
  // The other ranks are given another element size: meshing themselves, they would hold other
  // meshes; receiving rank 0's, every rank holds its mesh to the last bit.
  scene::SceneConfig config = scene::parse_scene(example("hertz-ball"), "");
  scene::set_element_size(config, parallel::is_root() ? 2.0 : 3.0);
  const fem::Problem problem = scene::build_problem(config);
  const std::string mine = mesh::tet_mesh_bytes(problem.mesh);
  const std::vector<char> all = parallel::gather_all(std::vector<char>(mine.begin(), mine.end()));
  ASSERT_EQ(all.size(), mine.size() * static_cast<std::size_t>(parallel::size()));
  for (int r = 0; r < parallel::size(); ++r)
    EXPECT_EQ(std::string(all.begin() + static_cast<long>(r * mine.size()), all.begin() + static_cast<long>((r + 1) * mine.size())), mine)
        << "rank " << r;
  EXPECT_GT(problem.mesh.num_tets(), 0);
  // Rank 0 cannot read its surface file (the other ranks could): every rank ends with rank 0's
  // message, as an input error naming the file.
  const sinew::testing::TempDir data;
  if (!parallel::is_root()) sinew::testing::write_text(data.path() / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  nlohmann::json surfaces = nlohmann::json::parse(R"({
    "units": "mm, mN, kPa",
    "materials": {"gel": {"law": "neo-hookean", "mu": 1.0, "lambda": 10.0}},
    "bodies": [{"name": "block",
      "mesh": {"surfaces": {"element_size": 0.5, "surfaces": {"cube": {"file": "cube.stl"}},
                            "parts": [{"region": "box", "solid": {"surface": "cube"}}]}},
      "regions": {"*": {"material": "gel"}}}]
  })");
  surfaces["data_dir"] = data.path().string();
  try {
    scene::build_problem(scene::parse_scene(surfaces, data.path().string()));
    ADD_FAILURE() << "rank " << parallel::rank() << ": meshed";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cube.stl")) << "rank " << parallel::rank();
    EXPECT_THAT(e.what(), HasSubstr("file not found")) << "rank " << parallel::rank();
  }
}

TEST_F(Mpi, TheRankHelpersWorkUnderMpirun) {
  // This test program itself on 2 ranks, running only the RanksUnderMpirun tests above.
  const CommandResult result = run_program(fs::read_symlink("/proc/self/exe").string(), {"--gtest_filter=RanksUnderMpirun.*", "--gtest_color=no"}, directory,
                                           with_timeout(mpirun(2)));
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  // Each of the 2 ranks ran the nine tests and none skipped.
  std::size_t passed = 0;
  for (std::size_t at = result.out.find("[  PASSED  ] 9 tests"); at != std::string::npos;
       at = result.out.find("[  PASSED  ] 9 tests", at + 1))
    ++passed;
  EXPECT_EQ(passed, 2u) << result.out;
  EXPECT_EQ(result.out.find("SKIPPED"), std::string::npos) << result.out;
}

}  // namespace
}  // namespace sinew::app_test
