#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Eigenvalues>

#include "sinew/core/error.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/mass_matrix.hpp"
#include "sinew/fem/stable_time_step.hpp"
#include "support/problem_builder.hpp"

using namespace sinew;
namespace st = sinew::testing;

namespace {

material::MaterialPtr neo_hookean(double mu, double lambda) {
  material::MaterialSpec spec;
  spec.base = material::NeoHookeanParams{mu, lambda};
  return material::make_material(spec);
}

/// lambda + 2 mu = kappa + 4/3 mu: the P-wave (constrained) modulus at F = I (stress units).
double p_wave_modulus(const material::Material& law) {
  return law.initial_bulk_modulus() + 4.0 / 3.0 * law.initial_shear_modulus();
}

/// One regular tet of edge length h, positively oriented.
std::pair<Positions, Tets> regular_tet(double h) {
  Positions X(4, 3);
  X << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;  // edge 2 sqrt(2)
  X *= h / (2 * std::sqrt(2.0));
  Tets T(1, 4);
  T << 0, 1, 2, 3;
  if (mesh::signed_volume(X, T, 0) < 0) std::swap(T(0, 2), T(0, 3));
  return {X, T};
}

/// True highest angular frequency of the assembled system K u = omega^2 M u, K the elastic
/// Hessian at rest (tets with a law) and M the lumped mass of every tet (dense, small meshes only).
double assembled_omega_max(const Positions& rest, const Tets& tets, const std::vector<material::MaterialPtr>& laws,
                           const VectorX& tet_density) {
  fem::ElasticEnergy energy(rest, tets, laws);
  std::vector<std::pair<Index, Index>> pairs;
  energy.hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(static_cast<Index>(rest.rows()), pairs);
  energy.bind_pattern(H);
  energy.add_hessian(rest, H);
  const MatrixX K = H.to_dense();

  IndexVector region(tets.rows());  // one region per tet carries the per-tet density
  std::vector<double> density(static_cast<std::size_t>(tets.rows()));
  for (Index t = 0; t < tets.rows(); ++t) {
    region[t] = t;
    density[static_cast<std::size_t>(t)] = tet_density[t];
  }
  const VectorX m = MatrixX(fem::mass_matrix(rest, tets, region, density, fem::MassKind::Lumped)).diagonal();
  VectorX inv_sqrt_m(K.rows());
  for (Index a = 0; a < m.size(); ++a) inv_sqrt_m.segment<3>(3 * a).setConstant(1.0 / std::sqrt(m[a]));
  const MatrixX A = inv_sqrt_m.asDiagonal() * K * inv_sqrt_m.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<MatrixX> eig(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  return std::sqrt(eig.eigenvalues().maxCoeff());
}

std::vector<material::MaterialPtr> laws_of(const mesh::TetMesh& m, const std::vector<material::MaterialPtr>& region) {
  std::vector<material::MaterialPtr> out(static_cast<std::size_t>(m.num_tets()));
  for (Index t = 0; t < m.num_tets(); ++t) out[t] = region[static_cast<std::size_t>(m.region[t])];
  return out;
}

VectorX densities_of(const mesh::TetMesh& m, const std::vector<double>& region) {
  VectorX out(m.num_tets());
  for (Index t = 0; t < m.num_tets(); ++t) out[t] = region[static_cast<std::size_t>(m.region[t])];
  return out;
}

/// 3 x 2 x 2 box, jiggled, two regions (x > 1.5: second law and density).
mesh::TetMesh jiggled_two_region_box(unsigned seed) {
  auto m = st::box_mesh(3, 2, 2, Vector3(0, 0, 0), Vector3(3, 1.5, 1));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.08, 0.08);
  for (Index a = 0; a < m.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k) m.rest(a, k) += u(rng);
  for (Index t = 0; t < m.num_tets(); ++t) {
    double cx = 0;
    for (int i = 0; i < 4; ++i) cx += m.rest(m.tets(t, i), 0) / 4.0;
    m.region[t] = cx > 1.5 ? 1 : 0;
  }
  m.region_names = {"soft", "stiff"};
  return m;
}

}  // namespace

