// Paper §3: "behind" and "in front of" for the sweep plane and the sweep sphere.
#include "sweepcdt/predicates/sweep_sides.h"

#include <stdexcept>

#include "arith.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::predicates {

template <int D>
Coords<D + 1> with_point(const Coords<D>& f, const double* p) {
  Coords<D + 1> s;
  for (int i = 0; i < D; ++i) s[i] = f[i];
  s[D] = p;
  return s;
}

// orient(f, q) = n . q + c with n_k = normal_component(f, k). Far along -x_k its sign is -sign(n_k):
// the first axis with n_k != 0 decides which side is behind.
template <int D>
Sign behind_sign(const PlaneSweep&, const Coords<D>& f) {
  for (int k = 0; k < D; ++k) {
    const Sign n = detail::filtered_sign(
        [&](auto& arith) { return detail::normal_component<D>(arith, f, k); });
    if (n != Sign::Zero) return -n;
  }
  throw std::invalid_argument("behind_sign: the face does not span a hyperplane");
}

template <int D>
Sign behind_sign(const SphereSweep<D>& sweep, const Coords<D>& f) {
  for (const double* delta : sweep.delta) {
    const Sign o = orient<D>(with_point<D>(f, delta));
    if (o != Sign::Zero) return o;
  }
  throw std::invalid_argument("behind_sign: the seed simplex lies in the face's hyperplane");
}

template <int D>
Sign behind_sign(const StarSweep<D>& sweep, const Coords<D>& f) {
  for (int k = 0; k < D + 2; ++k) {
    const Sign o = orient<D>(with_point<D>(f, sweep.centre[k]));
    if (o != Sign::Zero) return sweep.toward[k] > 0 ? -o : o;
  }
  throw std::invalid_argument("behind_sign: the star's centre points lie in the face's hyperplane");
}

template <int D, class Sweep>
Side side_of(const Sweep& sweep, const Coords<D>& f, const double* p) {
  const Sign o = orient<D>(with_point<D>(f, p));
  if (o == Sign::Zero) return Side::On;
  return o == behind_sign<D>(sweep, f) ? Side::Behind : Side::Front;
}

#define SWEEPCDT_INSTANTIATE(D)                                                         \
  template Coords<D + 1> with_point<D>(const Coords<D>&, const double*);               \
  template Sign behind_sign<D>(const PlaneSweep&, const Coords<D>&);                    \
  template Sign behind_sign<D>(const SphereSweep<D>&, const Coords<D>&);                \
  template Side side_of<D, PlaneSweep>(const PlaneSweep&, const Coords<D>&, const double*); \
  template Sign behind_sign<D>(const StarSweep<D>&, const Coords<D>&);                  \
  template Side side_of<D, SphereSweep<D>>(const SphereSweep<D>&, const Coords<D>&, const double*); \
  template Side side_of<D, StarSweep<D>>(const StarSweep<D>&, const Coords<D>&, const double*);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::predicates
