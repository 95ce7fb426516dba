#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sinew/core/error.hpp"
#include "sinew/fem/dof_map.hpp"
#include "sinew/fem/hessian_reduction.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "sinew/fem/reactions.hpp"
#include "support/fd_check.hpp"
#include "support/problem_builder.hpp"

using namespace sinew;
namespace st = sinew::testing;

namespace {

/// A box [0,2]x[0,1]x[0,1]: tets with centroid x > 1.5 form a rigid region; the x = 0 face is
/// held in its plane, the edge x = 0, y = 0 also in y = 0, and node 0 is prescribed.
fem::Problem mixed_problem(fem::RigidBody::Kind rigid_kind) {
  auto p = st::box_problem(4, 2, 2, Vector3(0, 0, 0), Vector3(2, 1, 1), st::mooney_rivlin(), 1.0);
  fem::RigidBody& body = st::add_rigid_region(p, "bone", rigid_kind, 3.0, [](const Vector3& c) { return c.x() > 1.5; });
  body.motion.translation = Vector3(0.1, 0.2, 0);
  body.motion.angle = 0.3;
  body.motion.axis = Vector3(0, 1, 1);
  p.planar.push_back({"x0", st::nodes_on_plane(p.mesh, 0, 0.0), Vector3(2, 0, 0), 0.05, {}});
  std::vector<Index> edge;
  for (Index a : st::nodes_on_plane(p.mesh, 0, 0.0))
    if (p.mesh.rest(a, 1) == 0.0) edge.push_back(a);
  p.planar.push_back({"y0", edge, Vector3(0, 1, 0), 0.0, {}});
  p.prescribed.push_back({"pin", {0}, fem::RigidMotion{}});
  return p;
}

struct Fixture {
  fem::Problem problem;
  std::unique_ptr<fem::DofMap> dofs;
  std::unique_ptr<fem::ElasticEnergy> elastic;
  std::unique_ptr<fem::ExternalForceEnergy> external;

  explicit Fixture(fem::RigidBody::Kind kind) : problem(mixed_problem(kind)) {
    dofs = std::make_unique<fem::DofMap>(problem);
    elastic = std::make_unique<fem::ElasticEnergy>(problem.mesh.rest, problem.mesh.tets, st::tet_materials(problem));
    external = std::make_unique<fem::ExternalForceEnergy>(
        fem::lumped_masses(problem.mesh.rest, problem.mesh.tets, problem.mesh.region, problem.region_density),
        Vector3(0, 0, -1), fem::Amplitude{}, std::vector<fem::NodalForce>{}, problem.mesh.num_nodes());
  }
  double energy(const fem::State& s) const { return elastic->value(s.x) + external->value(s.x); }
  NodalVectors gradient(const fem::State& s) const {
    NodalVectors g = NodalVectors::Zero(s.x.rows(), 3);
    elastic->add_gradient(s.x, g);
    external->add_gradient(s.x, g);
    return g;
  }
};

/// A non-equilibrium state: free DOFs perturbed randomly, the rigid body moved and turned.
fem::State scrambled(const fem::DofMap& dofs, double lambda) {
  fem::State s = dofs.initial_state(lambda);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  VectorX dq(dofs.num_dofs());
  for (Index i = 0; i < dq.size(); ++i) dq[i] = u(rng);
  return dofs.apply_step(s, dq, 1.0);
}

}  // namespace

