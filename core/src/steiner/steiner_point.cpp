#include "sweepcdt/steiner_point.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace sweepcdt {
namespace {

// Doubles in [0, 1] by their bit patterns, which order them.
double from_bits(uint64_t u) {
  double t;
  std::memcpy(&t, &u, sizeof t);
  return t;
}
uint64_t bits_of(double t) {
  uint64_t u;
  std::memcpy(&u, &t, sizeof u);
  return u;
}
// How many doubles t on either side of the guess the searches try first.
constexpr uint64_t kGuessWindow = 64;
constexpr uint64_t kOne = 0x3FF0000000000000ull;  // the bit pattern of 1.0

struct Range {
  uint64_t first = 1, last = 0;  // bit patterns of t, inclusive; empty when first > last
};

// The t in `within` for which coordinate a + t * d, rounded as point_on_segment() rounds it, equals x.
// The rounded value is monotone in t (non-decreasing for d > 0, non-increasing for d < 0), so the
// answer is one interval, found by two binary searches.
Range preimage(double a, double d, double x, Range within) {
  const auto value = [&](uint64_t u) { return a + from_bits(u) * d; };
  if (d == 0) return value(within.first) == x ? within : Range{};
  // "At or beyond x" in the direction the coordinate moves as t grows.
  const auto reached = [&](uint64_t u) { return d > 0 ? value(u) >= x : value(u) <= x; };
  const auto passed = [&](uint64_t u) { return d > 0 ? value(u) > x : value(u) < x; };
  // Where the exact line meets x: a guess (floating point), whose neighbourhood narrows the searches
  // only where its ends bracket the answer, so the answer is the same with or without it.
  const double guess = std::clamp((x - a) / d, from_bits(within.first), from_bits(within.last));
  const uint64_t g = std::isnan(guess) ? within.first : bits_of(guess);
  const uint64_t near_lo = std::max(within.first, g > kGuessWindow ? g - kGuessWindow : 0);
  const uint64_t near_hi = std::min(within.last, g + kGuessWindow);
  // The first u with reached(u), and the first with passed(u); both predicates are monotone in u.
  const auto first_where = [&](auto&& predicate) {
    uint64_t lo = within.first, hi = within.last + 1;  // answer in [lo, hi]; hi = none
    if (!predicate(near_lo)) lo = near_lo + 1;
    if (predicate(near_hi)) hi = std::min(hi, near_hi);
    while (lo < hi) {
      const uint64_t mid = lo + (hi - lo) / 2;
      if (predicate(mid)) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  };
  // x beyond what the range's ends give: no t between does (the same answer as the searches, without them).
  if (!reached(within.last) || passed(within.first)) return {};
  const uint64_t first = first_where(reached), end = first_where(passed);
  if (first >= end) return {};
  return {first, end - 1};
}

bool from_a_to_b(const double* a, const double* b, const double* x) {
  Range t{1, kOne - 1};  // t in (0, 1): the smallest positive double up to the largest below 1
  // First whether each coordinate is within what t's range gives (a point off the segment mostly is
  // not), then the searches.
  for (int k = 0; k < 3; ++k) {
    const double d = b[k] - a[k], lo = a[k] + from_bits(t.first) * d, hi = a[k] + from_bits(t.last) * d;
    if (x[k] < std::min(lo, hi) || x[k] > std::max(lo, hi)) return false;
  }
  for (int k = 0; k < 3 && t.first <= t.last; ++k) t = preimage(a[k], b[k] - a[k], x[k], t);
  return t.first <= t.last;
}

}  // namespace

bool is_point_on_segment(const double* a, const double* b, const double* x) {
  const auto same = [](const double* p, const double* q) { return p[0] == q[0] && p[1] == q[1] && p[2] == q[2]; };
  if (same(x, a) || same(x, b)) return false;  // t near 0 or 1 rounds to an end: that splits nothing
  return from_a_to_b(a, b, x) || from_a_to_b(b, a, x);
}

}  // namespace sweepcdt
