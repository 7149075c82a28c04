#include "sweepcdt/predicates/exact_sum.h"

#include "arith.h"

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

#define SWEEPCDT_INSTANTIATE(D)                                                      \
  template void ExactMeasureSum::add_volume<D>(const Coords<D + 1>&, bool);          \
  template void ExactMeasureSum::add_projected_measure<D>(const Coords<D>&, int);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::predicates
