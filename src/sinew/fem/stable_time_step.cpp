#include "sinew/fem/stable_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "sinew/core/error.hpp"
#include "sinew/fem/tet_kinematics.hpp"

namespace sinew::fem {
namespace {

/// Largest eigenvalue found so far (omega^2, 1 / time^2) and its tet.
struct ElementBound {
  double lambda = -1;
  Index tet = -1;
};

/// The better of two bounds: the larger eigenvalue, the lower tet index on ties (deterministic).
ElementBound larger(const ElementBound& a, const ElementBound& b) {
  if (a.lambda != b.lambda) return a.lambda > b.lambda ? a : b;
  return (a.tet >= 0 && (b.tet < 0 || a.tet < b.tet)) ? a : b;
}

/// lambda_max(M_e^-1 K_e) for one tet: K_e = V0 B^T (dP/dF)(I) B (12 x 12, stress x length), M_e
/// = diag(rho V0 / 4) (mass). With a diagonal M_e the generalized problem is the symmetric one of
/// M_e^-1/2 K_e M_e^-1/2.
double element_eigenvalue(const material::Material& law, const TetRestShape& shape, double rho) {
  const Matrix9 dPdF = law.first_piola_derivative(Matrix3::Identity());
  const Eigen::Matrix<double, 9, 12> B = deformation_gradient_jacobian(shape.Dm_inv);
  const Matrix12 K = shape.volume * (B.transpose() * dPdF * B);
  Vector12 inv_sqrt_m;
  inv_sqrt_m.setConstant(1.0 / std::sqrt(rho * shape.volume / 4.0));
  Matrix12 A = inv_sqrt_m.asDiagonal() * K * inv_sqrt_m.asDiagonal();
  A = 0.5 * (A + A.transpose());  // dP/dF is symmetric up to rounding
  const Eigen::SelfAdjointEigenSolver<Matrix12> eig(A, Eigen::EigenvaluesOnly);
  return eig.eigenvalues()[11];  // ascending
}

}  // namespace

StableTimeStep critical_time_step(const Positions& rest, const Tets& tets,
                                  const std::vector<material::MaterialPtr>& tet_material,
                                  const VectorX& tet_density) {
  if (tet_material.size() != static_cast<std::size_t>(tets.rows()) || tet_density.size() != tets.rows())
    throw Error(fmt::format("critical_time_step: {} tets but {} materials and {} densities", tets.rows(),
                            tet_material.size(), tet_density.size()));
  for (Index t = 0; t < tets.rows(); ++t) {
    const double rho = tet_density[t];
    if (tet_material[t] && !(rho > 0 && std::isfinite(rho)))
      throw InputError(fmt::format(
          "critical_time_step: elastic tet {} has density {}; explicit time integration needs a finite "
          "density > 0 in every elastic region",
          t, rho));
  }
  const auto shapes = compute_rest_shapes(rest, tets);

  const ElementBound worst = tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, static_cast<Index>(tets.rows()), 256), ElementBound{},
      [&](const tbb::blocked_range<Index>& r, ElementBound best) {
        for (Index t = r.begin(); t < r.end(); ++t) {
          if (!tet_material[t]) continue;
          double lambda = element_eigenvalue(*tet_material[t], shapes[t], tet_density[t]);
          if (std::isnan(lambda)) lambda = std::numeric_limits<double>::infinity();  // reported below
          best = larger(best, {lambda, t});
        }
        return best;
      },
      larger);

  StableTimeStep result;
  if (worst.tet < 0) {
    result.dt = std::numeric_limits<double>::infinity();
    return result;
  }
  if (!std::isfinite(worst.lambda))
    throw Error(fmt::format("critical_time_step: the stiffness of tet {} at rest is not finite (material '{}')",
                            worst.tet, tet_material[worst.tet]->name()));
  result.critical_tet = worst.tet;
  result.omega_max = std::sqrt(std::max(worst.lambda, 0.0));
  result.dt = result.omega_max > 0 ? 2.0 / result.omega_max : std::numeric_limits<double>::infinity();
  return result;
}

}  // namespace sinew::fem
