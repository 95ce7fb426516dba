// Coplanar boundary faces of different bodies (docs/contact.md, "Faces in one plane"): two blocks
// stacked face to face with zero gap, and two slabs side by side whose ends lie in one cut plane.
// Touching faces give no energy and no force (their pairs are active, with zero depth, so Newton
// sees the contact stiffness from the start); the energy stays C¹ through the
// touching configuration (finite differences of the total energy); a cut face whose depth is not
// zero makes the energy jump unless it is kept out of the contact surface, and leaves a kink
// (C⁰) where the other body's side walls end in its plane.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "sinew/collision/material_depth.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "support/box_mesh.hpp"
#include "support/contact_fixtures.hpp"
#include "support/fd_check.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

/// Two box meshes as bodies 0 and 1 of one ContactGeometry (penalty 1 between them, no self
/// contact). `keep(body, triangle rest positions)` says which boundary triangles are contact
/// surface; `depth_surface(body, ...)` which are zero-depth surface.
struct TwoBodies {
  Positions x;
  ContactGeometry geometry;
  Index first_of_body1 = 0;
};

template <class Keep, class DepthSurface>
TwoBodies two_bodies(const mesh::TetMesh& a, const mesh::TetMesh& b, Keep keep, DepthSurface depth_surface) {
  TwoBodies out;
  const Index na = a.rest.rows(), nb = b.rest.rows();
  out.first_of_body1 = na;
  out.x.resize(na + nb, 3);
  out.x << a.rest, b.rest;
  auto& g = out.geometry;
  std::vector<Eigen::RowVector3i> surface;
  std::vector<Index> surface_body;
  g.depth.resize(na + nb);
  const mesh::TetMesh* meshes[2] = {&a, &b};
  for (Index body = 0; body < 2; ++body) {
    const mesh::TetMesh& m = *meshes[body];
    const Index offset = body == 0 ? 0 : na;
    const Triangles boundary = mesh::boundary_triangles(m.tets);
    std::vector<Index> depth_rows;
    for (Index f = 0; f < boundary.rows(); ++f) {
      Matrix3 tri;
      for (int k = 0; k < 3; ++k) tri.row(k) = m.rest.row(boundary(f, k));
      if (keep(body, tri)) {
        surface.push_back(boundary.row(f).array() + static_cast<int>(offset));
        surface_body.push_back(body);
      }
      if (depth_surface(body, tri)) depth_rows.push_back(f);
    }
    Triangles zero(static_cast<Index>(depth_rows.size()), 3);
    for (std::size_t k = 0; k < depth_rows.size(); ++k) zero.row(static_cast<Index>(k)) = boundary.row(depth_rows[k]);
    std::vector<Index> nodes(static_cast<std::size_t>(m.rest.rows()));
    for (Index i = 0; i < m.rest.rows(); ++i) nodes[static_cast<std::size_t>(i)] = i;
    g.depth.segment(offset, m.rest.rows()) = collision::material_depth(m.rest, zero, nodes);
  }
  g.surface.resize(static_cast<Index>(surface.size()), 3);
  g.surface_body.resize(static_cast<Index>(surface.size()));
  for (std::size_t k = 0; k < surface.size(); ++k) {
    g.surface.row(static_cast<Index>(k)) = surface[k];
    g.surface_body[static_cast<Index>(k)] = surface_body[k];
  }
  g.tets.resize(a.tets.rows() + b.tets.rows(), 4);
  g.tets << a.tets, (b.tets.array() + static_cast<int>(na)).matrix();
  g.tet_body.resize(g.tets.rows());
  g.tet_body.head(a.tets.rows()).setZero();
  g.tet_body.tail(b.tets.rows()).setOnes();
  g.penalty = MatrixX::Constant(2, 2, 1.0);
  g.penalty.diagonal().setZero();
  return out;
}

auto every_face = [](Index, const Matrix3&) { return true; };

