#pragma once
/// @file share.hpp
/// Splitting a list of work items among the parts that share it (the ranks of a run on several
/// processes, docs/mpi.md).

#include <algorithm>
#include <cstddef>

namespace sinew {

/// Items [begin, end) of a list.
struct ItemRange {
  std::size_t begin = 0, end = 0;
};

/// The items of 0..count-1 that part `part` of `parts` takes: contiguous ranges, in order, whose
/// sizes differ by at most one (parts < 1 counts as 1).
inline ItemRange share_of(std::size_t count, int part, int parts) {
  const auto p = static_cast<std::size_t>(std::max(1, parts));
  const auto k = static_cast<std::size_t>(std::clamp(part, 0, static_cast<int>(p) - 1));
  const std::size_t base = count / p, extra = count % p;
  ItemRange range;
  range.begin = k * base + std::min(k, extra);
  range.end = range.begin + base + (k < extra ? 1 : 0);
  return range;
}

}  // namespace sinew
