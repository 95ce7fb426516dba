#pragma once
/// @file flat_positions.hpp
/// Positions (#V x 3, row-major) as one vector (x0 y0 z0 x1 ...) and back, for tests that
/// compare nodal fields with flat gradients and Hessians.

#include <Eigen/Core>

#include "sinew/core/types.hpp"

namespace sinew::testing {

inline VectorX flatten(const Positions& x) { return Eigen::Map<const VectorX>(x.data(), x.size()); }
inline Positions unflatten(const VectorX& v) { return Eigen::Map<const Positions>(v.data(), v.size() / 3, 3); }

}  // namespace sinew::testing