class RegularTet : public ::testing::TestWithParam<int> {};

TEST_P(RegularTet, BoundIsExactForOneTetAndAboveTheWaveSpeedEstimate) {
  const auto law = GetParam() == 0 ? neo_hookean(3.0, 10.0) : st::mooney_rivlin(1.0, 0.3, 2.0);
  const double h = 0.2, rho = 1.5;
  const auto [X, T] = regular_tet(h);
  const std::vector<material::MaterialPtr> laws{law};
  const VectorX density = VectorX::Constant(1, rho);
  const auto step = fem::critical_time_step(X, T, laws, density);
  EXPECT_EQ(step.critical_tet, 0);
  EXPECT_DOUBLE_EQ(step.dt, 2.0 / step.omega_max);

  // Irons' bound is the element eigenvalue itself when the mesh is one element.
  const double exact = assembled_omega_max(X, T, laws, density);
  EXPECT_NEAR(step.omega_max, exact, 1e-10 * exact);

  // 1D estimate: a bar element of length h with lumped masses has omega = 2 c / h. The tet is
  // stiffer than a bar of its edge length (its altitude h sqrt(2/3) is shorter and the modes
  // couple), so omega_max >= 2 c / h, of the same order of magnitude.
  const double c = std::sqrt(p_wave_modulus(*law) / rho);
  const double omega_1d = 2 * c / h;
  EXPECT_GE(step.omega_max, omega_1d);
  EXPECT_LE(step.omega_max, 3 * omega_1d);  // 3 / sqrt(2) for both laws here
  EXPECT_LE(step.dt, h / c);  // the CFL-like step h / c is not stable for the tet
}

INSTANTIATE_TEST_SUITE_P(Laws, RegularTet, ::testing::Values(0, 1),
                         [](const auto& info) { return info.param == 0 ? "NeoHookean" : "MooneyRivlin"; });

TEST(CriticalTimeStep, BoundsTheAssembledLumpedSystemFromAboveWithinAFactorOfTwo) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto m = jiggled_two_region_box(seed);
    const auto laws = laws_of(m, {st::mooney_rivlin(1.0, 0.3, 2.0), neo_hookean(4.0, 20.0)});
    const VectorX density = densities_of(m, {1.0, 2.5});
    const auto step = fem::critical_time_step(m.rest, m.tets, laws, density);
    const double exact = assembled_omega_max(m.rest, m.tets, laws, density);
    EXPECT_GE(step.omega_max, exact * (1 - 1e-12)) << "seed " << seed;
    EXPECT_LE(step.omega_max, 2.0 * exact) << "seed " << seed;
    ASSERT_GE(step.critical_tet, 0);
    ASSERT_LT(step.critical_tet, m.num_tets());
    // the critical tet alone gives the same bound
    Tets one = m.tets.row(step.critical_tet);
    const auto alone = fem::critical_time_step(m.rest, one, {laws[step.critical_tet]},
                                               VectorX::Constant(1, density[step.critical_tet]));
    EXPECT_DOUBLE_EQ(alone.omega_max, step.omega_max);
  }
}

TEST(CriticalTimeStep, ScalesWithSquareRootOfDensityAndInverseSquareRootOfStiffness) {
  const auto m = jiggled_two_region_box(5);
  const auto nh = [&](double scale) {
    return laws_of(m, {neo_hookean(scale * 1.0, scale * 5.0), neo_hookean(scale * 2.0, scale * 3.0)});
  };
  const VectorX density = densities_of(m, {1.0, 1.3});
  const auto base = fem::critical_time_step(m.rest, m.tets, nh(1.0), density);
  const auto heavy = fem::critical_time_step(m.rest, m.tets, nh(1.0), 4.0 * density);
  const auto stiff = fem::critical_time_step(m.rest, m.tets, nh(9.0), density);  // E x 9 at fixed nu
  EXPECT_NEAR(heavy.dt, 2.0 * base.dt, 1e-12 * base.dt);
  EXPECT_NEAR(stiff.dt, base.dt / 3.0, 1e-12 * base.dt);
  EXPECT_EQ(heavy.critical_tet, base.critical_tet);
  EXPECT_EQ(stiff.critical_tet, base.critical_tet);
}

