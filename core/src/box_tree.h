// BoxTree<D>: a static bounding-box hierarchy over axis-aligned boxes, for finding the pairs of
// simplices whose boxes overlap (PLC checking, point location in validate()). Box coordinates are
// the input doubles themselves, so overlap tests are exact comparisons.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

namespace sweepcdt::detail {

template <int D>
struct Box {
  std::array<double, D> lo, hi;

  static Box of_points(const double* const* p, int count) {
    Box b;
    for (int k = 0; k < D; ++k) b.lo[k] = b.hi[k] = p[0][k];
    for (int i = 1; i < count; ++i)
      for (int k = 0; k < D; ++k) {
        b.lo[k] = std::min(b.lo[k], p[i][k]);
        b.hi[k] = std::max(b.hi[k], p[i][k]);
      }
    return b;
  }
  bool overlaps(const Box& o) const {
    for (int k = 0; k < D; ++k)
      if (hi[k] < o.lo[k] || o.hi[k] < lo[k]) return false;
    return true;
  }
  void extend(const Box& o) {
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], o.lo[k]);
      hi[k] = std::max(hi[k], o.hi[k]);
    }
  }
};

template <int D>
class BoxTree {
 public:
  explicit BoxTree(std::vector<Box<D>> boxes) : boxes_(std::move(boxes)), order_(boxes_.size()) {
    std::iota(order_.begin(), order_.end(), 0u);
    if (boxes_.empty()) return;
    centres_.resize(boxes_.size());
    for (std::size_t i = 0; i < boxes_.size(); ++i)
      for (int k = 0; k < D; ++k) centres_[i][k] = boxes_[i].lo[k] / 2 + boxes_[i].hi[k] / 2;
    nodes_.reserve(2 * boxes_.size() / kLeafSize + 1);
    nodes_.push_back({});
    build(0, 0, static_cast<uint32_t>(boxes_.size()));
    centres_ = {};
  }

  // Calls visit(i) for every box i that overlaps `query`.
  template <class Visit>
  void for_each_overlap(const Box<D>& query, Visit&& visit) const {
    for_each_passing([&](const Box<D>& b) { return b.overlaps(query); }, visit);
  }

  // Calls visit(i) for every box i that passes `test` (a box predicate that must also hold for any
  // box enclosing a passing one, like "meets this ray"), pruning subtrees whose bounds fail it.
  template <class Test, class Visit>
  void for_each_passing(Test&& test, Visit&& visit) const {
    if (nodes_.empty()) return;
    Stack stack;
    while (!stack.empty()) {
      const Node& node = nodes_[stack.pop()];
      if (!test(node.box)) continue;
      if (node.left == kLeaf) {
        for (uint32_t i = node.begin; i < node.end; ++i)
          if (test(boxes_[order_[i]])) visit(order_[i]);
      } else {
        stack.push(node.left);
        stack.push(node.left + 1);
      }
    }
  }

  // True as soon as pred(i) holds for a box i overlapping `query`.
  template <class Pred>
  bool any_overlap(const Box<D>& query, Pred&& pred) const {
    if (nodes_.empty()) return false;
    Stack stack;
    while (!stack.empty()) {
      const Node& node = nodes_[stack.pop()];
      if (!node.box.overlaps(query)) continue;
      if (node.left == kLeaf) {
        for (uint32_t i = node.begin; i < node.end; ++i)
          if (boxes_[order_[i]].overlaps(query) && pred(order_[i])) return true;
      } else {
        stack.push(node.left);
        stack.push(node.left + 1);
      }
    }
    return false;
  }

  const Box<D>& box(uint32_t i) const { return boxes_[i]; }

 private:
  static constexpr uint32_t kLeaf = 0xffffffffu;
  static constexpr uint32_t kLeafSize = 4;
  // The nodes a depth-first walk has yet to visit, starting at the root. The tree is balanced (median
  // splits), so it is at most 32 levels deep for 2^32 boxes, and a walk holds at most one node a
  // level plus one: a fixed array, not a vector allocated by every query (the PLC check makes one
  // query per simplex).
  class Stack {
   public:
    bool empty() const { return size_ == 0; }
    void push(uint32_t node) { slots_[size_++] = node; }
    uint32_t pop() { return slots_[--size_]; }

   private:
    std::array<uint32_t, 64> slots_{};  // slots_[0] = 0: the root
    uint32_t size_ = 1;
  };
  struct Node {
    Box<D> box;
    uint32_t begin = 0, end = 0, left = kLeaf;  // children: nodes left and left + 1
  };

  // Builds the subtree of order_[begin, end) with its root in nodes_[slot] (already allocated):
  // median split of the box centres along the longest axis.
  void build(uint32_t slot, uint32_t begin, uint32_t end) {
    Box<D> bounds = boxes_[order_[begin]];
    for (uint32_t i = begin + 1; i < end; ++i) bounds.extend(boxes_[order_[i]]);
    nodes_[slot] = {bounds, begin, end, kLeaf};
    if (end - begin <= kLeafSize) return;
    int axis = 0;
    for (int k = 1; k < D; ++k)
      if (bounds.hi[k] - bounds.lo[k] > bounds.hi[axis] - bounds.lo[axis]) axis = k;
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](uint32_t a, uint32_t b) { return centres_[a][axis] < centres_[b][axis]; });
    const uint32_t left = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[slot].left = left;
    build(left, begin, mid);
    build(left + 1, mid, end);
  }

  std::vector<Box<D>> boxes_;
  std::vector<uint32_t> order_;
  std::vector<Node> nodes_;
  std::vector<std::array<double, D>> centres_;  // only while building
};

}  // namespace sweepcdt::detail
