#include "sinew/fem/mass_matrix.hpp"

#include <cmath>
#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/fem/tet_kinematics.hpp"

namespace sinew::fem {

Eigen::SparseMatrix<double> mass_matrix(const Positions& rest, const Tets& tets, const IndexVector& region,
                                        const std::vector<double>& region_density, MassKind kind) {
  if (region.size() != tets.rows())
    throw Error(fmt::format("mass_matrix: {} region ids for {} tets", region.size(), tets.rows()));
  for (std::size_t r = 0; r < region_density.size(); ++r) {
    const double rho = region_density[r];
    if (!(rho >= 0) || !std::isfinite(rho))
      throw InputError(fmt::format("mass_matrix: density of region {} must be finite and >= 0, got {}", r, rho));
  }
  for (Index t = 0; t < tets.rows(); ++t)
    if (region[t] < 0 || static_cast<std::size_t>(region[t]) >= region_density.size())
      throw Error(fmt::format("mass_matrix: tet {} has region {}, but only {} region densities are given", t,
                              region[t], region_density.size()));

  const auto shapes = compute_rest_shapes(rest, tets);
  const auto num_nodes = static_cast<Index>(rest.rows());
  std::vector<Eigen::Triplet<double, Index>> entries;
  entries.reserve(static_cast<std::size_t>(num_nodes) +
                  static_cast<std::size_t>(tets.rows()) * (kind == MassKind::Consistent ? 16 : 4));
  for (Index a = 0; a < num_nodes; ++a) entries.emplace_back(a, a, 0.0);  // a full stored diagonal
  for (Index t = 0; t < tets.rows(); ++t) {
    const double m = region_density[static_cast<std::size_t>(region[t])] * shapes[t].volume;
    if (kind == MassKind::Lumped) {
      for (int i = 0; i < 4; ++i) entries.emplace_back(tets(t, i), tets(t, i), m / 4.0);
    } else {
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) entries.emplace_back(tets(t, i), tets(t, j), m / 20.0 * (i == j ? 2.0 : 1.0));
    }
  }
  Eigen::SparseMatrix<double> M(num_nodes, num_nodes);
  M.setFromTriplets(entries.begin(), entries.end());  // duplicates are summed
  return M;
}

}  // namespace sinew::fem