/// Relative error of the gradient against central differences over every coordinate.
double fd_error(ContactEnergy& energy, const Positions& x, double h) {
  const NodalVectors analytic = st::gradient_at(energy, x);
  Eigen::VectorXd x0(3 * x.rows()), a(3 * x.rows());
  for (Index i = 0; i < x.rows(); ++i)
    for (int c = 0; c < 3; ++c) {
      x0[3 * i + c] = x(i, c);
      a[3 * i + c] = analytic(i, c);
    }
  auto f = [&](const Eigen::VectorXd& v) {
    Positions y = x;
    for (Index i = 0; i < x.rows(); ++i)
      for (int c = 0; c < 3; ++c) y(i, c) = v[3 * i + c];
    energy.update(y);
    return energy.value(y);
  };
  return st::relative_error(a, st::fd_gradient(f, x0, h));
}

Positions moved(const TwoBodies& s, const Vector3& body1_offset) {
  Positions x = s.x;
  for (Index i = s.first_of_body1; i < x.rows(); ++i) x.row(i) += body1_offset.transpose();
  return x;
}

class Coplanar : public ::testing::TestWithParam<PairHessian> {};

TEST_P(Coplanar, StackedFaceToFaceWithZeroGapHasNoForceAndAContinuousEnergy) {
  // Body 0 = [0,1]² x [-1,0] (2 cells a side), body 1 = [0,1]² x [0,1] (3 cells a side): the
  // touching faces z = 0 have non-matching meshes; depth is measured from every boundary face.
  const TwoBodies s = two_bodies(st::box_mesh(2, 2, 2, Vector3(0, 0, -1), Vector3(1, 1, 0)),
                                 st::box_mesh(3, 3, 3, Vector3(0, 0, 0), Vector3(1, 1, 1)), every_face, every_face);
  ContactEnergy energy(s.geometry, {ContactMethod::Area, GetParam()});
  energy.update(s.x);
  // Each touching triangle lies on a boundary face of the other body, counted once by the
  // half-open rule, where the depth is zero: no energy and no force (round-off only), but a
  // contact stiffness for Newton.
  EXPECT_FALSE(energy.active_pairs().empty());
  EXPECT_LT(energy.value(s.x), 1e-28);
  EXPECT_LT(st::gradient_at(energy, s.x).norm(), 1e-13);
  EXPECT_GT(st::hessian_at(energy, s.x).norm(), 0.01);
  // Pressed together by d: E ~ d² (no jump, no kink in E at d = 0); exact gradient at d.
  auto energy_at = [&](double d) {
    const Positions x = moved(s, Vector3(0, 0, -d));
    energy.update(x);
    return energy.value(x);
  };
  const double e3 = energy_at(1e-3), e6 = energy_at(1e-6);
  std::cout << "[stacked] E(1e-3) = " << e3 << ", E(1e-6) = " << e6 << ", E(-1e-6) = " << energy_at(-1e-6) << "\n";
  EXPECT_GT(e3, 0);
  EXPECT_NEAR(e6 / e3, 1e-6, 1e-7);
  EXPECT_EQ(energy_at(-1e-6), 0.0);
  const double err = fd_error(energy, moved(s, Vector3(0.013, -0.021, -1e-3)), 1e-8);
  EXPECT_LT(err, 1e-5);
}

/// Two slabs side by side, both ending in the cut plane z = 0: body 0 = [-1, 0.1] x [0,1] x
/// [-1,0], body 1 = [0,1] x [0,1] x [-1,0], overlapping by 0.1 in x, so the ends of both lie in
/// one plane over the strip 0 < x < 0.1.
bool on_cut(const Matrix3& tri) { return (tri.col(2).array().abs() < 1e-12).all(); }

TwoBodies side_by_side(bool cut_is_contact_surface, bool cut_is_depth_surface) {
  return two_bodies(
      st::box_mesh(4, 2, 2, Vector3(-1, 0, -1), Vector3(0.1, 1, 0)), st::box_mesh(3, 3, 3, Vector3(0, 0, -1), Vector3(1, 1, 0)),
      [&](Index, const Matrix3& tri) { return cut_is_contact_surface || !on_cut(tri); },
      [&](Index, const Matrix3& tri) { return cut_is_depth_surface || !on_cut(tri); });
}

