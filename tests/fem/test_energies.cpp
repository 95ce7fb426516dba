#include <gtest/gtest.h>

#include <random>

#include <Eigen/Eigenvalues>

#include "sinew/core/error.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "support/fd_check.hpp"
#include "support/flat_positions.hpp"
#include "support/problem_builder.hpp"

using namespace sinew;
namespace st = sinew::testing;
using st::flatten;
using st::unflatten;

namespace {

Positions perturbed(const Positions& X, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  Positions x = X;
  for (Index i = 0; i < x.rows(); ++i)
    for (int k = 0; k < 3; ++k) x(i, k) += u(rng);
  return x;
}


material::MaterialPtr fibered_veronda() {
  material::MaterialSpec spec;
  spec.base = material::VerondaWestmannParams{0.5, 1.5, 3.0};
  spec.fiber = material::FiberParams{0.4, 2.0, Vector3(1, 1, 0)};
  return material::make_material(spec);
}

}  // namespace

class ElasticEnergyFD : public ::testing::TestWithParam<int> {};

TEST_P(ElasticEnergyFD, GradientAndHessianMatchFiniteDifferences) {
  const auto law = GetParam() == 0 ? st::mooney_rivlin() : fibered_veronda();
  auto p = st::box_problem(2, 2, 1, Vector3(0, 0, 0), Vector3(1, 1, 0.5), law);
  fem::ElasticEnergy energy(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  const Positions x = perturbed(p.mesh.rest * 1.1, 0.05, 7);
  ASSERT_TRUE(energy.is_valid(x));

  NodalVectors g = NodalVectors::Zero(x.rows(), 3);
  energy.add_gradient(x, g);
  const VectorX fd_g = st::fd_gradient([&](const VectorX& v) { return energy.value(unflatten(v)); }, flatten(x), 1e-6);
  EXPECT_LT(st::relative_error(flatten(g), fd_g), 1e-7);

  std::vector<std::pair<Index, Index>> pairs;
  energy.hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(static_cast<Index>(x.rows()), pairs);
  energy.bind_pattern(H);
  energy.add_hessian(x, H);
  const MatrixX fd_H = st::fd_jacobian(
      [&](const VectorX& v) {
        NodalVectors gv = NodalVectors::Zero(x.rows(), 3);
        energy.add_gradient(unflatten(v), gv);
        return flatten(gv);
      },
      flatten(x), 1e-6);
  const MatrixX dense = H.to_dense();
  EXPECT_LT(st::relative_error(dense, fd_H), 1e-7);
  EXPECT_LT((dense - dense.transpose()).norm(), 1e-10 * dense.norm());
}

INSTANTIATE_TEST_SUITE_P(Laws, ElasticEnergyFD, ::testing::Values(0, 1));

TEST(ElasticEnergy, RestIsStressFreeAndRigidMotionsCostNothing) {
  auto p = st::box_problem(2, 1, 1, Vector3(0, 0, 0), Vector3(2, 1, 1), st::mooney_rivlin());
  fem::ElasticEnergy energy(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  EXPECT_NEAR(energy.value(p.mesh.rest), 0, 1e-12);
  const Matrix3 R = Eigen::AngleAxisd(0.7, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  Positions moved = (p.mesh.rest * R.transpose()).rowwise() + Eigen::RowVector3d(3, -1, 2);
  EXPECT_NEAR(energy.value(moved), 0, 1e-11);
  NodalVectors g = NodalVectors::Zero(moved.rows(), 3);
  energy.add_gradient(moved, g);
  EXPECT_LT(g.norm(), 1e-11);
}

TEST(ElasticEnergy, InvertedElementIsIllegal) {
  auto p = st::box_problem(1, 1, 1, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin());
  fem::ElasticEnergy energy(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  Positions x = p.mesh.rest;
  x.col(2) *= -1;  // mirror: every tet inverted
  EXPECT_FALSE(energy.is_valid(x));
  EXPECT_EQ(energy.value(x), std::numeric_limits<double>::infinity());
}

TEST(ElasticEnergy, TetMeasuresFollowEachTetWhenRigidTetsComeFirst) {
  // The energy keeps the rest shapes of its deformable tets only; the measures must still read
  // each tet's own shape. Every other tet rigid, the first among them, and a stretch of 1.2 in x:
  // J = 1.2 and a positive stress in every deformable tet, J = 1 and no stress in the rigid ones.
  auto p = st::box_problem(2, 1, 1, Vector3(0, 0, 0), Vector3(2, 1, 1), st::mooney_rivlin());
  std::vector<material::MaterialPtr> materials = st::tet_materials(p);
  for (std::size_t t = 0; t < materials.size(); t += 2) materials[t] = nullptr;
  // Rest shapes of different sizes, so that a tet read with another's shape would show.
  p.mesh.rest.col(1) *= 1.0 + 0.1 * p.mesh.rest.col(0).array().square().matrix().norm();
  p.mesh.rest(0, 2) -= 0.05;
  fem::ElasticEnergy energy(p.mesh.rest, p.mesh.tets, materials);
  ASSERT_EQ(energy.deformable_tets().size(), energy.rest_shapes().size());
  Positions x = p.mesh.rest;
  x.col(0) *= 1.2;
  const fem::TetMeasures m = fem::compute_tet_measures(x, energy);
  ASSERT_EQ(m.J.size(), p.mesh.tets.rows());
  for (Index t = 0; t < p.mesh.tets.rows(); ++t) {
    if (materials[static_cast<std::size_t>(t)]) {
      EXPECT_NEAR(m.J[t], 1.2, 1e-12) << "tet " << t;
      EXPECT_GT(m.von_mises[t], 0) << "tet " << t;
    } else {
      EXPECT_EQ(m.J[t], 1.0) << "tet " << t;
      EXPECT_EQ(m.von_mises[t], 0.0) << "tet " << t;
    }
  }
}

// bind_pattern puts every tet block where the pattern has it, and refuses a pattern without
// the tets' blocks.
TEST(ElasticEnergy, BindingFindsEveryTetBlockAndRefusesAPatternWithoutThem) {
  auto p = st::box_problem(6, 5, 4, Vector3(0, 0, 0), Vector3(1, 1, 0.5), st::mooney_rivlin());
  fem::ElasticEnergy energy(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  std::vector<std::pair<Index, Index>> pairs;
  energy.hessian_pattern(pairs);
  const Index num_nodes = static_cast<Index>(p.mesh.rest.rows());
  BlockSparseMatrix whole;
  whole.set_pattern(num_nodes, pairs);
  energy.bind_pattern(whole);
  // Blocks bound to the wrong places would break the Hessian's symmetry or its null space of
  // rigid translations (each tet's blocks sum to zero along a row of nodes).
  const Positions x = perturbed(p.mesh.rest, 0.02, 3);
  energy.add_hessian(x, whole);
  const MatrixX dense = whole.to_dense();
  EXPECT_GT(dense.norm(), 0.0);
  EXPECT_LT((dense - dense.transpose()).norm(), 1e-10 * dense.norm());
  for (int k = 0; k < 3; ++k) {
    VectorX translation = VectorX::Zero(dense.cols());
    for (Index a = 0; a < num_nodes; ++a) translation[3 * a + k] = 1.0;
    EXPECT_LT((dense * translation).norm(), 1e-10 * dense.norm()) << "direction " << k;
  }
  // Without the blocks of the last node's pairs: refused with the reason.
  std::vector<std::pair<Index, Index>> partial;
  for (const auto& [a, b] : pairs)
    if (a != num_nodes - 1 && b != num_nodes - 1) partial.emplace_back(a, b);
  BlockSparseMatrix lacking;
  lacking.set_pattern(num_nodes, partial);
  EXPECT_THAT([&] { energy.bind_pattern(lacking); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("lacks a tet block")));
}

// When the pattern grows (new contact pairs), the tets' blocks are rebound by the matrix's map
// of moved blocks; the Hessian is the one a fresh binding gives.
TEST(ElasticEnergy, RebindingAfterTheBlocksMovedGivesTheFreshHessian) {
  auto p = st::box_problem(4, 3, 3, Vector3(0, 0, 0), Vector3(1, 1, 0.5), st::mooney_rivlin());
  const Index num_nodes = static_cast<Index>(p.mesh.rest.rows());
  fem::ElasticEnergy moved(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  fem::ElasticEnergy fresh(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  std::vector<std::pair<Index, Index>> pairs;
  moved.hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(num_nodes, pairs);
  moved.bind_pattern(H);
  for (Index a = 0; a + 7 < num_nodes; a += 5) pairs.emplace_back(a, a + 7);  // like contact pairs
  H.set_pattern(num_nodes, pairs);
  ASSERT_FALSE(H.moved_block_index().empty());
  moved.bind_pattern(H);
  const Positions x = perturbed(p.mesh.rest, 0.02, 5);
  moved.add_hessian(x, H);
  const MatrixX by_map = H.to_dense();

  BlockSparseMatrix G;
  G.set_pattern(num_nodes, pairs);
  fresh.bind_pattern(G);
  fresh.add_hessian(x, G);
  EXPECT_GT(by_map.norm(), 0.0);
  EXPECT_EQ(by_map, G.to_dense());
}

// Shares of the tets (MPI ranks, docs/mpi.md): each keeps only the laws and rest shapes of the
// tets it evaluates; two complementary shares add up to the whole term, and each lists the whole
// term's pattern for a Hessian summed over the ranks.
TEST(ElasticEnergy, ComplementarySharesAddUpToTheWholeTerm) {
  auto p = st::box_problem(4, 3, 2, Vector3(0, 0, 0), Vector3(1, 1, 0.5), st::mooney_rivlin());
  std::vector<material::MaterialPtr> materials = st::tet_materials(p);
  for (std::size_t t = 0; t < materials.size(); t += 5) materials[t] = nullptr;  // some rigid tets
  const auto num_tets = static_cast<std::size_t>(p.mesh.tets.rows());
  const Index num_nodes = static_cast<Index>(p.mesh.rest.rows());
  std::vector<bool> first_half(num_tets), second_half(num_tets);
  for (std::size_t t = 0; t < num_tets; ++t) (t < num_tets / 2 ? first_half : second_half)[t] = true;
  const fem::ElasticEnergy whole(p.mesh.rest, p.mesh.tets, materials);
  fem::ElasticEnergy a(p.mesh.rest, p.mesh.tets, materials, {.evaluated_tets = first_half});
  fem::ElasticEnergy b(p.mesh.rest, p.mesh.tets, materials, {.evaluated_tets = second_half});
  ASSERT_GT(a.deformable_tets().size(), 0u);
  ASSERT_GT(b.deformable_tets().size(), 0u);
  EXPECT_EQ(a.deformable_tets().size() + b.deformable_tets().size(), whole.deformable_tets().size());
  EXPECT_EQ(a.rest_shapes().size(), a.deformable_tets().size());
  EXPECT_EQ(a.materials().size(), a.deformable_tets().size());
  for (const Index t : a.deformable_tets()) EXPECT_TRUE(first_half[static_cast<std::size_t>(t)] && materials[static_cast<std::size_t>(t)]);

  const Positions x = perturbed(p.mesh.rest, 0.03, 7);
  EXPECT_NEAR(a.value(x) + b.value(x), whole.value(x), 1e-12 * whole.value(x));
  NodalVectors ga = NodalVectors::Zero(num_nodes, 3), gb = ga, gw = ga;
  a.add_gradient(x, ga);
  b.add_gradient(x, gb);
  whole.add_gradient(x, gw);
  EXPECT_LE((ga + gb - gw).cwiseAbs().maxCoeff(), 1e-12 * gw.cwiseAbs().maxCoeff());

  // Each share's own pattern is part of the whole; its whole pattern is the whole term's.
  std::vector<std::pair<Index, Index>> whole_pairs, own_pairs, listed_whole;
  whole.hessian_pattern(whole_pairs);
  a.hessian_pattern(own_pairs);
  a.whole_hessian_pattern(listed_whole);
  EXPECT_LT(own_pairs.size(), whole_pairs.size());
  EXPECT_EQ(listed_whole, whole_pairs);
  BlockSparseMatrix H, W;
  H.set_pattern(num_nodes, whole_pairs);
  W.set_pattern(num_nodes, whole_pairs);
  a.bind_pattern(H);
  b.bind_pattern(H);
  a.add_hessian(x, H);
  b.add_hessian(x, H);
  fem::ElasticEnergy whole_bound(p.mesh.rest, p.mesh.tets, materials);
  whole_bound.bind_pattern(W);
  whole_bound.add_hessian(x, W);
  const MatrixX sum = H.to_dense(), expected = W.to_dense();
  EXPECT_GT(expected.norm(), 0.0);
  EXPECT_LE((sum - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());

  // The measures of a share: its own tets, J = 1 and no stress elsewhere.
  const fem::TetMeasures m = fem::compute_tet_measures(x, a), mw = fem::compute_tet_measures(x, whole);
  for (std::size_t t = 0; t < num_tets; ++t) {
    const bool own = first_half[t] && materials[t];
    EXPECT_EQ(m.J[static_cast<Index>(t)], own ? mw.J[static_cast<Index>(t)] : 1.0) << t;
    EXPECT_EQ(m.von_mises[static_cast<Index>(t)], own ? mw.von_mises[static_cast<Index>(t)] : 0.0) << t;
  }
  EXPECT_THAT([&] { fem::ElasticEnergy(p.mesh.rest, p.mesh.tets, materials, {.evaluated_tets = {true, false}}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("one evaluated-tet flag per tet")));
}

// add_hessian computes the tets' Hessians 4,096 at a time. A mesh of three such chunks gives the
// Hessian that shares of under one chunk each add up to (each computed in a single chunk), and
// the Hessian agrees with central differences of the gradient, which is assembled whole.
TEST(ElasticEnergy, HessiansComputedInChunksAddUpAcrossTheChunkBoundaries) {
  auto p = st::box_problem(12, 12, 10, Vector3(0, 0, 0), Vector3(1, 1, 0.8), st::mooney_rivlin());
  const auto num_tets = static_cast<std::size_t>(p.mesh.tets.rows());
  ASSERT_GT(num_tets, 2u * 4096u);
  const Index num_nodes = static_cast<Index>(p.mesh.rest.rows());
  fem::ElasticEnergy whole(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  std::vector<std::pair<Index, Index>> pairs;
  whole.hessian_pattern(pairs);
  BlockSparseMatrix W, S;
  W.set_pattern(num_nodes, pairs);
  S.set_pattern(num_nodes, pairs);
  whole.bind_pattern(W);
  const Positions x = perturbed(p.mesh.rest, 0.01, 11);
  whole.add_hessian(x, W);

  // Three interleaved shares of under 4,096 tets each.
  for (std::size_t share = 0; share < 3; ++share) {
    std::vector<bool> mine(num_tets);
    for (std::size_t t = share; t < num_tets; t += 3) mine[t] = true;
    fem::ElasticEnergy part(p.mesh.rest, p.mesh.tets, st::tet_materials(p), {.evaluated_tets = mine});
    ASSERT_LT(part.deformable_tets().size(), 4096u);
    part.bind_pattern(S);
    part.add_hessian(x, S);
  }
  double largest = 0, difference = 0;
  for (std::size_t k = 0; k < W.values().size(); ++k) {
    largest = std::max(largest, W.values()[k].cwiseAbs().maxCoeff());
    difference = std::max(difference, (W.values()[k] - S.values()[k]).cwiseAbs().maxCoeff());
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(difference, 1e-12 * largest);

  // H v against (g(x + h v) - g(x - h v)) / 2h for a random v.
  const VectorX v = flatten(perturbed(Positions::Zero(num_nodes, 3), 1.0, 13));
  const double h = 1e-6;
  NodalVectors plus = NodalVectors::Zero(num_nodes, 3), minus = plus;
  whole.add_gradient(x + h * unflatten(v), plus);
  whole.add_gradient(x - h * unflatten(v), minus);
  const VectorX difference_quotient = (flatten(plus) - flatten(minus)) / (2 * h);
  const VectorX product = W.multiply(v);
  EXPECT_LE((product - difference_quotient).norm(), 1e-6 * product.norm());
}

TEST(ElasticEnergy, ProjectedHessianIsPositiveSemiDefinite) {
  auto p = st::box_problem(2, 1, 1, Vector3(0, 0, 0), Vector3(2, 1, 1), st::mooney_rivlin());
  fem::ElasticEnergy energy(p.mesh.rest, p.mesh.tets, st::tet_materials(p), {.project_hessians = true});
  Positions x = p.mesh.rest;
  x.col(0) *= 0.6;  // strong compression: the exact Hessian is indefinite here
  x = perturbed(x, 0.05, 3);
  std::vector<std::pair<Index, Index>> pairs;
  energy.hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(static_cast<Index>(x.rows()), pairs);
  energy.bind_pattern(H);
  energy.add_hessian(x, H);
  Eigen::SelfAdjointEigenSolver<MatrixX> eig(H.to_dense());
  EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-10 * eig.eigenvalues().cwiseAbs().maxCoeff());
}

TEST(ExternalForceEnergy, GravityUsesLumpedMassAndAmplitude) {
  auto p = st::box_problem(2, 2, 2, Vector3(0, 0, 0), Vector3(1, 2, 3), st::mooney_rivlin(), 5.0);
  const VectorX m = fem::lumped_masses(p.mesh.rest, p.mesh.tets, p.mesh.region, p.region_density);
  EXPECT_NEAR(m.sum(), 5.0 * 6.0, 1e-12);
  fem::ExternalForceEnergy ext(m, Vector3(0, 0, -10), {}, {}, p.mesh.num_nodes());
  ext.set_load_parameter(0.5);
  EXPECT_NEAR(ext.forces().col(2).sum(), -0.5 * 10 * 30, 1e-10);
  // E = -f.x: gradient is -f
  NodalVectors g = NodalVectors::Zero(p.mesh.num_nodes(), 3);
  ext.add_gradient(p.mesh.rest, g);
  EXPECT_LT((g + ext.forces()).norm(), 1e-14);
  EXPECT_NEAR(ext.value(p.mesh.rest), -(ext.forces().array() * p.mesh.rest.array()).sum(), 1e-12);
}

TEST(ExternalForceEnergy, NodalForcesGoInEqualOrGivenShares) {
  auto p = st::box_problem(1, 1, 1, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin(), 1.0);
  const Index n = p.mesh.num_nodes();
  fem::NodalForce equal{"equal", {0, 1}, Vector3(0, 0, 2), {}, {}};
  fem::NodalForce shared{"shared", {2, 3}, Vector3(4, 0, 0), {}, {0.25, 0.75}};
  fem::ExternalForceEnergy ext(VectorX::Zero(n), Vector3::Zero(), {}, {equal, shared}, n);
  ext.set_load_parameter(0.5);  // the default amplitude is the ramp
  EXPECT_EQ(Vector3(ext.forces().row(0)), Vector3(0, 0, 0.5));
  EXPECT_EQ(Vector3(ext.forces().row(1)), Vector3(0, 0, 0.5));
  EXPECT_EQ(Vector3(ext.forces().row(2)), Vector3(0.5, 0, 0));
  EXPECT_EQ(Vector3(ext.forces().row(3)), Vector3(1.5, 0, 0));
  EXPECT_EQ(ext.forces().bottomRows(n - 4).norm(), 0);
}
