// add_polygon(): planar polygons to triangles, exactly (OFF, OBJ and PLY store polygons).
#include <algorithm>
#include <array>

#include "reader_util.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io::detail {
namespace {

using predicates::Sign;

// Ear clipping costs O(k^3) in the worst case; beyond this a non-convex polygon is refused rather
// than let a hostile file spin. Convex polygons (fanned in O(k)) have no such limit.
constexpr std::size_t kMaxEarClipVertices = 256;

class PlanarPolygon {
 public:
  PlanarPolygon(const Soup& soup, int drop) : soup_(soup), drop_(drop) {}
  const double* p(uint32_t id) const { return soup_.points.data() + 3 * std::size_t{id}; }
  // Orientation of three vertices in the polygon's plane, seen through the projection along `drop_`
  // (a bijection on the plane, since the plane is not parallel to that axis).
  Sign orient2(uint32_t a, uint32_t b, uint32_t c) const { return predicates::orient_projected<3>({p(a), p(b), p(c)}, drop_); }
  // Lexicographic order of the projected points: -1, 0 or +1.
  int compare(uint32_t a, uint32_t b) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (axis == drop_) continue;
      if (p(a)[axis] < p(b)[axis]) return -1;
      if (p(a)[axis] > p(b)[axis]) return 1;
    }
    return 0;
  }

 private:
  const Soup& soup_;
  int drop_;
};

bool collinear(const double* a, const double* b, const double* c) {
  for (int drop = 0; drop < 3; ++drop)
    if (predicates::orient_projected<3>({a, b, c}, drop) != Sign::Zero) return false;
  return true;
}

// Convex (and simple) iff every turn has the same nonzero sign and the vertices change lexicographic
// direction exactly twice (winding once: a pentagram turns one way everywhere but winds twice).
bool convex(const PlanarPolygon& poly, const std::vector<uint32_t>& ids, Sign turn) {
  const std::size_t k = ids.size();
  int changes = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const uint32_t prev = ids[(i + k - 1) % k], cur = ids[i], next = ids[(i + 1) % k];
    if (poly.orient2(prev, cur, next) != turn) return false;
    const int in = poly.compare(cur, prev), out = poly.compare(next, cur);
    if (in == 0 || out == 0) return false;
    if (in != out) ++changes;
  }
  return changes == 2;
}

}  // namespace

void add_polygon(Soup& soup, const std::vector<uint32_t>& ids, const Location& where) {
  const std::size_t k = ids.size();
  auto& out = soup.triangles;
  if (k == 3) {
    out.insert(out.end(), ids.begin(), ids.end());
    return;
  }
  auto bad = [&](InputErrorKind kind, const std::string& why) {
    fail(kind, soup.file, where, "polygon with " + std::to_string(k) + " vertices " + why);
  };
  std::vector<uint32_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
    bad(InputErrorKind::BadPolygon, "names vertex " + std::to_string(*it) + " twice");

  auto p = [&](uint32_t id) { return soup.points.data() + 3 * std::size_t{id}; };
  // A plane through three non-collinear vertices a, b, c.
  const uint32_t a = ids[0];
  std::size_t ib = 1;
  while (ib < k && std::equal(p(a), p(a) + 3, p(ids[ib]))) ++ib;
  std::size_t ic = ib + 1;
  while (ic < k && collinear(p(a), p(ids[ib]), p(ids[ic]))) ++ic;
  if (ib >= k || ic >= k) bad(InputErrorKind::BadPolygon, "is degenerate: all its vertices are collinear");
  const uint32_t b = ids[ib], c = ids[ic];
  for (uint32_t v : ids)
    if (predicates::orient<3>({p(a), p(b), p(c), p(v)}) != Sign::Zero)
      bad(InputErrorKind::BadPolygon, "is not planar: vertex " + std::to_string(v) + " is off the plane of vertices " +
                                          std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c));
  int drop = 0;
  while (predicates::orient_projected<3>({p(a), p(b), p(c)}, drop) == Sign::Zero) ++drop;
  const PlanarPolygon poly(soup, drop);

  // The lexicographically smallest vertex is extreme, so its turn is the polygon's orientation.
  const std::size_t low = static_cast<std::size_t>(
      std::min_element(ids.begin(), ids.end(), [&](uint32_t u, uint32_t v) { return poly.compare(u, v) < 0; }) - ids.begin());
  const Sign turn = poly.orient2(ids[(low + k - 1) % k], ids[low], ids[(low + 1) % k]);
  if (turn == Sign::Zero) bad(InputErrorKind::BadPolygon, "is not simple (it folds back on itself)");

  if (convex(poly, ids, turn)) {
    for (std::size_t i = 1; i + 1 < k; ++i) out.insert(out.end(), {ids[0], ids[i], ids[i + 1]});
    return;
  }
  if (k > kMaxEarClipVertices)
    bad(InputErrorKind::Unsupported, "is not convex; non-convex polygons are limited to " + std::to_string(kMaxEarClipVertices) + " vertices");

  // Ear clipping: cut a vertex whose turn agrees with the polygon and whose triangle holds no other
  // remaining vertex, not even on its boundary.
  std::vector<uint32_t> ring = ids;
  auto is_ear = [&](std::size_t i) {
    const std::size_t n = ring.size();
    const uint32_t u = ring[(i + n - 1) % n], v = ring[i], w = ring[(i + 1) % n];
    if (poly.orient2(u, v, w) != turn) return false;
    for (std::size_t j = 0; j < n; ++j) {
      const uint32_t q = ring[j];
      if (q == u || q == v || q == w) continue;
      if (poly.orient2(u, v, q) != -turn && poly.orient2(v, w, q) != -turn && poly.orient2(w, u, q) != -turn) return false;
    }
    return true;
  };
  std::size_t i = 0;
  while (ring.size() > 3) {
    const std::size_t n = ring.size();
    std::size_t tried = 0;
    while (tried < n && !is_ear(i % n)) {
      ++i;
      ++tried;
    }
    if (tried == n) bad(InputErrorKind::BadPolygon, "is not simple (no ear left to cut)");
    i %= n;
    out.insert(out.end(), {ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]});
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
  }
  if (poly.orient2(ring[0], ring[1], ring[2]) != turn) bad(InputErrorKind::BadPolygon, "is not simple");
  out.insert(out.end(), ring.begin(), ring.end());
}

}  // namespace sweepcdt::io::detail
