#include "sinew/solver/row_order.hpp"

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/core/share.hpp"

namespace sinew::solver {

std::vector<int> unknown_owners(const fem::DofMap& dofs, const std::vector<int>& node_owner, Index num_nodes) {
  if (node_owner.empty()) return {};
  if (node_owner.size() != static_cast<std::size_t>(num_nodes))
    throw Error(fmt::format("row owners: {} node owners for {} nodes", node_owner.size(), num_nodes));
  std::vector<int> owner(static_cast<std::size_t>(dofs.num_dofs()), 0);  // rigid bodies' unknowns: rank 0
  for (Index a = 0; a < num_nodes; ++a) {
    if (dofs.kind(a) == fem::DofMap::NodeKind::RigidMember) continue;  // its body's unknowns
    for (int k = 0; k < dofs.num_node_dofs(a); ++k)
      owner[static_cast<std::size_t>(dofs.first_dof(a) + k)] = node_owner[static_cast<std::size_t>(a)];
  }
  return owner;
}

RowOrder order_rows_by_owner(Index n, const std::vector<int>& owner, int ranks, int block_size) {
  if (ranks < 1) ranks = 1;
  if (block_size < 1 || n % block_size != 0)
    throw Error(fmt::format("row order: {} unknowns are not blocks of {}", n, block_size));
  if (!owner.empty() && owner.size() != static_cast<std::size_t>(n))
    throw Error(fmt::format("row order: {} owners for {} unknowns", owner.size(), n));
  const Index blocks = n / block_size;
  std::vector<int> block_owner(static_cast<std::size_t>(blocks));
  for (int r = 0; r < ranks; ++r) {
    const ItemRange share = share_of(static_cast<std::size_t>(blocks), r, ranks);
    for (std::size_t b = share.begin; b < share.end; ++b) block_owner[b] = r;
  }
  if (!owner.empty())
    for (Index b = 0; b < blocks; ++b) {
      const int r = owner[static_cast<std::size_t>(b * block_size)];
      if (r < 0 || r >= ranks) throw Error(fmt::format("row order: unknown {} owned by rank {} of {}", b * block_size, r, ranks));
      block_owner[static_cast<std::size_t>(b)] = r;
    }
  RowOrder order;
  order.first.assign(static_cast<std::size_t>(ranks) + 1, 0);
  for (const int r : block_owner) order.first[static_cast<std::size_t>(r) + 1] += block_size;
  for (std::size_t r = 0; r < static_cast<std::size_t>(ranks); ++r) order.first[r + 1] += order.first[r];
  order.old_of_new.resize(static_cast<std::size_t>(n));
  std::vector<Index> next(order.first.begin(), order.first.end() - 1);
  for (Index b = 0; b < blocks; ++b) {
    Index& at = next[static_cast<std::size_t>(block_owner[static_cast<std::size_t>(b)])];
    for (int k = 0; k < block_size; ++k) order.old_of_new[static_cast<std::size_t>(at++)] = b * block_size + k;
  }
  return order;
}

}  // namespace sinew::solver
