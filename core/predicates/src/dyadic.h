// Dyadic: an exact number m * 2^e (m a GMP integer). Every finite double is one, and sums, differences
// and products of dyadics are dyadic, so every predicate polynomial is evaluated exactly — without the
// gcd cost of rationals.
#pragma once
#include <gmpxx.h>

#include <cstdint>

namespace sweepcdt::predicates::detail {

class Dyadic {
 public:
  Dyadic() = default;  // zero
  explicit Dyadic(double d);  // exact; d must be finite
  // (negative ? -1 : 1) times the magnitude in `limbs` (little-endian, `count` limbs) times 2^exponent.
  static Dyadic from_magnitude(const uint64_t* limbs, int count, bool negative, long exponent);

  friend Dyadic operator+(const Dyadic& a, const Dyadic& b);
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b);
  friend Dyadic operator*(const Dyadic& a, const Dyadic& b);
  Dyadic operator-() const;

  int sign() const { return sgn(mantissa_); }
  double to_double() const;  // nearest double (for reporting only)

 private:
  mpz_class mantissa_;
  long exponent_ = 0;
};

}  // namespace sweepcdt::predicates::detail
