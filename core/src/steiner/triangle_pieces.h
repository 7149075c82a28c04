// The refined surface's triangles while refinement splits segments (refine.cpp), split pass after
// pass at a cost proportional to the splits. A round's later passes split a few segments each (a
// scan's cascades run to thousands of passes), and rebuilding the whole list in order every pass
// was a fifth of the instructions on a jittered 86k-triangle vase.
//
// A split triangle keeps its slot and its other pieces go to the end of the lists; a link per slot
// keeps the order they would have had spliced in at its place (the same order as splitting the list
// in one scan), and put_in_order() writes that order out before anything reads the lists in order.
#pragma once
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sweepcdt::detail {

class TrianglePieces {
 public:
  using Triangle = std::array<uint32_t, 3>;

  // The lists, held by the caller: per triangle its vertices (oriented), the input triangle it lies
  // in, and whether it changed since its facet's last flips.
  TrianglePieces(std::vector<Triangle>& triangles, std::vector<uint32_t>& original, std::vector<char>& unflipped)
      : tris_(triangles), original_(original), unflipped_(unflipped) {}

  // Splits every triangle along each of its edges in `new_point` (edge_key -> the point inside it),
  // keeping its orientation and input triangle. For each new point m, steiner_on[m - first_steiner]
  // is set, when still kNone, to the input triangle of the first triangle in order holding its edge.
  // `num_points`: all points, the new ones included.
  void split(const std::unordered_map<uint64_t, uint32_t>& new_point, std::size_t num_points, std::vector<uint32_t>& steiner_on,
             uint32_t first_steiner);

  // The lists in order again (nothing to do when nothing was split since the last call).
  void put_in_order();

  // Triangle `slot` was `before` and is now tris_[slot] (a facet's flips between splits).
  void changed(uint32_t slot, const Triangle& before);

 private:
  void start(std::size_t num_points);  // the links and each point's triangles, once per ordering

  std::vector<Triangle>& tris_;
  std::vector<uint32_t>& original_;
  std::vector<char>& unflipped_;
  bool split_since_ordered_ = false;
  std::vector<uint32_t> next_;      // per slot: the next triangle in order (kNone after the last)
  std::vector<uint32_t> position_;  // per slot: where it, or the triangle it was split from, was at the last ordering
  std::vector<std::vector<uint32_t>> incident_;  // per point: the slots of the triangles with it as a vertex
};

}  // namespace sweepcdt::detail