TEST(Problem, ATetsLawIsItsOwnOrItsRegionsAndARigidTetHasNone) {
  fem::Problem p = mixed_problem(fem::RigidBody::Kind::Prescribed);
  Index rigid = -1, soft = -1;
  for (Index t = 0; t < p.mesh.num_tets(); ++t) (p.region_material[p.mesh.region[t]] ? soft : rigid) = t;
  ASSERT_GE(rigid, 0);
  ASSERT_GE(soft, 0);
  const material::MaterialPtr own = st::mooney_rivlin();
  p.element_material[soft] = own;
  p.element_material[rigid] = own;  // a law of its own makes a tet of a rigid region deformable
  const std::vector<material::MaterialPtr> laws = fem::tet_laws(p);
  ASSERT_EQ(laws.size(), static_cast<std::size_t>(p.mesh.num_tets()));
  for (Index t = 0; t < p.mesh.num_tets(); ++t) {
    const auto it = p.element_material.find(t);
    const material::MaterialPtr expected = it != p.element_material.end() ? it->second : p.region_material[p.mesh.region[t]];
    EXPECT_EQ(laws[static_cast<std::size_t>(t)], expected) << "tet " << t;
    EXPECT_EQ(fem::is_rigid_tet(p, t), expected == nullptr) << "tet " << t;
  }
  EXPECT_FALSE(fem::is_rigid_tet(p, rigid));
  p.element_material.erase(rigid);
  EXPECT_TRUE(fem::is_rigid_tet(p, rigid));
}

TEST(DofMap, CountsDegreesOfFreedom) {
  Fixture f(fem::RigidBody::Kind::Free);
  const auto& p = f.problem;
  int free = 0, planar1 = 0, planar2 = 0, rigid = 0;
  for (Index a = 0; a < p.mesh.num_nodes(); ++a) {
    switch (f.dofs->kind(a)) {
      case fem::DofMap::NodeKind::Free: ++free; break;
      case fem::DofMap::NodeKind::Planar: (p.mesh.rest(a, 1) == 0.0 ? planar1 : planar2)++; break;
      case fem::DofMap::NodeKind::RigidMember: ++rigid; break;
      default: break;
    }
  }
  // 5x3x3 grid; x=0 face has 9 nodes: node 0 pinned, 2 more on the edge y=0 (1 DOF), 6 with 2 DOFs.
  EXPECT_EQ(planar1, 2);
  EXPECT_EQ(planar2, 6);
  EXPECT_EQ(rigid, 18);  // the last column of cells, x in [1.5, 2]: two node layers of 9
  EXPECT_EQ(f.dofs->num_dofs(), 3 * free + 2 * 6 + 1 * 2 + 6);
}

TEST(DofMap, SyncSatisfiesPlanarConstraints) {
  Fixture f(fem::RigidBody::Kind::Prescribed);
  fem::State s = scrambled(*f.dofs, 0.5);
  f.dofs->sync(s, 0.5);
  for (Index a : f.problem.planar[0].nodes)
    if (a != 0) {
      EXPECT_NEAR(s.x(a, 0) - f.problem.mesh.rest(a, 0), 0.025, 1e-14);
    }
  // Prescribed rigid body follows its motion.
  for (Index a : f.dofs->rigid_members(0)) {
    const Vector3 expected = f.problem.rigid_bodies[0].motion.apply(f.problem.mesh.rest.row(a).transpose(), 0.5);
    EXPECT_NEAR((s.x.row(a).transpose() - expected).norm(), 0, 1e-13);
  }
}

/// The state a first stage of `kind` ends in: the problem synced to lambda = 1 with the free
/// nodes displaced and the free rigid body turned.
fem::State end_of_first_stage(const fem::DofMap& dofs, const fem::Problem& p) {
  fem::State s = dofs.initial_state(1.0);
  for (Index a = 0; a < p.mesh.num_nodes(); ++a)
    if (dofs.kind(a) == fem::DofMap::NodeKind::Free) s.x.row(a) += Vector3(0.01 * a, -0.02, 0.03).transpose();
  if (dofs.rigid_first_dof(0) >= 0) {
    VectorX dq = VectorX::Zero(dofs.num_dofs());
    dq.segment<6>(dofs.rigid_first_dof(0)) << 0.1, 0, -0.05, 0.2, -0.1, 0.3;
    s = dofs.apply_step(s, dq, 1.0);
  }
  return s;
}

