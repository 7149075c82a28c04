// WideInt<L>: a signed integer of at most L 64-bit limbs in sign-magnitude form, with +, -, *.
// The arithmetic is exact whenever every magnitude fits in L limbs; the exact stage of the
// predicates (arith.h) only uses it after proving that bound (below 2^(64 L - 1)) for the whole
// formula. Only the `size` low limbs of a magnitude are significant, so a product costs
// size(a) * size(b) limb products, not L^2: the values of a predicate are mostly far below the
// bound that chose L (the differences of a degenerate input are small, or zero).
// No heap allocation: this is what makes exactly degenerate inputs (coplanar CAD faces, grids,
// cospherical points) fast.
#pragma once
#include <array>
#include <cstdint>

namespace sweepcdt::predicates::detail {

template <int L>
struct WideInt {
  std::array<uint64_t, L> mag;  // little-endian magnitude; limbs at and above `size` are not read
  int size = 0;                 // significant limbs: mag[size - 1] != 0, or size == 0 for zero
  bool negative = false;        // never set for zero

  WideInt() = default;

  [[gnu::always_inline]] static WideInt from_int64(int64_t v) {
    WideInt r;
    if (v == 0) return r;
    r.negative = v < 0;
    r.mag[0] = r.negative ? uint64_t{0} - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
    r.size = 1;
    return r;
  }

  // (negative ? -1 : 1) * m * 2^shift for m != 0 and shift >= -(trailing zero bits of m), i.e. an
  // integer; it must fit in L limbs (shift + bit length of m <= 64 L). Inputs of a wide binary range.
  static WideInt from_shifted(uint64_t m, int shift, bool negative) {
    WideInt r;
    if (shift < 0) {
      m >>= -shift;  // exact: only zero bits go
      shift = 0;
    }
    const int limb = shift >> 6, bit = shift & 63;
    for (int i = 0; i < limb; ++i) r.mag[i] = 0;
    r.mag[limb] = m << bit;
    r.size = limb + 1;
    const uint64_t high = bit == 0 ? 0 : m >> (64 - bit);
    if (high != 0) r.mag[r.size++] = high;
    r.negative = negative;
    return r;
  }

  // |a| vs |b|: -1, 0, +1.
  static int compare_magnitude(const WideInt& a, const WideInt& b) {
    if (a.size != b.size) return a.size < b.size ? -1 : 1;
    for (int i = a.size - 1; i >= 0; --i)
      if (a.mag[i] != b.mag[i]) return a.mag[i] < b.mag[i] ? -1 : 1;
    return 0;
  }
  // |a| + |b| with the given sign.
  [[gnu::always_inline]] static WideInt add_magnitudes(const WideInt& a, const WideInt& b, bool negative) {
    const WideInt& big = a.size >= b.size ? a : b;
    const WideInt& small = a.size >= b.size ? b : a;
    WideInt r;
    uint64_t carry = 0;
    int i = 0;
    for (; i < small.size; ++i) {
      const unsigned __int128 s = static_cast<unsigned __int128>(big.mag[i]) + small.mag[i] + carry;
      r.mag[i] = static_cast<uint64_t>(s);
      carry = static_cast<uint64_t>(s >> 64);
    }
    for (; i < big.size; ++i) {
      const unsigned __int128 s = static_cast<unsigned __int128>(big.mag[i]) + carry;
      r.mag[i] = static_cast<uint64_t>(s);
      carry = static_cast<uint64_t>(s >> 64);
    }
    r.size = big.size;
    if (carry && r.size < L) r.mag[r.size++] = carry;  // r.size == L: beyond the proven bound, not reached
    r.negative = negative && r.size != 0;
    return r;
  }
  // |big| - |small| (|big| >= |small|) with the given sign.
  [[gnu::always_inline]] static WideInt subtract_magnitudes(const WideInt& big, const WideInt& small, bool negative) {
    WideInt r;
    uint64_t borrow = 0;
    int i = 0;
    for (; i < small.size; ++i) {
      const uint64_t x = big.mag[i], y = small.mag[i];
      const uint64_t d = x - y - borrow;
      borrow = (x < y) || (x - y < borrow) ? 1 : 0;
      r.mag[i] = d;
    }
    for (; i < big.size; ++i) {
      const uint64_t x = big.mag[i];
      r.mag[i] = x - borrow;
      borrow = x < borrow ? 1 : 0;
    }
    int n = big.size;
    while (n > 0 && r.mag[n - 1] == 0) --n;
    r.size = n;
    r.negative = negative && n != 0;
    return r;
  }
  // a + (b with its sign flipped when `flip`).
  [[gnu::always_inline]] static WideInt signed_sum(const WideInt& a, const WideInt& b, bool flip) {
    const bool b_negative = b.negative != flip;
    if (b.size == 0) return a;
    if (a.size == 0) {
      WideInt r = b;
      r.negative = b_negative;
      return r;
    }
    if (a.negative == b_negative) return add_magnitudes(a, b, a.negative);
    const int c = compare_magnitude(a, b);
    if (c == 0) return WideInt();
    return c > 0 ? subtract_magnitudes(a, b, a.negative) : subtract_magnitudes(b, a, b_negative);
  }

