#include "sweepcdt/predicates/exact_sum.h"

#include <cmath>

#include "arith.h"
#include "filters3.h"

namespace sweepcdt::predicates {

struct ExactMeasureSum::Impl {
  detail::Dyadic sum;
};

ExactMeasureSum::ExactMeasureSum() : impl_(std::make_unique<Impl>()) {}
ExactMeasureSum::~ExactMeasureSum() = default;
ExactMeasureSum::ExactMeasureSum(const ExactMeasureSum& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
ExactMeasureSum& ExactMeasureSum::operator=(const ExactMeasureSum& o) {
  *impl_ = *o.impl_;
  return *this;
}

template <int D>
void ExactMeasureSum::add_volume(const Coords<D + 1>& p, bool subtract) {
  // Homogeneous of degree D in the coordinate differences, as exact_value() requires.
  const detail::Dyadic v = detail::exact_value([&](auto& a) { return detail::orient_det<D>(a, p); });
  impl_->sum = subtract ? impl_->sum - v : impl_->sum + v;
}

template <int D>
void ExactMeasureSum::add_projected_measure(const Coords<D>& f, int drop) {
  const detail::Dyadic v = detail::exact_value([&](auto& a) { return detail::normal_component<D>(a, f, drop); });
  impl_->sum = v.sign() < 0 ? impl_->sum - v : impl_->sum + v;
}

Sign ExactMeasureSum::compare(const ExactMeasureSum& other) const {
  return detail::sign_of(impl_->sum - other.impl_->sum);
}

double ExactMeasureSum::to_double() const { return impl_->sum.to_double(); }

Sign volume_sum_sign(std::size_t n, const std::function<Coords<4>(std::size_t k, bool& negate)>& term) {
  // Each term's estimate v_k is within e_k of its determinant (filters3.h). Summing n of them in
  // order adds at most gamma_n * sum |v_k|, gamma_n = n u / (1 - n u) (Higham, Accuracy and Stability
  // of Numerical Algorithms, 4.2). The bound's own sums of non-negative terms are low by at most the
  // factor 1 - gamma_n: 1.01 covers that while n u < 1/101.
  double sum = 0, errors = 0, magnitudes = 0;
  for (std::size_t k = 0; k < n; ++k) {
    bool negate = false;
    const detail::Estimate e = detail::orient3_estimate(term(k, negate));
    sum += negate ? -e.value : e.value;
    errors += e.error;
    magnitudes += std::fabs(e.value);
  }
  const double nu = static_cast<double>(n) * detail::kUnitRoundoff;
  if (nu < 1.0 / 101) {
    const double bound = 1.01 * (errors + nu / (1 - nu) * magnitudes);
    if (sum > bound) return Sign::Positive;  // false for NaN and infinities: the exact sum decides
    if (sum < -bound) return Sign::Negative;
  }
  ExactMeasureSum exact;
  for (std::size_t k = 0; k < n; ++k) {
    bool negate = false;
    const Coords<4> p = term(k, negate);
    exact.add_volume<3>(p, negate);
  }
  return exact.compare(ExactMeasureSum());
}

#define SWEEPCDT_INSTANTIATE(D)                                                      \
  template void ExactMeasureSum::add_volume<D>(const Coords<D + 1>&, bool);          \
  template void ExactMeasureSum::add_projected_measure<D>(const Coords<D>&, int);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::predicates