TEST(DofMap, AStartStateIsWhereMotionsAndPlanesStartFrom) {
  for (auto kind : {fem::RigidBody::Kind::Prescribed, fem::RigidBody::Kind::Fixed, fem::RigidBody::Kind::Free}) {
    SCOPED_TRACE(static_cast<int>(kind));
    Fixture first(kind);
    const fem::State start = end_of_first_stage(*first.dofs, first.problem);
    Fixture second(kind);
    second.dofs->set_start(start);
    ASSERT_TRUE(second.dofs->has_start());
    // At lambda 0 of the new stage: exactly the start state (the motions are 0 there, and
    // every constraint is measured from the start).
    const fem::State s0 = second.dofs->initial_state(0.0);
    EXPECT_NEAR((s0.x - start.x).cwiseAbs().maxCoeff(), 0, 1e-14);
    const auto& p = second.problem;
    const fem::State s = second.dofs->initial_state(0.5);
    // Planar nodes: their displacement in the plane's normal is measured from the start.
    for (Index a : p.planar[0].nodes)
      if (a != 0) {
        EXPECT_NEAR(s.x(a, 0) - start.x(a, 0), 0.025, 1e-14);
      }
    // The pinned node stays where the first stage left it.
    EXPECT_NEAR((s.x.row(0) - start.x.row(0)).norm(), 0, 1e-14);
    // Rigid members: a prescribed body moves by its motion from its start pose, a fixed one
    // stays, a free one starts at its pose.
    const fem::RigidMotion& motion = p.rigid_bodies[0].motion;
    for (Index a : second.dofs->rigid_members(0)) {
      const Vector3 from = start.x.row(a).transpose();
      const Vector3 expected = kind == fem::RigidBody::Kind::Prescribed ? motion.apply(from, 0.5) : from;
      EXPECT_NEAR((s.x.row(a).transpose() - expected).norm(), 0, 1e-12) << "node " << a;
    }
  }
}

TEST(DofMap, RefusesAStartStateThatDoesNotFit) {
  Fixture f(fem::RigidBody::Kind::Free);
  fem::State start = f.dofs->initial_state(0.0);
  fem::State fewer = start;
  fewer.x.conservativeResize(start.x.rows() - 1, 3);
  EXPECT_THROW(f.dofs->set_start(fewer), InputError);
  fem::State no_bodies = start;
  no_bodies.rigid.clear();
  EXPECT_THROW(f.dofs->set_start(no_bodies), InputError);
  fem::State not_finite = start;
  not_finite.x(3, 1) = std::nan("");
  EXPECT_THROW(f.dofs->set_start(not_finite), InputError);
  // The rigid body's nodes deformed (it was deformable in the earlier run).
  fem::State bent = start;
  bent.x.row(f.dofs->rigid_members(0).front()) += Vector3(0, 0.1, 0).transpose();
  try {
    f.dofs->set_start(bent);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rigid body \"bone\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("deformable"), std::string::npos) << e.what();
  }
  fem::State sheared = start;
  sheared.rigid[0].R(0, 1) = 0.5;
  EXPECT_THROW(f.dofs->set_start(sheared), InputError);
  EXPECT_FALSE(f.dofs->has_start());
}

class DofMapDerivatives : public ::testing::TestWithParam<fem::RigidBody::Kind> {};

