// The priority-queue keys of SWEEPCDT (paper §3), compared exactly and with the same lifting-map
// perturbation as insphere_perturbed (paper §6: "the same method and vertex order must be used in
// the tests that determine the order of circumcenters").
//
// Perturbing the lifted heights w_v -> w_v - eps_v moves a circumcentre (it becomes the centre of the
// power/orthogonal sphere) and moves every power linearly in eps, so each comparison below is a sign
// of  value + sum_v eps_v * coeff_v  : the value if it is non-zero, else the coefficient of the
// least vertex id that is non-zero.
#pragma once
#include <array>
#include <optional>

#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

// Lexicographic comparison of the (perturbed) circumcentres of two non-degenerate D-simplices:
// Negative when s's centre comes first (sweep-plane order), Zero only for equal centres.
template <int D>
Sign compare_circumcenters(const Vertices<D + 1>& s, const Vertices<D + 1>& t);

// sign(Psi_q(s) - Psi_q(t)), where Psi_q(s) = |q O_s|^2 - r_s^2 is the power of q with respect to
// the (perturbed) circumsphere of s. q's own lift cancels, so q need not be a vertex.
template <int D>
Sign compare_power(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const Vertex& q);

// Lexicographic comparison of power tuples Psi_Delta(s) = <Psi_Delta0(s), ..., Psi_DeltaD(s)> for
// the seed simplex delta (sweep-sphere order): Negative when s comes first.
template <int D>
Sign compare_power_tuples(const Vertices<D + 1>& s, const Vertices<D + 1>& t,
                          const Vertices<D + 1>& delta);

// Certified enclosures of the keys, to compare queue items cheaply: the exact (unperturbed) value
// lies in [lo, hi]. When two enclosures are disjoint their order is the order of the perturbed keys
// too (the perturbation is infinitesimal); otherwise compare exactly with the functions above and below.
// lo = -inf, hi = +inf when the filter's preconditions fail (see approx.h).
struct KeyInterval {
  double lo, hi;
};

// What compare_power_sequences works out about one simplex and reuses when given it again: the
// enclosures of its powers at q_1..q_{n-1} and its orientation, each computed on first need. A
// sweep's queue compares one item with many others; in the star sweeps of Steiner points every
// simplex through the point's segment ties with the others at q_0, and recomputing both was a
// fifth of those sweeps' time (perforated_tube_fine).
struct PowerSequenceCache {
  std::array<KeyInterval, 7> at{};  // at[k]: the power at q_k (k >= 1), when bit k of `known` is set
  uint8_t known = 0;
  int8_t orientation = 0;  // its sign; 0: not known yet
};

// The same for any sequence of points q_0..q_{n-1} (n <= D + 2), entry k multiplied by toward[k]
// (+1 or -1): the order of the star sweep (sweep_sides.h, StarSweep), whose centre may be perturbed
// away from a point. `s_cache` and `t_cache`, when given, hold what earlier calls with the same
// simplex (and the same q) worked out; the answer is the same without them.
template <int D>
Sign compare_power_sequences(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const Vertex* q, const int8_t* toward, int n,
                             PowerSequenceCache* s_cache = nullptr, PowerSequenceCache* t_cache = nullptr);

// Psi_q(s), the first entry of the power tuple for q = Delta_0.
template <int D>
KeyInterval power_interval(const Vertices<D + 1>& s, const double* q);

// Psi_q(s) = -L / Ds as two double-word values (the predicates' second stage, dd_approx.h), each
// with what bounds its error: L the lifted determinant of s's vertices about q, Ds the orientation
// determinant. A sweep computes them once for a queue item whose enclosure overlaps another's and
// compares items from them (power_order_from_words) instead of evaluating the exact comparison's
// stages again for every pair: in the star sweeps of points on facets bent by rounding most
// comparisons past the enclosures need the second stage, and a heap compares one item many times.
struct PowerWords {
  double l_hi, l_lo, l_mag;
  int l_rounds;
  double d_hi, d_lo, d_mag;
  int d_rounds;
};
template <int D>
PowerWords power_words(const Vertices<D + 1>& s, const double* q);

// sign(Psi_q(s) - Psi_q(t)) from their words when the double-word arithmetic certifies it (then the
// unperturbed powers differ and the perturbation cannot change the order), else nullopt: compare
// exactly. The same certificate as the second stage of compare_power's exact evaluation.
std::optional<Sign> power_order_from_words(const PowerWords& s, const PowerWords& t);

// Coordinate k of the circumcentre of s.
template <int D>
KeyInterval circumcenter_interval(const Vertices<D + 1>& s, int k);

}  // namespace sweepcdt::predicates
