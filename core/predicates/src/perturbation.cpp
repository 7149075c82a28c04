// Paper §6: insphere under the lifting-map perturbation. The derivation of the sign rule is in
// perturbation.h.
#include "sweepcdt/predicates/perturbation.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "stats_counters.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::predicates {

template <int D>
Sign insphere_perturbed(const Vertices<D + 2>& p) {
  const Sign unperturbed = insphere<D>(coords_of(p));
  if (unperturbed != Sign::Zero) return unperturbed;
  detail::count_perturbed();
  detail::count_tie();

  std::array<int, D + 2> by_id;
  std::iota(by_id.begin(), by_id.end(), 0);
  std::sort(by_id.begin(), by_id.end(), [&](int a, int b) { return p[a].id < p[b].id; });
  for (const int i : by_id) {
    Coords<D + 1> rest;
    for (int j = 0, r = 0; j < D + 2; ++j)
      if (j != i) rest[r++] = p[j].x;
    const Sign o = orient<D>(rest);
    if (o != Sign::Zero) return ((i + D + 1) % 2 == 0) ? o : -o;
  }
  return Sign::Zero;  // all D+2 points in one hyperplane
}

template <int D>
bool inside_circumsphere(const Vertices<D + 1>& s, const Vertex& q) {
  const Sign o = orient<D>(coords_of(s));
  if (o == Sign::Zero) throw std::invalid_argument("inside_circumsphere: degenerate simplex");
  Vertices<D + 2> all;
  std::copy(s.begin(), s.end(), all.begin());
  all[D + 1] = q;
  return insphere_perturbed<D>(all) == o;
}

#define SWEEPCDT_INSTANTIATE(D)                                        \
  template Sign insphere_perturbed<D>(const Vertices<D + 2>&);         \
  template bool inside_circumsphere<D>(const Vertices<D + 1>&, const Vertex&);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::predicates
