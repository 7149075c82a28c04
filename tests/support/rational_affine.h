// Affine functions with exact rational coefficients, for the brute-force oracles (tests only):
// hyperplanes through D points of R^D given by doubles (every coefficient exact in mpq).
#pragma once
#include <optional>
#include <stdexcept>
#include <vector>

#include "rational_reference.h"

namespace sweepcdt::fixtures {

// f(x) = n . x - c.
struct Affine {
  ref::Vec n;
  ref::Q c;
  ref::Q at(const ref::Vec& x) const { return ref::dot(n, x) - c; }
  Affine negated() const { return {ref::scale(-1, n), -c}; }
};

// The hyperplane through D affinely independent points (orientation unspecified).
inline Affine hyperplane_through(const std::vector<ref::Vec>& points) {
  ref::Mat differences;
  for (std::size_t i = 1; i < points.size(); ++i) differences.push_back(ref::sub(points[i], points[0]));
  const auto n = ref::null_vector(differences);
  if (!n) throw std::logic_error("hyperplane_through: affinely dependent points");
  return {*n, ref::dot(*n, points[0])};
}

// f or -f, whichever is positive at x; nullopt when x lies on the hyperplane.
inline std::optional<Affine> positive_at(const Affine& f, const ref::Vec& x) {
  const int side = sgn(f.at(x));
  if (side == 0) return std::nullopt;
  return side > 0 ? f : f.negated();
}

// The hyperplane through `points`, positive at `positive` (which must lie off it).
inline Affine hyperplane_through(const std::vector<ref::Vec>& points, const ref::Vec& positive) {
  const auto f = positive_at(hyperplane_through(points), positive);
  if (!f) throw std::logic_error("hyperplane_through: orienting point on the hyperplane");
  return *f;
}

// The function of facet i of the simplex `s` (D+1 points): zero on the facet opposite s[i], positive
// at s[i], so positive exactly on the open side that holds the interior.
inline Affine facet_function(const std::vector<ref::Vec>& s, std::size_t i) {
  std::vector<ref::Vec> facet;
  for (std::size_t k = 0; k < s.size(); ++k)
    if (k != i) facet.push_back(s[k]);
  return hyperplane_through(facet, s[i]);
}

// Barycentric coordinates of each of `points` in the non-degenerate simplex `s` (D+1 points of R^D):
// result[j][i] is the coordinate of points[j] along s[i]. One elimination for all points.
inline std::vector<ref::Vec> barycentric(const std::vector<ref::Vec>& s, const std::vector<ref::Vec>& points) {
  const std::size_t d = s.size() - 1, n = s.size();
  ref::Mat a(n, ref::Vec(n + points.size()));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < d; ++k) a[k][i] = s[i][k];
    a[d][i] = 1;
  }
  for (std::size_t j = 0; j < points.size(); ++j) {
    for (std::size_t k = 0; k < d; ++k) a[k][n + j] = points[j][k];
    a[d][n + j] = 1;
  }
  const auto pivots = ref::rref(a);
  if (pivots.size() < n || pivots[n - 1] != n - 1) throw std::logic_error("barycentric: degenerate simplex");
  std::vector<ref::Vec> result(points.size(), ref::Vec(n));
  for (std::size_t j = 0; j < points.size(); ++j)
    for (std::size_t i = 0; i < n; ++i) result[j][i] = a[i][n + j];
  return result;
}

}  // namespace sweepcdt::fixtures