  [[gnu::always_inline]] friend WideInt operator+(const WideInt& a, const WideInt& b) { return signed_sum(a, b, false); }
  [[gnu::always_inline]] friend WideInt operator-(const WideInt& a, const WideInt& b) { return signed_sum(a, b, true); }
  WideInt operator-() const {
    WideInt r = *this;
    r.negative = size != 0 && !negative;
    return r;
  }
  [[gnu::always_inline]] friend WideInt operator*(const WideInt& a, const WideInt& b) {
    WideInt r;
    if (a.size == 0 || b.size == 0) return r;
    const int n = a.size + b.size < L ? a.size + b.size : L;  // the proven bound keeps the product in L limbs
    for (int k = 0; k < n; ++k) r.mag[k] = 0;
    for (int i = 0; i < a.size; ++i) {
      unsigned __int128 carry = 0;
      int j = 0;
      for (; j < b.size && i + j < n; ++j) {
        carry += static_cast<unsigned __int128>(a.mag[i]) * b.mag[j] + r.mag[i + j];
        r.mag[i + j] = static_cast<uint64_t>(carry);
        carry >>= 64;
      }
      if (i + j < n) r.mag[i + j] = static_cast<uint64_t>(carry);
    }
    int size = n;
    while (size > 0 && r.mag[size - 1] == 0) --size;
    r.size = size;
    r.negative = size != 0 && (a.negative != b.negative);
    return r;
  }
  int sign() const { return size == 0 ? 0 : (negative ? -1 : 1); }
};

// Int128: the narrowest width of the fixed-width stage, for formulas whose dry run proves every
// value below 2^127 in magnitude: plain two's complement (__int128), so sums and products run without
// the data-dependent branches of WideInt (sizes, magnitude comparisons, carries by loop), which
// mispredict on the dense values of exactly coplanar CAD faces. Exact under the same proof as
// WideInt<2>: no value overflows, so no wrap-around (and no undefined behaviour) ever happens.
struct Int128 {
  __int128 v = 0;

  [[gnu::always_inline]] static Int128 from_int64(int64_t x) { return {x}; }
  [[gnu::always_inline]] friend Int128 operator+(Int128 a, Int128 b) { return {a.v + b.v}; }
  [[gnu::always_inline]] friend Int128 operator-(Int128 a, Int128 b) { return {a.v - b.v}; }
  [[gnu::always_inline]] friend Int128 operator*(Int128 a, Int128 b) { return {a.v * b.v}; }
  [[gnu::always_inline]] Int128 operator-() const { return {-v}; }
  int sign() const { return (v > 0) - (v < 0); }
};

// Int192: the next width, two's complement in three limbs, for values below 2^191 in magnitude: a 3D
// insphere test on float coordinates (CAD parts, scans: 22 to 35 bits of binary range, 133 to 188
// bits of value) fits, where WideInt<4> spent a microsecond on the branches Int128 avoids. Sums and
// products are taken modulo 2^192; since the dry run proves every value below 2^191, each is the
// exact value (a product modulo 2^192 of two's complement operands is the product modulo 2^192).
struct Int192 {
  uint64_t limb[3] = {0, 0, 0};  // little-endian two's complement

  [[gnu::always_inline]] static Int192 from_int64(int64_t x) {
    const auto high = static_cast<uint64_t>(x >> 63);  // sign extension: all ones or all zeros
    return {{static_cast<uint64_t>(x), high, high}};
  }
  [[gnu::always_inline]] friend Int192 operator+(const Int192& a, const Int192& b) {
    Int192 r;
    unsigned __int128 s = static_cast<unsigned __int128>(a.limb[0]) + b.limb[0];
    r.limb[0] = static_cast<uint64_t>(s);
    s = (s >> 64) + a.limb[1] + b.limb[1];
    r.limb[1] = static_cast<uint64_t>(s);
    r.limb[2] = a.limb[2] + b.limb[2] + static_cast<uint64_t>(s >> 64);
    return r;
  }
  [[gnu::always_inline]] Int192 operator-() const {
    // ~x + 1
    Int192 r;
    unsigned __int128 s = static_cast<unsigned __int128>(~limb[0]) + 1;
    r.limb[0] = static_cast<uint64_t>(s);
    s = (s >> 64) + ~limb[1];
    r.limb[1] = static_cast<uint64_t>(s);
    r.limb[2] = ~limb[2] + static_cast<uint64_t>(s >> 64);
    return r;
  }
  [[gnu::always_inline]] friend Int192 operator-(const Int192& a, const Int192& b) { return a + -b; }
  [[gnu::always_inline]] friend Int192 operator*(const Int192& a, const Int192& b) {
    using U = unsigned __int128;
    const U p00 = static_cast<U>(a.limb[0]) * b.limb[0];
    const U p01 = static_cast<U>(a.limb[0]) * b.limb[1];
    const U p10 = static_cast<U>(a.limb[1]) * b.limb[0];
    Int192 r;
    r.limb[0] = static_cast<uint64_t>(p00);
    const U middle = (p00 >> 64) + static_cast<uint64_t>(p01) + static_cast<uint64_t>(p10);  // < 3 * 2^64
    r.limb[1] = static_cast<uint64_t>(middle);
    r.limb[2] = static_cast<uint64_t>(middle >> 64) + static_cast<uint64_t>(p01 >> 64) + static_cast<uint64_t>(p10 >> 64) +
                a.limb[0] * b.limb[2] + a.limb[1] * b.limb[1] + a.limb[2] * b.limb[0];  // modulo 2^64
    return r;
  }
  int sign() const {
    if (static_cast<int64_t>(limb[2]) < 0) return -1;
    return (limb[0] | limb[1] | limb[2]) != 0 ? 1 : 0;
  }
};

}  // namespace sweepcdt::predicates::detail