TEST_P(DofMapDerivatives, ReducedGradientAndHessianMatchFiniteDifferences) {
  Fixture f(GetParam());
  f.external->set_load_parameter(1.0);
  const fem::State base = scrambled(*f.dofs, 1.0);
  const Index n = f.dofs->num_dofs();
  auto E = [&](const VectorX& q) { return f.energy(f.dofs->apply_step(base, q, 1.0)); };

  const NodalVectors g_full = f.gradient(base);
  const VectorX g = f.dofs->reduce_gradient(base, g_full);
  const VectorX fd_g = st::fd_gradient(E, VectorX::Zero(n), 1e-6);
  EXPECT_LT(st::relative_error(g, fd_g), 1e-7);

  std::vector<std::pair<Index, Index>> pairs;
  f.elastic->hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(f.problem.mesh.num_nodes(), pairs);
  f.elastic->bind_pattern(H);
  fem::HessianReduction reduction(*f.dofs);
  reduction.bind(H);
  f.elastic->add_hessian(base.x, H);
  fem::SparseMatrix K;
  reduction.reduce(base, H, g_full, VectorX(), K);
  const MatrixX dense = MatrixX(K);

  // Second differences of the energy through the step map.
  const double h = 1e-4;
  MatrixX fd_K(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index j = i; j < n; ++j) {
      VectorX q = VectorX::Zero(n);
      auto at = [&](double si, double sj) {
        q.setZero();
        q[i] += si * h;
        q[j] += sj * h;
        return E(q);
      };
      fd_K(i, j) = fd_K(j, i) = (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4 * h * h);
    }
  EXPECT_LT(st::relative_error(dense, fd_K), 1e-5);
  if (GetParam() == fem::RigidBody::Kind::Free) {
    const Index r = n - 6;  // rotation-rotation block: where the second-order map term lives
    EXPECT_LT(st::relative_error(dense.block(r + 3, r + 3, 3, 3), fd_K.block(r + 3, r + 3, 3, 3)), 1e-5);
  }
}

INSTANTIATE_TEST_SUITE_P(RigidKinds, DofMapDerivatives,
                         ::testing::Values(fem::RigidBody::Kind::Free, fem::RigidBody::Kind::Prescribed));

TEST(DofMap, RejectsContradictoryConstraints) {
  auto p = mixed_problem(fem::RigidBody::Kind::Fixed);
  p.prescribed.push_back({"grab-bone", {p.mesh.num_nodes() - 1}, fem::RigidMotion{}});
  try {
    fem::DofMap dofs(p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grab-bone"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rigid body"), std::string::npos) << e.what();
  }
  auto q = mixed_problem(fem::RigidBody::Kind::Fixed);
  q.planar.push_back({"again-x", {3}, Vector3(-1, 0, 0), 0.0, {}});
  q.planar.push_back({"also-x", {3}, Vector3(1, 0, 0), 0.0, {}});
  EXPECT_THROW(fem::DofMap dofs(q), InputError);
}

TEST(Reactions, BalanceGravityOnAFixedBody) {
  // A block resting on a fixed bottom face: the reaction carries the weight (at any state,
  // since sum of elastic forces is zero).
  auto p = st::box_problem(2, 2, 2, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin(), 2.0);
  p.prescribed.push_back({"floor", st::nodes_on_plane(p.mesh, 2, 0.0), fem::RigidMotion{}});
  fem::DofMap dofs(p);
  fem::ElasticEnergy elastic(p.mesh.rest, p.mesh.tets, st::tet_materials(p));
  fem::ExternalForceEnergy gravity(fem::lumped_masses(p.mesh.rest, p.mesh.tets, p.mesh.region, p.region_density),
                                   Vector3(0, 0, -9.81), {}, {}, p.mesh.num_nodes());
  fem::State s = dofs.initial_state(1.0);
  NodalVectors g = NodalVectors::Zero(p.mesh.num_nodes(), 3);
  elastic.add_gradient(s.x, g);
  gravity.add_gradient(s.x, g);
  // Move free nodes to make the elastic forces non-zero; the reaction still balances the load
  // once the free nodes are in equilibrium; here we check the bookkeeping: total = -sum(g over set).
  const auto reactions = fem::compute_reactions(p, dofs, s, g);
  ASSERT_EQ(reactions.size(), 1u);
  Vector3 expected = Vector3::Zero();
  for (Index a : p.prescribed[0].nodes) expected += g.row(a).transpose();
  EXPECT_LT((reactions[0].force - expected).norm(), 1e-12);
}
