// ExactMeasureSum: an exact running sum of simplex measures (orientation determinants), so that
// validate() can compare volumes without rounding: "the simplices cover exactly the domain".
#pragma once
#include <cstddef>
#include <functional>
#include <memory>

#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

class ExactMeasureSum {
 public:
  ExactMeasureSum();
  ~ExactMeasureSum();
  ExactMeasureSum(const ExactMeasureSum&);
  ExactMeasureSum& operator=(const ExactMeasureSum&);

  // Adds (or subtracts) det [p_i - p_D]: D! times the signed volume of the D-simplex p.
  template <int D>
  void add_volume(const Coords<D + 1>& p, bool subtract = false);

  // Adds the absolute (D-1)-measure of the (D-1)-simplex f of E^D projected along axis `drop`, times
  // (D-1)!: |orient_{D-1}| of the projection. Projection scales all measures in one hyperplane alike.
  template <int D>
  void add_projected_measure(const Coords<D>& f, int drop);

  Sign compare(const ExactMeasureSum& other) const;
  double to_double() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The sign of the sum over n tetrahedra of det [p_i - p_3] (6 times the signed volume), term k
// negated when `term(k, negate)` sets negate: a floating-point sum with a certified error bound
// (the orientation filter's bound for each term, plus the summation's), and the exact sum above only
// when that bound cannot tell. io's surface check orients each closed shell by it: summed exactly,
// 1.3M triangles took a tenth of reading the file.
Sign volume_sum_sign(std::size_t n, const std::function<Coords<4>(std::size_t k, bool& negate)>& term);

}  // namespace sweepcdt::predicates
