// Sign: the result type of every predicate.
#pragma once
#include <cstdint>

#ifdef __FAST_MATH__
#error "sweepcdt's predicates must not be compiled with -ffast-math: their error bounds assume IEEE arithmetic"
#endif

namespace sweepcdt::predicates {

enum class Sign : int8_t { Negative = -1, Zero = 0, Positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}
constexpr int to_int(Sign s) { return static_cast<int>(s); }

}  // namespace sweepcdt::predicates
