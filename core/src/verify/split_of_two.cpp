// is_split_of_two() (split_of_two.h). A split point x of a and b lies on their segment up to the
// rounding of one construction, so seen from x, a and b lie in almost opposite directions: sorting
// the candidates by the direction of the line from x to them leaves only the pairs with almost the
// same key to try, each with the exact test. The filter only ever skips pairs that cannot pass the
// exact test, by the bound derived below, so the answer is exactly that of trying every pair.
//
// The bound. x = fl(a + fl(t fl(b - a))) coordinate by coordinate for a double t in (0, 1)
// (steiner_point.h; or the same from b to a). With Δ = b - a, round to nearest (relative error
// u = 2^-53, and 2^-1075 absolute where a product underflows; differences and sums that underflow
// are exact), per coordinate k:
//     |x_k - a_k - t Δ_k|  <=  u/(1-u) |x_k| + (2u + u²) |Δ_k| + 2^-1075  <=  e_k,
//     e_k = 2^-51 (|x_k| + |Δ_k|) + 2^-1074.
// In two coordinates i, j, with v = a - x and w = b - x (so Δ = w - v), the residual r = x - a - tΔ
// gives cross(v, w) = r_j Δ_i - r_i Δ_j, hence |cross(v, w)| <= e_i |Δ_j| + e_j |Δ_i| (the same
// from b to a). Let α = |v|_∞, β = |w|_∞, S = max(|x_i|, |x_j|), R >= α, β; then |Δ_k| <= α + β
// and the sine of the angle between v and w is at most
//     (e_i + e_j)(α + β) / (α β)  <=  [2^-50 (S + 2R) + 2^-1073] (1/α + 1/β).
// For α, β >= ρ = 2^-33 (S + 2R) (and ρ >= 2^-1000) that is at most 2^-16 + 2^-72: the lines
// x→a and x→b differ by an angle below π/2 (2^-16 + 2^-72) < 1.6 · 2^-16. A line's key
// (line_key) moves by at most the angle the line turns, so the keys of a and b differ, around
// their circle of length 2, by less than 1.6 · 2^-16 plus the rounding of the keys and of v, w,
// S, R, ρ themselves (a few u each, relative) — well within kWindow = 2^-14.
// Candidates nearer than ρ to x (in the plane i, j) are tried with every other candidate.
//
// Cost: the sort, plus the pairs within kWindow of each other. That is few unless many candidates
// lie on one line through x (as seen in the plane i, j); then it tends to the exhaustive k²/2, of
// which it still skips every pair whose box does not hold x.
#include "split_of_two.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "sweepcdt/steiner_point.h"

namespace sweepcdt::detail {
namespace {

// The bound above: candidates nearer x than 2^kNear (S + 2R) are tried with every other one; the
// others' keys differ by less than kWindow when they split x.
constexpr int kNear = -33;
constexpr double kWindow = 0x1p-14;

// The direction of the line through 0 and (x, y) ≠ (0, 0) as a number in [0, 2): its angle θ in
// [0, π) from the x axis, squeezed monotonically (y/(x+y) for θ <= π/2, else 1 + |x|/(y+|x|)), with
// derivative in [1/2, 1]; keys near 2 meet keys near 0 (θ near π is θ near 0).
double line_key(double x, double y) {
  if (y < 0 || (y == 0 && x < 0)) x = -x, y = -y;
  return x >= 0 ? y / (x + y) : 1 + -x / (y - x);
}

bool holds(const double* x, const double* a, const double* b) {
  for (int k = 0; k < 3; ++k)
    if (x[k] < std::min(a[k], b[k]) || std::max(a[k], b[k]) < x[k]) return false;
  return true;
}

}  // namespace

bool is_split_of_two(std::span<const double> points, uint32_t s, std::span<const uint32_t> candidates) {
  const auto p = [&](uint32_t v) { return points.data() + 3 * std::size_t{v}; };
  const double* x = p(s);
  // Rounding is monotone, so a split point lies in the box of its two points: a cheap exact test first.
  const auto splits = [&](uint32_t a, uint32_t b) { return holds(x, p(a), p(b)) && is_point_on_segment(p(a), p(b), x); };

  // The plane i, j: drop the axis the candidates spread least along (any choice is correct; a flat
  // facet seen edge-on would make most candidates "near" below).
  std::array<double, 3> lo{x[0], x[1], x[2]}, hi = lo;
  for (uint32_t c : candidates)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p(c)[k]), hi[k] = std::max(hi[k], p(c)[k]);
  int dropped = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[k] - lo[k] < hi[dropped] - lo[dropped]) dropped = k;
  const int i = dropped == 0 ? 1 : 0, j = dropped == 2 ? 1 : 2;

  double reach = 0;  // R
  for (uint32_t c : candidates) reach = std::max({reach, std::abs(p(c)[i] - x[i]), std::abs(p(c)[j] - x[j])});
  const double rho = std::max(std::ldexp(std::max(std::abs(x[i]), std::abs(x[j])) + 2 * reach, kNear), 0x1p-1000);
  if (!std::isfinite(rho)) {  // coordinates near overflow: no bound, every pair
    for (std::size_t a = 0; a < candidates.size(); ++a)
      for (std::size_t b = a + 1; b < candidates.size(); ++b)
        if (splits(candidates[a], candidates[b])) return true;
    return false;
  }

  struct Line {
    double key;
    uint32_t id;
  };
  std::vector<Line> far;
  far.reserve(candidates.size());
  for (uint32_t c : candidates) {
    const double vi = p(c)[i] - x[i], vj = p(c)[j] - x[j];
    if (std::max(std::abs(vi), std::abs(vj)) >= rho) {
      far.push_back({line_key(vi, vj), c});
      continue;
    }
    for (uint32_t other : candidates)  // near x: its line says little
      if (other != c && splits(c, other)) return true;
  }
  std::sort(far.begin(), far.end(), [](const Line& a, const Line& b) { return a.key < b.key; });
  const std::size_t m = far.size();
  for (std::size_t q = 0; q < m; ++q)
    for (std::size_t r = 1; r < m; ++r) {  // the following keys around the circle, while within the window
      const std::size_t next = q + r < m ? q + r : q + r - m;
      if (far[next].key + (q + r < m ? 0 : 2) - far[q].key > kWindow) break;
      if (splits(far[q].id, far[next].id)) return true;
    }
  return false;
}

}  // namespace sweepcdt::detail
