// orient2's and orient3's exact stage for coordinates of a small binary range (orientation.cpp),
// before the general fixed-width stage (arith.h). On CAD parts with Steiner points most exact
// orientation calls are points of one facet, exactly coplanar (or collinear in a facet's
// projection); their coordinates — floats, and Steiner points a + t (b - a) with t of 20 bits — are
// multiples of 2^low below 2^(low + 61). Scaled by 2^-low they are integers of 61 bits, so:
//   the differences from the last point fit in 62 bits (int64),
//   a 2x2 determinant of them in 125 bits (__int128): orient2's value, orient3's minors,
//   and orient3's determinant, at most 189 bits, is summed as 2^64 A + B with A an __int128 and
//   0 <= B < 2^64, which gives its sign.
// Exact, no heap, no limb loops: a fraction of the general stage's instructions. Inputs out of that
// range (or infinite, NaN) return nullopt and take the general stage.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <optional>

#include "arith.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::predicates::detail {

inline constexpr int kSmallRangeBits = 61;

// The rows p_i - p_N (i < N) of N + 1 points in D = N dimensions, scaled by a common power of two
// to integers: |entry| < 2^62 (all 0 when every coordinate is 0). The scan and the scaling are the
// general stage's (arith.h: ScanArith, IntArith). Nullopt when the nonzero coordinates span more
// than kSmallRangeBits bits, or one is infinite or NaN.
template <int N>
std::optional<std::array<std::array<int64_t, N>, N>> small_range_differences(const Coords<N + 1>& p) {
  ScanArith scan;
  for (int i = 0; i <= N; ++i)
    for (int k = 0; k < N; ++k) scan.see(p[i][k]);
  std::array<std::array<int64_t, N>, N> d{};
  if (!scan.finite) return std::nullopt;
  if (scan.lowest_bit == std::numeric_limits<int>::max()) return d;  // every coordinate 0
  if (scan.highest_bit + 1 - scan.lowest_bit > kSmallRangeBits) return std::nullopt;
  const IntArith<Int128> scaling{scan.lowest_bit};  // |scaled| < 2^61
  for (int i = 0; i < N; ++i)
    for (int k = 0; k < N; ++k) d[i][k] = scaling.scaled(p[i][k]) - scaling.scaled(p[N][k]);
  return d;
}

inline Sign sign_of_128(__int128 x) { return x > 0 ? Sign::Positive : x < 0 ? Sign::Negative : Sign::Zero; }

// orient<2>'s sign of p (the sign of det[p0 - p2; p1 - p2]), or nullopt.
inline std::optional<Sign> orient2_small_range(const Coords<3>& p) {
  const auto d = small_range_differences<2>(p);
  if (!d) return std::nullopt;
  return sign_of_128(__int128{(*d)[0][0]} * (*d)[1][1] - __int128{(*d)[0][1]} * (*d)[1][0]);
}

// orient<3>'s sign of p (the sign of det[p0 - p3; p1 - p3; p2 - p3]), or nullopt.
inline std::optional<Sign> orient3_small_range(const Coords<4>& p) {
  const auto rows = small_range_differences<3>(p);
  if (!rows) return std::nullopt;
  const auto& d = *rows;
  using I128 = __int128;
  // Cofactors of row 0 along its columns: |minor| < 2^125.
  const I128 minor[3] = {I128{d[1][1]} * d[2][2] - I128{d[1][2]} * d[2][1],
                         I128{d[1][2]} * d[2][0] - I128{d[1][0]} * d[2][2],
                         I128{d[1][0]} * d[2][1] - I128{d[1][1]} * d[2][0]};
  // det = sum of d[0][k] * minor[k] = 2^64 A + B: each minor split as 2^64 hi + lo (0 <= lo < 2^64),
  // each d * lo (below 2^126 in magnitude) split again the same way.
  I128 high_sum = 0;              // A
  unsigned __int128 low_sum = 0;  // B before its carry: below 3 * 2^64
  for (int k = 0; k < 3; ++k) {
    const I128 hi = minor[k] >> 64;  // arithmetic shift: the floor
    const uint64_t lo = static_cast<uint64_t>(minor[k]);
    const I128 product = I128{d[0][k]} * static_cast<I128>(lo);
    high_sum += I128{d[0][k]} * hi + (product >> 64);
    low_sum += static_cast<uint64_t>(product);
  }
  high_sum += static_cast<I128>(low_sum >> 64);
  if (high_sum != 0) return sign_of_128(high_sum);
  return static_cast<uint64_t>(low_sum) != 0 ? Sign::Positive : Sign::Zero;
}

}  // namespace sweepcdt::predicates::detail
