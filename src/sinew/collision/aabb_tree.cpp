#include "sinew/collision/aabb_tree.hpp"

#include <stdexcept>

namespace sinew::collision {

void AabbTree::build(const std::vector<Aabb>& boxes, int leaf_size) {
  // Programming error, not input: the leaf size is chosen by the code that builds the tree.
  if (leaf_size < 1) throw std::invalid_argument("AabbTree::build: leaf_size must be >= 1");
  nodes_.clear();
  leaf_boxes_.clear();
  slot_.clear();
  order_.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) order_[i] = static_cast<Index>(i);
  if (boxes.empty()) return;
  nodes_.reserve(2 * (boxes.size() / static_cast<std::size_t>(leaf_size) + 1));

  std::vector<Vector3> centers(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) centers[i] = boxes[i].center();

  // Explicit work list of (node, begin, end) ranges of order_; children are appended after
  // their parent, which refit() relies on.
  struct Range {
    Index node, begin, end;
  };
  std::vector<Range> work;
  nodes_.push_back(Node{});
  work.push_back({0, 0, static_cast<Index>(boxes.size())});
  while (!work.empty()) {
    const Range r = work.back();
    work.pop_back();
    Aabb box;
    for (Index k = r.begin; k < r.end; ++k) box.extend(boxes[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])]);
    nodes_[static_cast<std::size_t>(r.node)].box = box;
    if (r.end - r.begin <= leaf_size) {
      nodes_[static_cast<std::size_t>(r.node)].first = r.begin;
      nodes_[static_cast<std::size_t>(r.node)].count = r.end - r.begin;
      continue;
    }
    int axis = 0;
    box.sizes().maxCoeff(&axis);
    const Index mid = r.begin + (r.end - r.begin) / 2;
    std::nth_element(order_.begin() + r.begin, order_.begin() + mid, order_.begin() + r.end, [&](Index a, Index b) {
      const double ca = centers[static_cast<std::size_t>(a)][axis];
      const double cb = centers[static_cast<std::size_t>(b)][axis];
      return ca < cb || (ca == cb && a < b);  // total order: deterministic
    });
    const Index left = static_cast<Index>(nodes_.size());
    nodes_.push_back(Node{});
    nodes_.push_back(Node{});
    nodes_[static_cast<std::size_t>(r.node)].first = left;
    nodes_[static_cast<std::size_t>(r.node)].count = 0;
    work.push_back({left + 1, mid, r.end});
    work.push_back({left, r.begin, mid});
  }
  leaf_boxes_.resize(boxes.size());
  slot_.resize(boxes.size());
  for (std::size_t k = 0; k < order_.size(); ++k) {
    leaf_boxes_[k] = boxes[static_cast<std::size_t>(order_[k])];
    slot_[static_cast<std::size_t>(order_[k])] = static_cast<Index>(k);
  }
}

void AabbTree::refit(const std::vector<Aabb>& boxes) {
  // Programming error, not input: refit() is given the boxes of the same primitives as build().
  if (boxes.size() != order_.size())
    throw std::invalid_argument("AabbTree::refit: " + std::to_string(boxes.size()) + " boxes for a tree built over " +
                                std::to_string(order_.size()));
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    Node& node = nodes_[n];
    Aabb box;
    if (node.is_leaf()) {
      for (Index k = node.first; k < node.first + node.count; ++k) {
        const Aabb& b = boxes[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])];
        leaf_boxes_[static_cast<std::size_t>(k)] = b;
        box.extend(b);
      }
    } else {
      box = nodes_[static_cast<std::size_t>(node.first)].box;
      box.extend(nodes_[static_cast<std::size_t>(node.first + 1)].box);
    }
    node.box = box;
  }
}

}  // namespace sinew::collision
