// volume_sum_sign (exact_sum.h): the sign of a sum of signed tetrahedron volumes, by a floating-point
// sum with a certified bound and the exact sum only when the bound cannot tell, against the rational
// reference (tests/support/rational_reference.h) — on sums far from zero, exactly zero (terms that
// cancel), a huge sum plus a tiny residue of either sign, terms one ulp apart, and scales that
// overflow or underflow the filter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "rational_reference.h"
#include "sweepcdt/predicates/exact_sum.h"

namespace {

using sweepcdt::predicates::Coords;
using sweepcdt::predicates::Sign;
namespace ref = sweepcdt::ref;

struct Term {
  std::array<double, 12> x;
  bool negate;
};

int reference_sign(const std::vector<Term>& terms) {
  ref::Q sum = 0;
  for (const Term& t : terms) {
    ref::Mat m(3, ref::Vec(3));
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) m[i][k] = ref::Q(t.x[3 * i + k]) - ref::Q(t.x[9 + k]);
    const ref::Q d = ref::det(m);
    sum += t.negate ? -d : d;
  }
  return sgn(sum);
}

int as_int(Sign s) { return s == Sign::Positive ? 1 : s == Sign::Negative ? -1 : 0; }

int computed_sign(const std::vector<Term>& terms) {
  return as_int(sweepcdt::predicates::volume_sum_sign(terms.size(), [&](std::size_t k, bool& negate) {
    negate = terms[k].negate;
    const double* x = terms[k].x.data();
    return Coords<4>{x, x + 3, x + 6, x + 9};
  }));
}

Term random_term(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  Term t;
  for (double& v : t.x) v = u(rng) * scale;
  t.negate = rng() & 1;
  return t;
}

TEST(VolumeSum, SignMatchesTheRationalSum) {
  std::mt19937_64 rng(31);
  int nonzero_random = 0, residues = 0;
  for (const double scale : {1.0, 0x1p-30, 0x1p40, 0x1p-1000, 3.0e-310, 0x1p600}) {
    for (int round = 0; round < 40; ++round) {
      std::vector<Term> terms;
      const int n = 1 + static_cast<int>(rng() % 50);
      for (int k = 0; k < n; ++k) terms.push_back(random_term(rng, scale));
      const int random_sign = reference_sign(terms);
      EXPECT_EQ(computed_sign(terms), random_sign) << "random, scale " << scale;
      nonzero_random += random_sign != 0;
      // Every term again, negated: exactly zero.
      std::vector<Term> cancelled = terms;
      for (Term t : terms) t.negate = !t.negate, cancelled.push_back(t);
      EXPECT_EQ(reference_sign(cancelled), 0);
      EXPECT_EQ(computed_sign(cancelled), 0) << "cancelling, scale " << scale;
      // And one coordinate of one copy moved by an ulp, or a tiny tetrahedron added: a residue far
      // below the bound, of either sign.
      std::vector<Term> nudged = cancelled;
      double& x = nudged[n + static_cast<int>(rng() % n)].x[rng() % 12];
      x = std::nextafter(x, (rng() & 1) ? INFINITY : -INFINITY);
      const int expected = reference_sign(nudged);
      EXPECT_EQ(computed_sign(nudged), expected) << "an ulp off, scale " << scale;
      std::vector<Term> tiny = cancelled;
      tiny.push_back(random_term(rng, scale * 0x1p-40));
      EXPECT_EQ(computed_sign(tiny), reference_sign(tiny)) << "tiny residue, scale " << scale;
      residues += expected != 0;
    }
  }
  EXPECT_GT(residues, 100) << "the ulp moves should mostly leave a nonzero residue";
  EXPECT_GT(nonzero_random, 200) << "random sums should be far from zero (the filter's case)";
  EXPECT_EQ(computed_sign({}), 0);
}

}  // namespace
