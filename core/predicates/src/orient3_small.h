// orient3's exact stage for coordinates of a small binary range (orientation.cpp), before the
// general fixed-width stage (arith.h). On CAD parts with Steiner points most exact orient3 calls
// are four exactly coplanar points of one facet; their coordinates — floats, and Steiner points a
// + t (b - a) with t of 20 bits — are multiples of 2^low below 2^(low + 61). Scaled by 2^-low they
// are integers of 61 bits, so:
//   the differences from the fourth point fit in 62 bits (int64),
//   the 2x2 minors of the 3x3 determinant in 125 bits (__int128),
//   and the determinant, at most 189 bits, is summed as 2^64 A + B with A an __int128 and
//   0 <= B < 2^64, which gives its sign.
// Exact, no heap, no limb loops: about a tenth of the general stage's instructions. Inputs out of
// that range (or subnormal, infinite, NaN) return nullopt and take the general stage.
#pragma once
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <optional>

#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::predicates::detail {

inline constexpr int kSmallRangeBits = 61;

// orient<3>'s sign of p (the sign of det[p0 - p3; p1 - p3; p2 - p3]), or nullopt.
inline std::optional<Sign> orient3_small_range(const Coords<4>& p) {
  // Each coordinate as m 2^e with m odd (zero: m = 0), and the range of the nonzero ones' bits.
  std::array<std::array<int64_t, 3>, 4> scaled{};
  std::array<std::array<int, 3>, 4> shift{};
  int lowest = std::numeric_limits<int>::max(), highest = std::numeric_limits<int>::min();
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      const uint64_t bits = std::bit_cast<uint64_t>(p[i][k]);
      const int biased = static_cast<int>((bits >> 52) & 0x7ff);
      const uint64_t fraction = bits & ((uint64_t{1} << 52) - 1);
      if (biased == 0 && fraction == 0) continue;      // zero
      if (biased == 0 || biased == 0x7ff) return std::nullopt;  // subnormal, infinite, NaN
      const uint64_t m = fraction | (uint64_t{1} << 52);
      const int zeros = std::countr_zero(m);
      const int64_t odd = static_cast<int64_t>(m >> zeros);
      scaled[i][k] = (bits >> 63) ? -odd : odd;
      shift[i][k] = biased - 1075 + zeros;  // the value is odd * 2^shift
      lowest = std::min(lowest, shift[i][k]);
      highest = std::max(highest, biased - 1023);  // 2^highest <= |value| < 2^(highest + 1)
    }
  if (lowest == std::numeric_limits<int>::max()) return Sign::Zero;  // every coordinate 0
  if (highest + 1 - lowest > kSmallRangeBits) return std::nullopt;
  std::array<std::array<int64_t, 3>, 4> x;  // the coordinates times 2^-lowest: |x| < 2^61
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) x[i][k] = scaled[i][k] == 0 ? 0 : scaled[i][k] * (int64_t{1} << (shift[i][k] - lowest));
  std::array<std::array<int64_t, 3>, 3> d;  // rows p_i - p_3: |d| < 2^62
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) d[i][k] = x[i][k] - x[3][k];
  using I128 = __int128;
  // Cofactors of row 0 along its columns: |minor| < 2^125.
  const I128 minor[3] = {I128{d[1][1]} * d[2][2] - I128{d[1][2]} * d[2][1],
                         I128{d[1][2]} * d[2][0] - I128{d[1][0]} * d[2][2],
                         I128{d[1][0]} * d[2][1] - I128{d[1][1]} * d[2][0]};
  // det = sum of d[0][k] * minor[k] = 2^64 A + B: each minor split as 2^64 hi + lo (0 <= lo < 2^64),
  // each d * lo (below 2^126 in magnitude) split again the same way.
  I128 high_sum = 0;           // A
  unsigned __int128 low_sum = 0;  // B before its carry: below 3 * 2^64
  for (int k = 0; k < 3; ++k) {
    const I128 hi = minor[k] >> 64;  // arithmetic shift: the floor
    const uint64_t lo = static_cast<uint64_t>(minor[k]);
    const I128 product = I128{d[0][k]} * static_cast<I128>(lo);
    high_sum += I128{d[0][k]} * hi + (product >> 64);
    low_sum += static_cast<uint64_t>(product);
  }
  high_sum += static_cast<I128>(low_sum >> 64);
  const uint64_t low = static_cast<uint64_t>(low_sum);
  if (high_sum > 0) return Sign::Positive;
  if (high_sum < 0) return Sign::Negative;
  return low != 0 ? Sign::Positive : Sign::Zero;
}

}  // namespace sweepcdt::predicates::detail
