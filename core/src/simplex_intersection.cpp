// Orientation-based intersection tests for segments in E^2 and triangles in E^3; in E^4 and E^5 exact
// shortcuts before the linear program.
#include "simplex_intersection.h"

#include <algorithm>

#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::detail {
namespace {

using predicates::Sign;
using P = const double*;

Sign orient2(P a, P b, P c) { return predicates::orient<2>({a, b, c}); }
Sign orient3(P a, P b, P c, P d) { return predicates::orient<3>({a, b, c, d}); }

// A collinear point c lies on the closed segment ab iff it is within ab's bounding box.
bool on_segment_2d(P a, P b, P c) {
  for (int k = 0; k < 2; ++k)
    if (c[k] < std::min(a[k], b[k]) || c[k] > std::max(a[k], b[k])) return false;
  return true;
}

bool segments_meet_2d(P p, P q, P a, P b) {
  // a and b strictly on one side of pq's line (or p and q of ab's): no contact, and no more tests.
  const Sign o1 = orient2(p, q, a), o2 = orient2(p, q, b);
  if (o1 * o2 == Sign::Positive) return false;
  const Sign o3 = orient2(a, b, p), o4 = orient2(a, b, q);
  if (o3 * o4 == Sign::Positive) return false;
  if (o1 * o2 == Sign::Negative && o3 * o4 == Sign::Negative) return true;
  return (o1 == Sign::Zero && on_segment_2d(p, q, a)) || (o2 == Sign::Zero && on_segment_2d(p, q, b)) ||
         (o3 == Sign::Zero && on_segment_2d(a, b, p)) || (o4 == Sign::Zero && on_segment_2d(a, b, q));
}

// No mix of strictly positive and strictly negative signs.
bool consistent(Sign a, Sign b, Sign c) {
  const bool pos = a == Sign::Positive || b == Sign::Positive || c == Sign::Positive;
  const bool neg = a == Sign::Negative || b == Sign::Negative || c == Sign::Negative;
  return !(pos && neg);
}

// The third orientation only when the first two do not already disagree.
bool point_in_triangle_2d(P p, P a, P b, P c) {
  const Sign s1 = orient2(a, b, p), s2 = orient2(b, c, p);
  if (s1 * s2 == Sign::Negative) return false;
  return consistent(s1, s2, orient2(c, a, p));
}

bool segment_meets_triangle_2d(P p, P q, P a, P b, P c) {
  return point_in_triangle_2d(p, a, b, c) || point_in_triangle_2d(q, a, b, c) || segments_meet_2d(p, q, a, b) ||
         segments_meet_2d(p, q, b, c) || segments_meet_2d(p, q, c, a);
}

// Coplanar work in E^3: drop an axis along which the triangle's plane projects one-to-one.
struct PlaneProjection {
  int drop;
  std::array<double, 2> project(P p) const {
    std::array<double, 2> r;
    for (int k = 0, c = 0; k < 3; ++k)
      if (k != drop) r[c++] = p[k];
    return r;
  }
};

PlaneProjection projection_of(P a, P b, P c) {
  for (int drop = 0; drop < 3; ++drop)
    if (predicates::orient_projected<3>({a, b, c}, drop) != Sign::Zero) return {drop};
  return {2};  // unreachable for a non-degenerate triangle
}

// p coplanar with triangle abc.
bool coplanar_point_in_triangle(P p, P a, P b, P c) {
  const PlaneProjection pr = projection_of(a, b, c);
  const auto p2 = pr.project(p), a2 = pr.project(a), b2 = pr.project(b), c2 = pr.project(c);
  return point_in_triangle_2d(p2.data(), a2.data(), b2.data(), c2.data());
}

// Two coplanar triangles without a common vertex, projected one-to-one to 2D (the same projection for
// both): whether they meet, as closed sets. They are disjoint exactly when the line of one of their
// six edges has that edge's triangle on one side and the other triangle's three vertices strictly on
// the other: the separating axis theorem for convex polygons (the edge of the Minkowski difference
// s - t nearest the origin is a translate of an edge of s or of -t with the same outward normal, so
// that edge's own line separates). At most 2 + 18 orientations, most pairs of a flat CAD face a few;
// testing each of the six edges against the other triangle took up to 108.
bool coplanar_triangles_meet_2d(const std::array<std::array<double, 2>, 3>& s, const std::array<std::array<double, 2>, 3>& t) {
  const auto an_edge_separates = [](const std::array<std::array<double, 2>, 3>& u, const std::array<std::array<double, 2>, 3>& w) {
    const Sign inside = orient2(u[0].data(), u[1].data(), u[2].data());  // of every edge's third vertex
    for (int i = 0; i < 3; ++i) {
      const P e0 = u[i].data(), e1 = u[(i + 1) % 3].data();
      bool outside = true;
      for (int k = 0; k < 3 && outside; ++k) outside = orient2(e0, e1, w[k].data()) == -inside;
      if (outside) return true;
    }
    return false;
  };
  return !an_edge_separates(s, t) && !an_edge_separates(t, s);
}

// A triangle with what the segment tests against it reuse: its vertices and, once asked for, the
// projection its plane maps one-to-one under.
struct Triangle3 {
  P a, b, c;
  mutable int drop = -1;
  PlaneProjection projection() const {
    if (drop < 0) drop = projection_of(a, b, c).drop;
    return {drop};
  }
};

// Segment pq against triangle t, given op = orient3(t, p) and oq = orient3(t, q): the triangle-pair
// tests below compute each vertex's side of the other triangle's plane once, not once per edge.
bool segment_meets_triangle_3d(P p, P q, const Triangle3& t, Sign op, Sign oq) {
  const P a = t.a, b = t.b, c = t.c;
  if (op == oq && op != Sign::Zero) return false;
  if (op == Sign::Zero && oq == Sign::Zero) {
    const PlaneProjection pr = t.projection();
    const auto p2 = pr.project(p), q2 = pr.project(q), a2 = pr.project(a), b2 = pr.project(b), c2 = pr.project(c);
    return segment_meets_triangle_2d(p2.data(), q2.data(), a2.data(), b2.data(), c2.data());
  }
  if (op == Sign::Zero || oq == Sign::Zero) {
    const PlaneProjection pr = t.projection();
    const auto x2 = pr.project(op == Sign::Zero ? p : q), a2 = pr.project(a), b2 = pr.project(b), c2 = pr.project(c);
    return point_in_triangle_2d(x2.data(), a2.data(), b2.data(), c2.data());
  }
  return consistent(orient3(p, q, a, b), orient3(p, q, b, c), orient3(p, q, c, a));
}

template <int D>
int shared_count(const std::array<uint32_t, D>& ida, const std::array<uint32_t, D>& idb) {
  int n = 0;
  for (uint32_t i : ida) n += std::count(idb.begin(), idb.end(), i) > 0;
  return n;
}

// Reorders so that the shared vertices come first, in the same order in both.
template <int D>
void shared_first(std::array<P, D>& a, std::array<uint32_t, D>& ida, std::array<P, D>& b, std::array<uint32_t, D>& idb) {
  int next = 0;
  for (int i = 0; i < D; ++i) {
    const auto it = std::find(idb.begin(), idb.end(), ida[i]);
    if (it == idb.end()) continue;
    const int j = static_cast<int>(it - idb.begin());
    std::swap(a[next], a[i]);
    std::swap(ida[next], ida[i]);
    std::swap(b[next], b[j]);
    std::swap(idb[next], idb[j]);
    ++next;
  }
}

bool improper_2d(std::array<P, 2> a, std::array<uint32_t, 2> ida, std::array<P, 2> b, std::array<uint32_t, 2> idb) {
  const int shared = shared_count<2>(ida, idb);
  if (shared == 0) return segments_meet_2d(a[0], a[1], b[0], b[1]);
  if (shared == 2) return true;  // the same segment twice
  shared_first<2>(a, ida, b, idb);
  // Sharing an endpoint: improper iff collinear and pointing the same way (one contains the other's end).
  if (orient2(a[0], a[1], b[1]) != Sign::Zero) return false;
  return on_segment_2d(a[0], a[1], b[1]) || on_segment_2d(b[0], b[1], a[1]);
}

bool improper_3d(std::array<P, 3> a, std::array<uint32_t, 3> ida, std::array<P, 3> b, std::array<uint32_t, 3> idb) {
  const int shared = shared_count<3>(ida, idb);
  if (shared == 3) return true;
  shared_first<3>(a, ida, b, idb);
  const Triangle3 ta{a[0], a[1], a[2]}, tb{b[0], b[1], b[2]};
  // Sides of b's plane for a's vertices, and of a's plane for b's. When a lies in b's plane (all
  // zero), the planes are equal (a is not degenerate), so b's vertices are all on a's plane too: the
  // coplanar pairs of flat CAD faces cost 3 exact orientations, not 12.
  const auto sides = [](const Triangle3& t, P x) { return orient3(t.a, t.b, t.c, x); };
  const auto all_zero = [](const std::array<Sign, 3>& s) { return s[0] == Sign::Zero && s[1] == Sign::Zero && s[2] == Sign::Zero; };
  switch (shared) {
    case 0: {  // any contact at all
      // A triangle strictly on one side of the other's plane cannot meet it.
      const auto one_side = [](const std::array<Sign, 3>& s) { return s[0] != Sign::Zero && s[0] == s[1] && s[1] == s[2]; };
      const std::array<Sign, 3> sa{sides(tb, a[0]), sides(tb, a[1]), sides(tb, a[2])};
      if (one_side(sa)) return false;
      if (all_zero(sa)) {  // coplanar: any contact in their common plane
        const PlaneProjection pr = ta.projection();
        return coplanar_triangles_meet_2d({pr.project(a[0]), pr.project(a[1]), pr.project(a[2])},
                                          {pr.project(b[0]), pr.project(b[1]), pr.project(b[2])});
      }
      const std::array<Sign, 3> sb{sides(ta, b[0]), sides(ta, b[1]), sides(ta, b[2])};
      if (one_side(sb)) return false;
      return segment_meets_triangle_3d(a[0], a[1], tb, sa[0], sa[1]) ||
             segment_meets_triangle_3d(a[1], a[2], tb, sa[1], sa[2]) ||
             segment_meets_triangle_3d(a[2], a[0], tb, sa[2], sa[0]) ||
             segment_meets_triangle_3d(b[0], b[1], ta, sb[0], sb[1]) ||
             segment_meets_triangle_3d(b[1], b[2], ta, sb[1], sb[2]) ||
             segment_meets_triangle_3d(b[2], b[0], ta, sb[2], sb[0]);
    }
    case 1: {  // sharing vertex v = a[0] = b[0]: a contact away from v reaches an opposite edge
      const Sign a1 = sides(tb, a[1]), a2 = sides(tb, a[2]);
      if (segment_meets_triangle_3d(a[1], a[2], tb, a1, a2)) return true;
      const bool coplanar = a1 == Sign::Zero && a2 == Sign::Zero;  // a[0] = b[0] lies in b's plane too
      const Sign b1 = coplanar ? Sign::Zero : sides(ta, b[1]), b2 = coplanar ? Sign::Zero : sides(ta, b[2]);
      return segment_meets_triangle_3d(b[1], b[2], ta, b1, b2);
    }
    default: {  // sharing edge a[0]a[1]: improper iff coplanar with both apexes on the same side
      if (orient3(a[0], a[1], a[2], b[2]) != Sign::Zero) return false;
      const PlaneProjection pr = projection_of(a[0], a[1], a[2]);
      const auto u = pr.project(a[0]), v = pr.project(a[1]), x = pr.project(a[2]), y = pr.project(b[2]);
      return orient2(u.data(), v.data(), x.data()) == orient2(u.data(), v.data(), y.data());
    }
  }
}

// D >= 4: exact answers that spare the linear program (each one costs milliseconds of rationals).
// Disjoint bounding boxes: no common point. And when every vertex of b that a does not share lies
// strictly on one side of a's hyperplane, b meets that hyperplane only in the hull of the shared
// vertices, so a and b meet exactly in the face those span: proper (likewise with a and b swapped).
template <int D>
bool proper_without_lp(const std::array<P, D>& a, const std::array<uint32_t, D>& ida, const std::array<P, D>& b,
                       const std::array<uint32_t, D>& idb) {
  for (int k = 0; k < D; ++k) {
    double a_lo = a[0][k], a_hi = a[0][k], b_lo = b[0][k], b_hi = b[0][k];
    for (int i = 1; i < D; ++i) {
      a_lo = std::min(a_lo, a[i][k]), a_hi = std::max(a_hi, a[i][k]);
      b_lo = std::min(b_lo, b[i][k]), b_hi = std::max(b_hi, b[i][k]);
    }
    if (a_hi < b_lo || b_hi < a_lo) return true;
  }
  const auto others_on_one_side = [](const std::array<P, D>& s, const std::array<uint32_t, D>& ids, const std::array<P, D>& t,
                                     const std::array<uint32_t, D>& idt) {
    predicates::Coords<D + 1> x;
    std::copy(s.begin(), s.end(), x.begin());
    Sign side = Sign::Zero;
    for (int j = 0; j < D; ++j) {
      if (std::find(ids.begin(), ids.end(), idt[j]) != ids.end()) continue;
      x[D] = t[j];
      const Sign o = predicates::orient<D>(x);
      if (o == Sign::Zero || (side != Sign::Zero && o != side)) return false;
      side = o;
    }
    return true;
  };
  return others_on_one_side(a, ida, b, idb) || others_on_one_side(b, idb, a, ida);
}

}  // namespace

