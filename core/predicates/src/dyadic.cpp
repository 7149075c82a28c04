#include "dyadic.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace sweepcdt::predicates::detail {

Dyadic Dyadic::from_magnitude(const uint64_t* limbs, int count, bool negative, long exponent) {
  Dyadic r;
  if (count == 0) return r;
  mpz_import(r.mantissa_.get_mpz_t(), static_cast<size_t>(count), -1, sizeof(uint64_t), 0, 0, limbs);
  if (negative) mpz_neg(r.mantissa_.get_mpz_t(), r.mantissa_.get_mpz_t());
  r.exponent_ = exponent;
  return r;
}

Dyadic::Dyadic(double d) {
  if (!std::isfinite(d)) throw std::invalid_argument("exact arithmetic on a non-finite coordinate");
  if (d == 0.0) return;
  int exp = 0;
  const double fraction = std::frexp(d, &exp);  // d = fraction * 2^exp, 0.5 <= |fraction| < 1
  const auto mantissa = static_cast<int64_t>(std::ldexp(fraction, 53));  // exact: 53-bit integer
  mantissa_ = static_cast<long>(mantissa);
  exponent_ = exp - 53;
}

Dyadic operator+(const Dyadic& a, const Dyadic& b) {
  if (b.sign() == 0) return a;
  if (a.sign() == 0) return b;
  Dyadic r;
  if (a.exponent_ >= b.exponent_) {
    mpz_mul_2exp(r.mantissa_.get_mpz_t(), a.mantissa_.get_mpz_t(), a.exponent_ - b.exponent_);
    r.mantissa_ += b.mantissa_;
    r.exponent_ = b.exponent_;
  } else {
    mpz_mul_2exp(r.mantissa_.get_mpz_t(), b.mantissa_.get_mpz_t(), b.exponent_ - a.exponent_);
    r.mantissa_ += a.mantissa_;
    r.exponent_ = a.exponent_;
  }
  return r;
}

Dyadic Dyadic::operator-() const {
  Dyadic r = *this;
  r.mantissa_ = -r.mantissa_;
  return r;
}

Dyadic operator-(const Dyadic& a, const Dyadic& b) { return a + (-b); }

Dyadic operator*(const Dyadic& a, const Dyadic& b) {
  Dyadic r;
  if (a.sign() == 0 || b.sign() == 0) return r;
  r.mantissa_ = a.mantissa_ * b.mantissa_;
  r.exponent_ = a.exponent_ + b.exponent_;
  return r;
}

// Rounded to nearest, ties to even (mpz_get_d would truncate). The mantissa is first rounded to the
// number of bits the result can hold — 53, or fewer in the subnormal range — so the final scaling
// is exact (or overflows to infinity, which is then the correctly rounded result).
double Dyadic::to_double() const {
  if (sign() == 0) return 0.0;
  mpz_class magnitude = abs(mantissa_);
  const long bits = static_cast<long>(mpz_sizeinbase(magnitude.get_mpz_t(), 2));
  long exp = exponent_;
  const long top = exp + bits - 1;  // exponent of the leading bit
  const long keep = std::min(53L, top + 1075);  // 2^-1074 is the least subnormal bit
  if (keep < bits) {
    const long shift = bits - keep;
    mpz_class quotient, remainder, half;
    mpz_fdiv_q_2exp(quotient.get_mpz_t(), magnitude.get_mpz_t(), shift);
    mpz_fdiv_r_2exp(remainder.get_mpz_t(), magnitude.get_mpz_t(), shift);
    mpz_setbit(half.get_mpz_t(), shift - 1);
    const int c = cmp(remainder, half);
    if (c > 0 || (c == 0 && mpz_odd_p(quotient.get_mpz_t()))) ++quotient;
    magnitude = quotient;
    exp += shift;
  }
  const double m = magnitude.get_d();  // exact: at most 2^53
  const double r = std::ldexp(m, static_cast<int>(std::clamp(exp, -100000L, 100000L)));
  return mantissa_ < 0 ? -r : r;
}

}  // namespace sweepcdt::predicates::detail
