// The pair integrators' cheap rejections (src/sinew/contact/pair_integrator.hpp): the triangle's
// plane test and its edge test may only reject pairs whose clipped polygon has no area.

#include "sinew/contact/pair_integrator.hpp"

#include <gtest/gtest.h>

#include <random>

#include "sinew/collision/clip_triangle_tet.hpp"

namespace sinew::contact {
namespace {

/// The triangle (0,0,0), (1,0,0), (0,1,0) and a regular-ish tet of edge about `size` centred at
/// `center`.
PairGeometry pair_at(const Vector3& center, double size) {
  PairGeometry pg;
  pg.triangle << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  const Vector3 corners[4] = {Vector3(1, 1, 1), Vector3(1, -1, -1), Vector3(-1, 1, -1), Vector3(-1, -1, 1)};
  for (int k = 0; k < 4; ++k) pg.tet.row(k) = (center + 0.5 * size * corners[k]).transpose();
  pg.depth.setOnes();
  return pg;
}

bool clip_has_area(const PairGeometry& pg) { return collision::clip_triangle_tet(pg.triangle, pg.tet).count >= 3; }

TEST(PairIntegrator, TheEdgeTestRejectsATetBesideTheTriangleAndKeepsOneAcrossIt) {
  // Across the triangle's interior: kept, and it has area.
  const PairGeometry across = pair_at(Vector3(0.25, 0.25, 0), 0.3);
  EXPECT_TRUE(tet_crosses_triangle_plane(across));
  EXPECT_TRUE(tet_within_triangle_edges(across));
  EXPECT_TRUE(clip_has_area(across));
  // Crossing the plane beyond the hypotenuse, beyond x = 0 and beyond y = 0: rejected by the
  // edge test only (the plane test keeps them), and the clip agrees.
  for (const Vector3& c : {Vector3(0.9, 0.9, 0), Vector3(-0.5, 0.3, 0), Vector3(0.3, -0.5, 0)}) {
    const PairGeometry beside = pair_at(c, 0.3);
    EXPECT_TRUE(tet_crosses_triangle_plane(beside));
    EXPECT_FALSE(tet_within_triangle_edges(beside)) << c.transpose();
    EXPECT_FALSE(clip_has_area(beside));
  }
  // A tet whose vertex lies exactly on the edge's plane x = 0 (the tet touches the edge): kept for
  // the clip to decide, never rejected on round-off.
  PairGeometry touching = pair_at(Vector3(-0.15, 0.3, 0), 0.3);
  touching.tet(0, 0) = 0.0;
  EXPECT_TRUE(tet_within_triangle_edges(touching));
  // A degenerate triangle is left to the clip.
  PairGeometry degenerate = across;
  degenerate.triangle.row(2) = degenerate.triangle.row(1);
  EXPECT_TRUE(tet_within_triangle_edges(degenerate));
}

// Random tets round the triangle, many of them touching its edges' planes or lying in its plane:
// whenever the edge test rejects a pair, the clipped polygon has no area.
TEST(PairIntegrator, TheEdgeTestNeverRejectsAPairWhoseClipHasArea) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> position(-0.6, 1.6), size(0.05, 1.0), jitter(-0.4, 0.4);
  std::uniform_int_distribution<int> pick(0, 5);
  int rejected = 0, with_area = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    PairGeometry pg = pair_at(Vector3(position(rng), position(rng), jitter(rng)), size(rng));
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) pg.tet(k, c) += 0.2 * jitter(rng);
    // Snap some vertices onto the edge planes x = 0, y = 0, x + y = 1 or the plane z = 0.
    const int snap = pick(rng), vertex = pick(rng) % 4;
    if (snap == 0) pg.tet(vertex, 0) = 0.0;
    if (snap == 1) pg.tet(vertex, 1) = 0.0;
    if (snap == 2) pg.tet(vertex, 1) = 1.0 - pg.tet(vertex, 0);
    if (snap == 3) pg.tet(vertex, 2) = 0.0;
    const bool area = clip_has_area(pg);
    with_area += area ? 1 : 0;
    if (!tet_within_triangle_edges(pg)) {
      ++rejected;
      EXPECT_FALSE(area) << "trial " << trial;
    }
  }
  // The test is not vacuous: both kinds occur often.
  EXPECT_GT(rejected, 2000);
  EXPECT_GT(with_area, 2000);
}

}  // namespace
}  // namespace sinew::contact
