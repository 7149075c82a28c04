// Internal: the two number systems a predicate formula is evaluated in, the generic determinant, and
// filtered_sign(), which runs a formula in the filter first and exactly only if needed.
//
// A formula is a generic callable  formula(Arith& a) -> Arith::T  built only from a.diff(x, y) (an
// input-coordinate difference), +, -, * — so one text is the filter, the bit-size dry run, and the
// exact evaluations (fixed-width integers, or GMP dyadics for inputs of extreme binary range).
#pragma once
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "approx.h"
#include "dd_approx.h"
#include "dyadic.h"
#include "stats_counters.h"
#include "wide_int.h"
#include "sweepcdt/predicates/sign.h"

namespace sweepcdt::predicates::detail {

// one(): the constant 1, for formulas with constant entries (the perturbation's unit columns). Such a
// formula must still be homogeneous in the differences for the fixed-width stage (see exact_value).
struct FilterArith {
  using T = Approx;
  static T diff(double a, double b) { return approx_difference(a, b); }
  static T one() { return {1.0, 1.0, 0}; }  // exact: no rounding
};

struct ExactArith {
  using T = Dyadic;
  static T diff(double a, double b) { return Dyadic(a) - Dyadic(b); }
  static T one() { return Dyadic(1.0); }
};

inline Sign sign_of(const Dyadic& d) { return static_cast<Sign>(d.sign()); }

// A dry run of a formula: records the binary range of its inputs and a bound on the size of its
// value, as  |value| < 2^(degree * (B + 1) + extra)  when every input is an integer of at most B bits
// (differences have B + 1). Sums add one bit; products add degrees and extras.
struct BitBound {
  int degree = 0, extra = 0;
  friend BitBound operator+(const BitBound& a, const BitBound& b) {
    return {std::max(a.degree, b.degree), std::max(a.extra, b.extra) + 1};
  }
  friend BitBound operator-(const BitBound& a, const BitBound& b) { return a + b; }
  friend BitBound operator*(const BitBound& a, const BitBound& b) { return {a.degree + b.degree, a.extra + b.extra}; }
  BitBound operator-() const { return *this; }
};

// x = (negative ? -1 : 1) * mantissa * 2^exponent, read off the IEEE-754 bits (subnormals included).
struct Decomposed {
  uint64_t mantissa;
  int exponent;
  bool negative;
};
inline Decomposed decompose(double x) {
  const auto bits = std::bit_cast<uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  uint64_t mantissa = bits & ((uint64_t{1} << 52) - 1);
  if (biased != 0) mantissa |= uint64_t{1} << 52;
  return {mantissa, biased == 0 ? -1074 : biased - 1075, (bits >> 63) != 0};
}

struct ScanArith {
  using T = BitBound;
  int lowest_bit = std::numeric_limits<int>::max();   // exponent of the lowest set bit of any input
  int highest_bit = std::numeric_limits<int>::min();  // exponent of the highest set bit of any input
  bool finite = true;
  [[gnu::always_inline]] void see(double x) {
    finite = finite && std::isfinite(x);
    const Decomposed d = decompose(x);
    if (d.mantissa == 0) return;
    lowest_bit = std::min(lowest_bit, d.exponent + std::countr_zero(d.mantissa));
    highest_bit = std::max(highest_bit, d.exponent + 63 - std::countl_zero(d.mantissa));
  }
  [[gnu::always_inline]] T diff(double a, double b) {
    see(a);
    see(b);
    return {1, 0};
  }
  static T one() { return {0, 1}; }  // |1| < 2^1
};

// Inputs scaled by 2^-lowest_bit are integers below 2^62; evaluated in Int (WideInt<L> or Int128).
template <class Int>
struct IntArith {
  using T = Int;
  int lowest_bit;
  [[gnu::always_inline]] int64_t scaled(double x) const {
    const Decomposed d = decompose(x);
    if (d.mantissa == 0) return 0;  // a zero's exponent is arbitrary: no shift (it could exceed 63)
    const int shift = d.exponent - lowest_bit;  // >= -(trailing zeros of the mantissa): exact
    const auto magnitude = static_cast<int64_t>(shift >= 0 ? d.mantissa << shift : d.mantissa >> -shift);
    return d.negative ? -magnitude : magnitude;
  }
  [[gnu::always_inline]] T diff(double a, double b) const { return T::from_int64(scaled(a)) - T::from_int64(scaled(b)); }
  static T one() { return T::from_int64(1); }  // unscaled: homogeneous formulas only
};
template <int L>
using WideArith = IntArith<WideInt<L>>;
using Int128Arith = IntArith<Int128>;

// The same for inputs whose binary range exceeds 62 bits (CAD coordinates such as 50 beside a
// rounding residue 3.7e-15 of cos(90 degrees)): each scaled input is a multi-limb integer, built from
// its mantissa by a shift. A product still costs size(a) * size(b) limb products.
template <int L>
struct ShiftedArith {
  using T = WideInt<L>;
  int lowest_bit;
  [[gnu::always_inline]] T scaled(double x) const {
    const Decomposed d = decompose(x);
    if (d.mantissa == 0) return T();
    return T::from_shifted(d.mantissa, d.exponent - lowest_bit, d.negative);
  }
  [[gnu::always_inline]] T diff(double a, double b) const { return scaled(a) - scaled(b); }
  static T one() { return T::from_int64(1); }  // unscaled: homogeneous formulas only
};

// The limbs the fixed-width stage needs for a formula of the given dry-run bound over finite inputs
// spanning input_bits bits (every intermediate value is below 2^value_bits, and so is every scaled
// input), or 0 when none of the widths offered suffices (then GMP). 16 limbs: the power comparisons
// of the sphere sweep (degree 8) on CAD coordinates beside rounding residues (20 beside 1e-17, a
// range of about 115 bits) need about 940 bits; GMP's dyadics took a third of such a run.
inline int fixed_width_limbs(const BitBound& bound, int input_bits) {
  const long value_bits = static_cast<long>(bound.degree) * (input_bits + 1) + bound.extra;
  for (int limbs : {2, 4, 8, 12, 16})
    if (value_bits < 64L * limbs) return limbs;
  return 0;
}

// Exact value of a formula as a Dyadic, computed in fixed-width integers when the dry run proves
// they suffice. The formula must be homogeneous (every term of the dry run's degree): the integer
// result is then the value scaled by 2^(-degree * lowest_bit), which the exponent undoes.
template <class Formula>
Dyadic exact_value(const Formula& formula) {
  ScanArith scan;
  const BitBound bound = formula(scan);
  if (scan.finite && scan.lowest_bit == std::numeric_limits<int>::max()) return Dyadic();
  const int input_bits = scan.highest_bit - scan.lowest_bit + 1;
  if (scan.finite && input_bits <= 62) {
    const int value_bits = bound.degree * (input_bits + 1) + bound.extra;
    const long exponent = static_cast<long>(bound.degree) * scan.lowest_bit;
    const auto run = [&](auto arith) {
      const auto v = formula(arith);
      return Dyadic::from_magnitude(v.mag.data(), v.size, v.negative, exponent);
    };
    if (value_bits < 4 * 64) return run(WideArith<4>{scan.lowest_bit});
    if (value_bits < 8 * 64) return run(WideArith<8>{scan.lowest_bit});
  } else if (scan.finite) {
    const long exponent = static_cast<long>(bound.degree) * scan.lowest_bit;
    const auto run = [&](auto arith) {
      const auto v = formula(arith);
      return Dyadic::from_magnitude(v.mag.data(), v.size, v.negative, exponent);
    };
    const int limbs = fixed_width_limbs(bound, input_bits);
    if (limbs != 0 && limbs <= 4) return run(ShiftedArith<4>{scan.lowest_bit});
    if (limbs != 0 && limbs <= 8) return run(ShiftedArith<8>{scan.lowest_bit});
  }
  ExactArith exact;
  return formula(exact);
}

// Exact sign of a formula: fixed-width integers when the dry run proves they suffice, else dyadics.
template <class Formula>
Sign exact_sign(const Formula& formula) {
  count_exact();
  ScanArith scan;
  const BitBound bound = formula(scan);
  if (scan.finite && scan.lowest_bit == std::numeric_limits<int>::max()) return Sign::Zero;  // all inputs 0
  const int input_bits = scan.highest_bit - scan.lowest_bit + 1;
  const bool narrow = scan.finite && input_bits <= 62;  // non-finite input: the dyadic path reports it
  const int value_bits = narrow ? bound.degree * (input_bits + 1) + bound.extra : 0;  // must stay below the sign bit
  const auto run = [&](auto arith) { return static_cast<Sign>(formula(arith).sign()); };
  if (narrow && value_bits < 2 * 64) return run(Int128Arith{scan.lowest_bit});  // |value| < 2^127: cheap
  // Up to four limbs the integers cost no more than the double-words below (a 3D insphere test on
  // float CAD coordinates, 138 bits: 0.9 us in double-words, 1.0 us in WideInt<4>, 0.6 us in
  // Int192), and there the exact calls are mostly exact zeros, which the double-words cannot
  // decide: cospherical CAD vertices, such as a hole's two circles (all 4032 of
  // plate_with_holes_std's exact 3D insphere tests, 2683 of filleted_box_fine's 2700). So straight
  // to the integers.
  if (narrow && value_bits < 3 * 64) return run(IntArith<Int192>{scan.lowest_bit});
  if (narrow && value_bits < 4 * 64) return run(WideArith<4>{scan.lowest_bit});
  // Wider: double-words first (dd_approx.h), which decide the signs that are tiny but not zero
  // without multi-limb integers (exact zeros, as on an integer sphere, pay for both: so not above).
  DDFilterArith dd;
  if (const auto s = certain_sign(formula(dd))) return *s;
  if (narrow) {
    if (value_bits < 8 * 64) return run(WideArith<8>{scan.lowest_bit});
    if (value_bits < 12 * 64) return run(WideArith<12>{scan.lowest_bit});
  } else if (scan.finite) {  // a wide binary range: multi-limb inputs
    switch (fixed_width_limbs(bound, input_bits)) {
      case 2: return run(ShiftedArith<2>{scan.lowest_bit});
      case 4: return run(ShiftedArith<4>{scan.lowest_bit});
      case 8: return run(ShiftedArith<8>{scan.lowest_bit});
      case 12: return run(ShiftedArith<12>{scan.lowest_bit});
      case 16: return run(ShiftedArith<16>{scan.lowest_bit});
      default: break;
    }
  }
  ExactArith exact;
  return sign_of(formula(exact));
}

template <class Formula>
Sign filtered_sign(const Formula& formula) {
  FilterArith filter;
  if (const auto s = certain_sign(formula(filter))) {
    count_filtered();
    return *s;
  }
  return exact_sign(formula);
}

// The non-empty row subsets of an N-row matrix ordered by size, for the determinant below.
struct RowSubset {
  unsigned mask;
  int size;
};
template <int N>
constexpr std::array<RowSubset, (1u << N) - 1> subsets_by_size() {
  std::array<RowSubset, (1u << N) - 1> subsets{};
  std::size_t next = 0;
  for (int size = 1; size <= N; ++size)
    for (unsigned mask = 1; mask < (1u << N); ++mask)
      if (std::popcount(mask) == size) subsets[next++] = {mask, size};
  return subsets;
}

// det of an N x N row-major matrix by Laplace expansion, memoising the minors of the first k columns
// over row subsets (bitmask -> minor): O(N 2^N) products instead of O(N!).
template <int N, class T>
T determinant(const std::array<T, N * N>& a) {
  if constexpr (N == 1) {
    return a[0];
  } else {
    static constexpr auto subsets = subsets_by_size<N>();
    std::array<T, (1u << N)> minor;  // every entry read is written first (no zero-fill of wide ints)
    for (int r = 0; r < N; ++r) minor[1u << r] = a[r * N];
    for (std::size_t m = N; m < subsets.size(); ++m) {
      const unsigned mask = subsets[m].mask;
      const int k = subsets[m].size;
      // Expand the k x k minor (rows of mask, columns 0..k-1) along its last column k-1.
      T sum{};
      int position = 0;
      for (int r = 0; r < N; ++r) {
        if (!((mask >> r) & 1u)) continue;
        T term = a[r * N + k - 1] * minor[mask & ~(1u << r)];
        const bool negative = ((position + k - 1) & 1) != 0;
        if (position == 0)
          sum = negative ? -term : term;
        else
          sum = negative ? sum - term : sum + term;
        ++position;
      }
      minor[mask] = sum;
    }
    return minor[(1u << N) - 1];
  }
}

// det [p_i - p_D]_{i<D}: D! times the signed volume of the simplex p_0..p_D.
template <int D, class Arith, class Points>
typename Arith::T orient_det(Arith& arith, const Points& p) {
  using T = typename Arith::T;
  std::array<T, D * D> m;
  for (int i = 0; i < D; ++i)
    for (int k = 0; k < D; ++k) m[i * D + k] = arith.diff(p[i][k], p[D][k]);
  return determinant<D>(m);
}

// The coefficient of q_k in the affine function q -> det [[f_0,1],...,[f_{D-1},1],[q,1]]
// = (-1)^{D+k} orient_{D-1}(f projected without axis k). Component k of f's normal vector.
template <int D, class Arith, class Points>
typename Arith::T normal_component(Arith& arith, const Points& f, int k) {
  using T = typename Arith::T;
  constexpr int M = D - 1;
  std::array<T, M * M> m;
  for (int i = 0; i < M; ++i)
    for (int col = 0; col < M; ++col) {
      const int axis = col < k ? col : col + 1;  // every axis but k
      m[i * M + col] = arith.diff(f[i][axis], f[M][axis]);
    }
  T det = determinant<M>(m);
  return ((D + k) & 1) ? -det : det;
}

}  // namespace sweepcdt::predicates::detail