TEST(CriticalTimeStep, TheSmallestTetIsCriticalAndDtScalesWithSize) {
  const auto [X1, T1] = regular_tet(1.0);
  Positions X(8, 3);
  X.topRows(4) = X1;
  X.bottomRows(4) = (0.5 * X1).rowwise() + Eigen::RowVector3d(5, 0, 0);  // half size, elsewhere
  Tets T(2, 4);
  T.row(0) = T1.row(0);
  T.row(1) = T1.row(0).array() + 4;
  const auto law = neo_hookean(1.0, 2.0);
  const auto both = fem::critical_time_step(X, T, {law, law}, VectorX::Ones(2));
  const auto big = fem::critical_time_step(X1, T1, {law}, VectorX::Ones(1));
  EXPECT_EQ(both.critical_tet, 1);
  EXPECT_NEAR(both.dt, 0.5 * big.dt, 1e-12 * big.dt);
}

TEST(CriticalTimeStep, RigidTetsAreSkipped) {
  const auto m = jiggled_two_region_box(7);
  // region 1 rigid with zero density: no error, no contribution
  auto laws = laws_of(m, {st::mooney_rivlin(), nullptr});
  const VectorX density = densities_of(m, {1.0, 0.0});
  const auto step = fem::critical_time_step(m.rest, m.tets, laws, density);
  ASSERT_GE(step.critical_tet, 0);
  EXPECT_EQ(m.region[step.critical_tet], 0);

  // same as the elastic tets alone
  std::vector<Index> elastic;
  for (Index t = 0; t < m.num_tets(); ++t)
    if (m.region[t] == 0) elastic.push_back(t);
  Tets sub(static_cast<Index>(elastic.size()), 4);
  std::vector<material::MaterialPtr> sub_laws;
  for (std::size_t s = 0; s < elastic.size(); ++s) {
    sub.row(static_cast<Index>(s)) = m.tets.row(elastic[s]);
    sub_laws.push_back(laws[elastic[s]]);
  }
  const auto alone = fem::critical_time_step(m.rest, sub, sub_laws, VectorX::Ones(sub.rows()));
  EXPECT_EQ(alone.dt, step.dt);
  EXPECT_EQ(elastic[static_cast<std::size_t>(alone.critical_tet)], step.critical_tet);

  // a very light rigid region would dominate if it were counted
  const auto light = fem::critical_time_step(m.rest, m.tets, laws, densities_of(m, {1.0, 1e-12}));
  EXPECT_EQ(light.dt, step.dt);

  // nothing elastic: nothing limits the step
  const std::vector<material::MaterialPtr> none(static_cast<std::size_t>(m.num_tets()));
  const auto rigid = fem::critical_time_step(m.rest, m.tets, none, VectorX::Zero(m.num_tets()));
  EXPECT_EQ(rigid.dt, std::numeric_limits<double>::infinity());
  EXPECT_EQ(rigid.critical_tet, -1);
  EXPECT_EQ(rigid.omega_max, 0.0);
}

TEST(CriticalTimeStep, ElasticTetWithoutMassIsAnInputError) {
  const auto m = jiggled_two_region_box(9);
  const auto laws = laws_of(m, {st::mooney_rivlin(), st::mooney_rivlin()});
  VectorX density = VectorX::Ones(m.num_tets());
  density[3] = 0;
  try {
    fem::critical_time_step(m.rest, m.tets, laws, density);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("elastic tet 3 has density 0"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("explicit time integration needs a finite density > 0"));
  }
  density[3] = -1;
  EXPECT_THROW(fem::critical_time_step(m.rest, m.tets, laws, density), InputError);
  density[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(fem::critical_time_step(m.rest, m.tets, laws, density), InputError);
  // sizes must agree
  EXPECT_THROW(fem::critical_time_step(m.rest, m.tets, laws, VectorX::Ones(m.num_tets() - 1)), Error);
}