template <int D>
bool improper_intersection(const std::array<const double*, D>& a, const std::array<uint32_t, D>& ida,
                           const std::array<const double*, D>& b, const std::array<uint32_t, D>& idb) {
  if constexpr (D == 2) return improper_2d(a, ida, b, idb);
  else if constexpr (D == 3) return improper_3d(a, ida, b, idb);
  else return !proper_without_lp<D>(a, ida, b, idb) && improper_intersection_lp<D>(a, ida, b, idb);
}

template <int D>
bool point_in_simplex(const double* p, const std::array<const double*, D>& f) {
  if constexpr (D == 2) {
    return orient2(f[0], f[1], p) == Sign::Zero && on_segment_2d(f[0], f[1], p);
  } else if constexpr (D == 3) {
    return orient3(f[0], f[1], f[2], p) == Sign::Zero && coplanar_point_in_triangle(p, f[0], f[1], f[2]);
  } else {
    // A point is a degenerate simplex: reuse the LP with p repeated.
    std::array<const double*, D> q;
    q.fill(p);
    std::array<uint32_t, D> idq, idf;
    for (int i = 0; i < D; ++i) idf[i] = static_cast<uint32_t>(i), idq[i] = static_cast<uint32_t>(D);
    return improper_intersection_lp<D>(q, idq, f, idf);
  }
}

template bool improper_intersection<2>(const std::array<P, 2>&, const std::array<uint32_t, 2>&,
                                       const std::array<P, 2>&, const std::array<uint32_t, 2>&);
template bool improper_intersection<3>(const std::array<P, 3>&, const std::array<uint32_t, 3>&,
                                       const std::array<P, 3>&, const std::array<uint32_t, 3>&);
template bool improper_intersection<4>(const std::array<P, 4>&, const std::array<uint32_t, 4>&,
                                       const std::array<P, 4>&, const std::array<uint32_t, 4>&);
template bool improper_intersection<5>(const std::array<P, 5>&, const std::array<uint32_t, 5>&,
                                       const std::array<P, 5>&, const std::array<uint32_t, 5>&);
template bool point_in_simplex<2>(const double*, const std::array<P, 2>&);
template bool point_in_simplex<3>(const double*, const std::array<P, 3>&);
template bool point_in_simplex<4>(const double*, const std::array<P, 4>&);
template bool point_in_simplex<5>(const double*, const std::array<P, 5>&);

}  // namespace sweepcdt::detail
