// ExactMeasureSum: an exact running sum of simplex measures (orientation determinants), so that
// validate() can compare volumes without rounding: "the simplices cover exactly the domain".
#pragma once
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

}  // namespace sweepcdt::predicates
