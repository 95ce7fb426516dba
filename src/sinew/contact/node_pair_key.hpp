#pragma once
/// @file node_pair_key.hpp
/// A hash key for an unordered pair of node indices: the Hessian blocks a contact or friction
/// term fills, kept in a set to know when the sparsity pattern grew.

#include <algorithm>
#include <cstdint>

#include "sinew/core/types.hpp"

namespace sinew::contact {

/// The key of the pair {a, b} (both in [0, 2^32)): the smaller index in the high 32 bits, so
/// (a, b) and (b, a) give one key.
inline std::uint64_t node_pair_key(Index a, Index b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint64_t>(std::max(a, b));
}

}  // namespace sinew::contact
