// TrianglePieces (core/src/steiner/triangle_pieces.h) splits triangles in place and links the new
// pieces in order; checked against splitting the whole list in one scan per pass (what refinement
// did before: each triangle replaced by its pieces where it stands), on a triangulated grid with
// random splits over many passes, ordered at random moments.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <unordered_map>
#include <vector>

#include "steiner/facet_groups.h"
#include "steiner/triangle_pieces.h"

using namespace sweepcdt;
using namespace sweepcdt::detail;

namespace {

using Triangle = std::array<uint32_t, 3>;

struct Surface {
  std::vector<Triangle> tris;
  std::vector<uint32_t> original;
  std::vector<char> unflipped;
  std::vector<uint32_t> steiner_on;
};

// The reference: the whole list rebuilt in one scan, each triangle followed by its pieces.
void split_in_one_scan(Surface& s, const std::unordered_map<uint64_t, uint32_t>& new_point, uint32_t first_steiner) {
  Surface out;
  out.steiner_on = s.steiner_on;
  for (std::size_t j = 0; j < s.tris.size(); ++j) {
    std::vector<Triangle> work{s.tris[j]};
    for (std::size_t w = 0; w < work.size(); ++w)
      for (int i = 0; i < 3; ++i) {
        const auto it = new_point.find(edge_key(work[w][i], work[w][(i + 1) % 3]));
        if (it == new_point.end()) continue;
        uint32_t& on = out.steiner_on[it->second - first_steiner];
        if (on == kNone) on = s.original[j];
        Triangle second = work[w];
        work[w][(i + 1) % 3] = it->second;
        second[i] = it->second;
        work.push_back(second);
        --w;
        break;
      }
    for (const Triangle& t : work) {
      out.tris.push_back(t);
      out.original.push_back(s.original[j]);
      out.unflipped.push_back(work.size() > 1 || s.unflipped[j]);
    }
  }
  s = std::move(out);
}

// An n x n grid of squares, two triangles each, both sides of every interior edge.
Surface grid(uint32_t n) {
  Surface s;
  const auto id = [&](uint32_t i, uint32_t j) { return i * (n + 1) + j; };
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = 0; j < n; ++j) {
      s.tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (uint32_t t = 0; t < s.tris.size(); ++t) s.original.push_back(t), s.unflipped.push_back(0);
  return s;
}

}  // namespace

TEST(TrianglePieces, SplitsAsOneScanPerPassWould) {
  constexpr uint32_t kN = 6;
  const uint32_t first_steiner = (kN + 1) * (kN + 1);
  for (uint32_t seed = 0; seed < 20; ++seed) {
    std::mt19937 rng(seed);
    Surface reference = grid(kN), pieces_surface = reference;
    TrianglePieces pieces(pieces_surface.tris, pieces_surface.original, pieces_surface.unflipped);
    uint32_t next_point = first_steiner;
    for (int pass = 0; pass < 40; ++pass) {
      // A few edges of the current triangles, some sharing a triangle or an end.
      std::unordered_map<uint64_t, uint32_t> new_point;
      const std::size_t splits = 1 + rng() % 4;
      for (std::size_t k = 0; k < splits; ++k) {
        const Triangle& t = reference.tris[rng() % reference.tris.size()];
        const int i = static_cast<int>(rng() % 3);
        if (new_point.emplace(edge_key(t[i], t[(i + 1) % 3]), next_point).second) ++next_point;
      }
      reference.steiner_on.resize(next_point - first_steiner, kNone);
      pieces_surface.steiner_on.resize(next_point - first_steiner, kNone);
      split_in_one_scan(reference, new_point, first_steiner);
      pieces.split(new_point, next_point, pieces_surface.steiner_on, first_steiner);
      if (rng() % 5 == 0 || pass == 39) {
        pieces.put_in_order();
        ASSERT_EQ(pieces_surface.tris, reference.tris) << "seed " << seed << ", pass " << pass;
        ASSERT_EQ(pieces_surface.original, reference.original);
        ASSERT_EQ(pieces_surface.unflipped, reference.unflipped);
      }
      ASSERT_EQ(pieces_surface.steiner_on, reference.steiner_on) << "seed " << seed << ", pass " << pass;
    }
  }
}

TEST(TrianglePieces, NothingToSplitChangesNothing) {
  Surface s = grid(2);
  const Surface before = s;
  TrianglePieces pieces(s.tris, s.original, s.unflipped);
  pieces.split({}, 9, s.steiner_on, 9);
  pieces.put_in_order();
  EXPECT_EQ(s.tris, before.tris);
  EXPECT_EQ(s.original, before.original);
}
