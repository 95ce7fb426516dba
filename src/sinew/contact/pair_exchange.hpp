#pragma once
/// @file pair_exchange.hpp
/// Contact pairs as bytes, for the ranks of a run on several processes to exchange the pairs each
/// one detected (docs/mpi.md, "Collision detection split by tet"). Only what the pair's method
/// uses is written: the clip polygon's `count` vertices (area method) or the collocation points
/// (point method). The bytes are read back on a process of the same build, so the layout is the
/// machine's own.

#include <cstddef>
#include <vector>

#include "sinew/contact/collision_set.hpp"

namespace sinew::contact {

/// Appends `pairs`, written for `method`, to `bytes`.
void pack_pairs(const std::vector<ActivePair>& pairs, ContactMethod method, std::vector<char>& bytes);

/// The pairs of `bytes` (one or more pack_pairs() outputs for `method`, concatenated), in order.
/// Throws std::runtime_error when the bytes end inside a pair or hold an impossible count (they
/// come from sinew itself, so that is a programming error).
std::vector<ActivePair> unpack_pairs(const std::vector<char>& bytes, ContactMethod method);

}  // namespace sinew::contact