/// Body 0's nodes in the cut plane moved by dz.
Positions cut_moved(const TwoBodies& s, double dz) {
  Positions x = s.x;
  for (Index i = 0; i < s.first_of_body1; ++i)
    if (std::abs(x(i, 2)) < 1e-12) x(i, 2) += dz;
  return x;
}

TEST_P(Coplanar, SideBySideCutFacesAreHarmless) {
  struct Variant {
    const char* name;
    bool contact, depth;
  };
  // Cut faces as contact and zero-depth surface (the default, whole boundary); cut faces out of
  // both (exclude_faces in a scene).
  for (const Variant v : {Variant{"cut is surface", true, true}, Variant{"cut excluded", false, false}}) {
    SCOPED_TRACE(v.name);
    const TwoBodies s = side_by_side(v.contact, v.depth);
    ContactEnergy energy(s.geometry, {ContactMethod::Area, GetParam()});
    energy.update(s.x);
    const double e0 = energy.value(s.x);
    EXPECT_GT(e0, 0);  // the side walls overlap
    // The cut face of body 0 moved in or out of the plane by round-off-sized and small amounts:
    // the energy changes continuously.
    for (const double dz : {1e-12, 1e-9}) {
      const Positions up = cut_moved(s, dz), down = cut_moved(s, -dz);
      energy.update(up);
      const double eu = energy.value(up);
      energy.update(down);
      const double ed = energy.value(down);
      EXPECT_LT(std::abs(eu - e0), 1e-6 * e0) << "dz " << dz;
      EXPECT_LT(std::abs(ed - e0), 1e-6 * e0) << "dz " << dz;
    }
    // Exact gradient. With zero depth on the cut the energy is C¹ through the coplanar state.
    // With depth > 0 on the cut, a side-wall triangle whose edge lies in the other body's cut
    // plane leaves the tets behind that plane when the edge moves out: the energy is only C⁰
    // there (a kink, whichever side the edge is counted on), so the check is made on both sides.
    if (v.depth) {
      const double err = fd_error(energy, s.x, 1e-8);
      std::cout << "[side by side] " << v.name << ": E = " << e0 << ", FD gradient error at the coplanar state "
                << err << "\n";
      EXPECT_LT(err, 1e-5);
    } else {
      for (const double dz : {-1e-3, 1e-3}) {
        const double err = fd_error(energy, cut_moved(s, dz), 1e-8);
        std::cout << "[side by side] " << v.name << ": E = " << e0 << ", FD gradient error with the cut moved by "
                  << dz << ": " << err << "\n";
        EXPECT_LT(err, 1e-5);
      }
    }
  }
}

TEST(CoplanarLimit, ACutFaceWithDepthInTheContactSurfaceMakesTheEnergyJump) {
  // Why exclude_faces exists: the cut faces are kept out of the zero-depth surface (so depth
  // there is the distance to the real surface, > 0) but left in the contact surface. Body 0's
  // end, lying in body 1's end plane over the overlap, does not count while in the plane
  // (half-open rule: its outward normal points away from body 1), and the energy jumps as it
  // moves into body 1.
  const TwoBodies s = side_by_side(/*contact=*/true, /*depth=*/false);
  ContactEnergy energy(s.geometry, {ContactMethod::Area, PairHessian::GaussNewton});
  const Positions up = cut_moved(s, 1e-9), down = cut_moved(s, -1e-9);
  energy.update(up);
  const double eu = energy.value(up);
  energy.update(down);
  const double ed = energy.value(down);
  std::cout << "[side by side] cut in the contact surface, not depth surface: E(+1e-9) = " << eu
            << ", E(-1e-9) = " << ed << "\n";
  EXPECT_GT(ed - eu, 1e-3 * eu);  // a 2e-9 move elsewhere changes E by < 1e-6 E
}

INSTANTIATE_TEST_SUITE_P(Hessians, Coplanar, ::testing::Values(PairHessian::Exact, PairHessian::GaussNewton),
                         [](const auto& info) { return info.param == PairHessian::Exact ? "Exact" : "GaussNewton"; });

}  // namespace
}  // namespace sinew::contact
