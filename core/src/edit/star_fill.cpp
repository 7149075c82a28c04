// check_star_fill (star_fill.h).
#include "star_fill.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "../facet_hash.h"
#include "../facets.h"
#include "../ids_text.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::detail {
namespace {

template <int D>
std::array<uint32_t, D + 1> simplex_of(const Triangulation<D>& fill, uint32_t t) {
  std::array<uint32_t, D + 1> s;
  std::copy_n(fill.simplex(t), D + 1, s.begin());
  return s;
}

// The vertex of simplex e.simplex opposite its facet e.
template <int D>
uint32_t apex(const Triangulation<D>& fill, const FacetEntry<D>& e) {
  return fill.simplex(e.simplex)[e.local];
}

}  // namespace

template <int D>
std::string check_star_fill(Triangulation<D>& fill, const Plc<D>& cavity) {
  const std::size_t simplices = fill.num_simplices(), points = cavity.num_points();
  const auto simplex_text = [&](uint32_t t) { return "simplex " + std::to_string(t) + " " + ids_text(fill.simplex(t), D + 1); };
  // 1. Ids and orientation (a repeated id makes a flat simplex).
  for (uint32_t t = 0; t < simplices; ++t) {
    predicates::Coords<D + 1> c;
    for (int i = 0; i <= D; ++i) {
      const uint32_t x = fill.simplex(t)[i];
      if (x >= points) return "simplex-ids: " + simplex_text(t) + " has a vertex out of range";
      c[i] = cavity.point(x);
    }
    if (predicates::orient<D>(c) != predicates::Sign::Positive)
      return "orientation: " + simplex_text(t) + " is not positively oriented (inverted or flat)";
  }
  // The facets and the constraints, each sorted by key, walked together.
  std::vector<FacetEntry<D>> facets;
  facets.reserve(simplices * (D + 1));
  for (uint32_t t = 0; t < simplices; ++t) {
    const SortedSimplex<D> s(fill.simplex(t));
    for (int j = 0; j <= D; ++j) facets.push_back(s.facet_without(j, t));
  }
  std::sort(facets.begin(), facets.end(), [](const FacetEntry<D>& a, const FacetEntry<D>& b) {
    return a.key < b.key || (a.key == b.key && a.simplex < b.simplex);
  });
  std::vector<std::pair<FacetKey<D>, uint32_t>> constraints;  // (sorted key, index in cavity)
  constraints.reserve(cavity.num_simplices());
  for (uint32_t j = 0; j < cavity.num_simplices(); ++j) {
    FacetKey<D> key;
    std::copy_n(cavity.simplex(j), D, key.begin());
    sort_tuple(key);
    constraints.push_back({key, j});
  }
  std::sort(constraints.begin(), constraints.end());

  fill.neighbors.assign(simplices * (D + 1), kNone);
  const auto facet_text = [](const FacetKey<D>& key) { return "facet " + ids_text(key.data(), D); };
  const auto missing = [&](uint32_t j) {
    return "constraints: constraining simplex " + std::to_string(j) + " " + ids_text(cavity.simplex(j), D) + " is not a union of facets";
  };
  std::size_t next = 0;  // the first constraint not yet matched
  for (std::size_t begin = 0, end; begin < facets.size(); begin = end) {
    const FacetKey<D>& key = facets[begin].key;
    end = begin + 1;
    while (end < facets.size() && facets[end].key == key) ++end;
    // 2. Shared by one or two simplices.
    if (end - begin > 2) return "facet-multiplicity: " + facet_text(key) + " is shared by " + std::to_string(end - begin) + " simplices";
    // 4. A constraint passed in key order without a facet is missing (the rest: after the loop).
    if (next < constraints.size() && constraints[next].first < key) return missing(constraints[next].second);
    uint32_t constraint = kNone;  // a constraint given twice is the later one, as for validate()
    while (next < constraints.size() && constraints[next].first == key) constraint = constraints[next++].second;
    const ExteriorSide exterior = constraint == kNone ? ExteriorSide::None : cavity.exterior_of(constraint);

    const FacetEntry<D>& a = facets[begin];
    if (end - begin == 1) {
      // 3. A boundary facet: a notated constraint, the simplex on its domain side. The simplex is
      // positive, so orient(constraint as given, apex) has the sign of the permutation between the two.
      if (exterior == ExteriorSide::None)
        return "domain-boundary: " + facet_text(key) + " bounds the triangulation but is not an exterior-notated constraining simplex";
      std::array<uint32_t, D + 1> as_given;
      std::copy_n(cavity.simplex(constraint), D, as_given.begin());
      as_given[D] = apex(fill, a);
      const bool positive = odd_permutation(as_given) == odd_permutation(simplex_of(fill, a.simplex));
      if (positive == (exterior == ExteriorSide::Positive))
        return "domain-boundary: " + simplex_text(a.simplex) + " lies on the exterior side of constraining simplex " + std::to_string(constraint);
      continue;
    }
    const FacetEntry<D>& b = facets[begin + 1];
    fill.neighbors[(D + 1) * a.simplex + a.local] = (D + 1) * b.simplex + b.local;
    fill.neighbors[(D + 1) * b.simplex + b.local] = (D + 1) * a.simplex + a.local;
    // 2. Opposite sides: a with its apex replaced by b's has b's vertices; both simplices positive,
    // b's apex lies on a's side exactly when the two orders are permutations of the same parity.
    std::array<uint32_t, D + 1> replaced = simplex_of(fill, a.simplex);
    replaced[a.local] = apex(fill, b);
    if (odd_permutation(replaced) == odd_permutation(simplex_of(fill, b.simplex)))
      return "interior-facet-sides: " + facet_text(key) + ": simplices " + std::to_string(a.simplex) + " and " + std::to_string(b.simplex) +
             " are not on opposite sides";
    // 3. An interior facet in a notated constraint puts one of its simplices on the exterior side.
    if (exterior != ExteriorSide::None)
      return "domain-boundary: a simplex at " + facet_text(key) + " lies on the exterior side of constraining simplex " + std::to_string(constraint);
    if (constraint != kNone) continue;
    // 5. Locally Delaunay, under the perturbation by cavity id.
    predicates::Vertices<D + 1> s;
    for (int k = 0; k <= D; ++k) s[k] = {cavity.point(fill.simplex(a.simplex)[k]), fill.simplex(a.simplex)[k]};
    const uint32_t q = apex(fill, b);
    if (predicates::inside_circumsphere<D>(s, {cavity.point(q), q}))
      return "locally-delaunay: " + facet_text(key) + " is not locally Delaunay: point " + std::to_string(q) + " is inside the circumsphere of " +
             simplex_text(a.simplex);
  }
  if (next < constraints.size()) return missing(constraints[next].second);
  return {};
}

template std::string check_star_fill<2>(Triangulation<2>&, const Plc<2>&);
template std::string check_star_fill<3>(Triangulation<3>&, const Plc<3>&);
template std::string check_star_fill<4>(Triangulation<4>&, const Plc<4>&);
template std::string check_star_fill<5>(Triangulation<5>&, const Plc<5>&);

}  // namespace sweepcdt::detail
