#include "dyadic.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace sweepcdt::predicates::detail {

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

double Dyadic::to_double() const {
  long exp = 0;
  const double m = mpz_get_d_2exp(&exp, mantissa_.get_mpz_t());
  return std::ldexp(m, static_cast<int>(exp + exponent_));
}

}  // namespace sweepcdt::predicates::detail
