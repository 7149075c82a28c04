// WideInt<L>: a signed integer of L 64-bit limbs in two's complement, with wrap-around +, -, *.
// Wrap-around arithmetic is exact whenever the true result fits in 64 L - 1 bits; the exact stage
// of the predicates (arith.h) only uses it after proving that bound for the whole formula.
// No heap allocation: this is what makes exactly degenerate inputs (coplanar CAD faces, grids,
// cospherical points) fast.
#pragma once
#include <array>
#include <cstdint>

namespace sweepcdt::predicates::detail {

template <int L>
struct WideInt {
  std::array<uint64_t, L> limb{};  // little-endian

  static WideInt from_int64(int64_t v) {
    WideInt r;
    r.limb[0] = static_cast<uint64_t>(v);
    for (int i = 1; i < L; ++i) r.limb[i] = v < 0 ? ~uint64_t{0} : 0;
    return r;
  }

  friend WideInt operator+(const WideInt& a, const WideInt& b) {
    WideInt r;
    unsigned __int128 carry = 0;
    for (int i = 0; i < L; ++i) {
      carry += static_cast<unsigned __int128>(a.limb[i]) + b.limb[i];
      r.limb[i] = static_cast<uint64_t>(carry);
      carry >>= 64;
    }
    return r;
  }
  WideInt operator-() const {
    WideInt r;
    unsigned __int128 carry = 1;  // ~x + 1
    for (int i = 0; i < L; ++i) {
      carry += static_cast<uint64_t>(~limb[i]);
      r.limb[i] = static_cast<uint64_t>(carry);
      carry >>= 64;
    }
    return r;
  }
  friend WideInt operator-(const WideInt& a, const WideInt& b) { return a + (-b); }
  friend WideInt operator*(const WideInt& a, const WideInt& b) {
    WideInt r;
    for (int i = 0; i < L; ++i) {
      if (a.limb[i] == 0) continue;
      unsigned __int128 carry = 0;
      for (int j = 0; i + j < L; ++j) {
        carry += static_cast<unsigned __int128>(a.limb[i]) * b.limb[j] + r.limb[i + j];
        r.limb[i + j] = static_cast<uint64_t>(carry);
        carry >>= 64;
      }
    }
    return r;
  }
  int sign() const {
    if (limb[L - 1] >> 63) return -1;
    for (uint64_t x : limb)
      if (x) return 1;
    return 0;
  }
};

}  // namespace sweepcdt::predicates::detail
