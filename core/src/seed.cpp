#include "seed.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::detail {

using predicates::Sign;

template <int D>
std::optional<std::array<uint32_t, D + 1>> delaunay_seed(const Plc<D>& plc) {
  const uint32_t n = static_cast<uint32_t>(plc.num_points());
  if (n < D + 1) return std::nullopt;
  const double* origin = plc.point(0);
  auto distance = [&](uint32_t i) {  // a search order only, never a decision
    double d = 0;
    for (int k = 0; k < D; ++k) d += (plc.point(i)[k] - origin[k]) * (plc.point(i)[k] - origin[k]);
    return d;
  };
  std::vector<uint32_t> order(n - 1);
  std::iota(order.begin(), order.end(), 1u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return distance(a) < distance(b); });

  auto empty_sphere = [&](const predicates::Vertices<D + 1>& s) {
    for (uint32_t q = 0; q < n; ++q) {
      const uint32_t candidate = q == 0 ? 0 : order[q - 1];  // nearest first: most spheres fail fast
      if (std::any_of(s.begin(), s.end(), [&](const predicates::Vertex& v) { return v.id == candidate; })) continue;
      if (predicates::inside_circumsphere<D>(s, {plc.point(candidate), candidate})) return false;
    }
    return true;
  };

  for (uint32_t k = std::min<uint32_t>(n - 1, 2 * D + 2);; k = std::min<uint32_t>(n - 1, 2 * k)) {
    std::vector<bool> chosen(k, false);
    std::fill(chosen.begin(), chosen.begin() + D, true);
    do {
      std::array<uint32_t, D + 1> ids{0};
      for (uint32_t i = 0, j = 1; i < k; ++i)
        if (chosen[i]) ids[j++] = order[i];
      predicates::Vertices<D + 1> s;
      for (int i = 0; i <= D; ++i) s[i] = {plc.point(ids[i]), ids[i]};
      const Sign o = predicates::orient<D>(predicates::coords_of(s));
      if (o == Sign::Zero || !empty_sphere(s)) continue;
      if (o == Sign::Negative) std::swap(ids[0], ids[1]);
      return ids;
    } while (std::prev_permutation(chosen.begin(), chosen.end()));
    if (k == n - 1) return std::nullopt;
  }
}

template std::optional<std::array<uint32_t, 3>> delaunay_seed<2>(const Plc<2>&);
template std::optional<std::array<uint32_t, 4>> delaunay_seed<3>(const Plc<3>&);
template std::optional<std::array<uint32_t, 5>> delaunay_seed<4>(const Plc<4>&);
template std::optional<std::array<uint32_t, 6>> delaunay_seed<5>(const Plc<5>&);

}  // namespace sweepcdt::detail
