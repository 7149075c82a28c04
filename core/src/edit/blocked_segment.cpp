// segment_in_spheres (blocked_segment.h): Seidel's incremental 2D linear program over the spheres
// through a and b, with exact predicates.
#include "blocked_segment.h"

#include "../segment_interior.h"

#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::detail {

using predicates::Sign;
using predicates::Vertex;

BlockedSegment segment_in_spheres(const Vertex& a, const Vertex& b, const std::vector<Vertex>& others) {
  const auto inside = [&](const Vertex& c, const Vertex& d, const Vertex& q) {
    return predicates::inside_circumsphere<3>({a, b, c, d}, q);
  };
  constexpr uint32_t kNoPoint = ~0u;
  const auto point_off_plane = [&](uint32_t e) {
    for (uint32_t q = 0; q < others.size(); ++q)
      if (predicates::orient<3>({a.x, b.x, others[e].x, others[q].x}) != Sign::Zero) return q;
    return kNoPoint;
  };
  std::vector<uint32_t> seen;  // indices into others; the sphere through a, b, others[kept] holds none
  seen.reserve(others.size());
  std::array<uint32_t, 2> kept{kNoPoint, kNoPoint};  // kNoPoint: no constraint pins a sphere yet
  for (uint32_t k = 0; k < others.size(); ++k) {
    const Vertex& e = others[k];
    if (kept[0] != kNoPoint && (kept[1] == k || !inside(others[kept[0]], others[kept[1]], e))) {  // on it, or outside
      seen.push_back(k);
      continue;
    }
    // Some sphere through a, b that holds none of the points seen, and not e, passes through e (the
    // half-planes seen meet in a convex set, which holds the kept sphere and lies on the line of e if
    // it reaches beyond it). On that line, the spheres through a, b and e, each point c seen bounds
    // the spheres that leave it out at the sphere through c, from the side of the plane abe it lies
    // on: the tighter of two bounds on one side is the point inside the other's sphere, and the two
    // sides' tightest bounds leave a sphere between them unless one is inside the other's.
    if (predicates::collinear<3>(a.x, b.x, e.x)) {
      // On the line ab: inside every sphere through a and b between them, outside all beyond them.
      if (strictly_inside_segment<3>(a.x, e.x, b.x)) return {SegmentInSpheres::Blocked, {k, k, k}};
      seen.push_back(k);
      continue;
    }
    std::array<uint32_t, 2> bound{kNoPoint, kNoPoint};  // per side of the plane abe
    uint32_t anchor = kNoPoint;  // a point off the plane abe, found when one in it is met
    for (const uint32_t j : seen) {
      const Vertex& c = others[j];
      const Sign side = predicates::orient<3>({a.x, b.x, e.x, c.x});
      if (side == Sign::Zero) {
        // c in the plane abe: every sphere through a, b, e meets it in the circle abe, so c is inside
        // all of them or none. Any fourth point off the plane tells which (the perturbation of §6
        // never decides by that point: its cofactor is orient(a, b, e, c) = 0).
        if (anchor == kNoPoint) anchor = point_off_plane(k);
        if (anchor == kNoPoint) return {};  // every point in one plane: left undecided
        if (inside(e, others[anchor], c)) return {SegmentInSpheres::Blocked, {k, j, anchor}};
        continue;
      }
      uint32_t& tightest = bound[side == Sign::Positive];
      if (tightest == kNoPoint || inside(e, others[tightest], c)) tightest = j;
    }
    if (bound[0] != kNoPoint && bound[1] != kNoPoint && inside(e, others[bound[0]], others[bound[1]]))
      return {SegmentInSpheres::Blocked, {k, bound[0], bound[1]}};
    seen.push_back(k);
    // The new sphere: at the bound met, or, with none, any on the line (through a point off the plane
    // abe, maybe one not seen yet: it lies on that sphere, so it is outside it as the closed program
    // counts; the perturbation leaves no program that only its boundary satisfies).
    uint32_t pin = bound[0] != kNoPoint ? bound[0] : bound[1];
    if (pin == kNoPoint) {
      if (anchor == kNoPoint) anchor = point_off_plane(k);
      if (anchor == kNoPoint) return {};  // every point in one plane: left undecided
      pin = anchor;
    }
    kept = {k, pin};
  }
  return {SegmentInSpheres::Delaunay, {}};
}

}  // namespace sweepcdt::detail
