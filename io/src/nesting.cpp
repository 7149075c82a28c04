#include "nesting.h"

#include <algorithm>
#include <array>

#include "sweepcdt/predicates/exact_sum.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io::detail {
namespace {

using predicates::Sign;

Sign sign_of(double d) { return d > 0 ? Sign::Positive : d < 0 ? Sign::Negative : Sign::Zero; }

// Side of the perturbed point q' = q + (0, e, e^2) relative to the directed edge (u, v) in the yz
// plane: the sign of orient2_yz(u, v, q'), expanded in e. The e-term is (u_z - v_z), the e^2-term
// (v_y - u_y); both vanish only if u and v project to the same point.
Sign perturbed_side(const double* u, const double* v, const double* q) {
  const Sign s = predicates::orient_projected<3>({u, v, q}, 0);
  if (s != Sign::Zero) return s;
  if (u[2] != v[2]) return sign_of(u[2] - v[2]);  // exact: the sign of a difference is a comparison
  return sign_of(v[1] - u[1]);
}

struct Box {
  std::array<double, 3> lo, hi;
  bool contains(const Box& b) const {
    for (int k = 0; k < 3; ++k)
      if (b.lo[k] < lo[k] || b.hi[k] > hi[k]) return false;
    return true;
  }
};

Box box_of(const Surface& s, const std::vector<uint32_t>& triangles) {
  const double* first = s.points.data() + 3 * std::size_t{s.triangles[3 * triangles[0]]};
  Box box{{first[0], first[1], first[2]}, {first[0], first[1], first[2]}};
  for (uint32_t t : triangles)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) {
        const double x = s.points[3 * std::size_t{s.triangles[3 * t + c]} + k];
        box.lo[k] = std::min(box.lo[k], x);
        box.hi[k] = std::max(box.hi[k], x);
      }
  return box;
}

}  // namespace

bool inside_shell(const Surface& surface, const std::vector<uint32_t>& triangles, const double* q) {
  bool inside = false;
  for (uint32_t t : triangles) {
    const uint32_t* v = surface.triangles.data() + 3 * std::size_t{t};
    const double* a = surface.points.data() + 3 * std::size_t{v[0]};
    const double* b = surface.points.data() + 3 * std::size_t{v[1]};
    const double* c = surface.points.data() + 3 * std::size_t{v[2]};
    // A triangle parallel to the x axis projects to a segment: the perturbed ray misses it.
    const Sign facing = predicates::orient_projected<3>({a, b, c}, 0);
    if (facing == Sign::Zero) continue;
    if (perturbed_side(a, b, q) != facing || perturbed_side(b, c, q) != facing || perturbed_side(c, a, q) != facing) continue;
    // The ray's line meets the plane at q + t* e_x with t* = orient(a, b, c, q) / n_x, and
    // n_x = orient2_yz(a, b, c): the crossing is ahead of q iff both have the same sign.
    const Sign side = predicates::orient<3>({a, b, c, q});
    if (side == facing) inside = !inside;
  }
  return inside;
}

int volume_sign(const Surface& surface, const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& reversed) {
  const double* origin = surface.points.data() + 3 * std::size_t{surface.triangles[3 * triangles[0]]};
  const auto point = [&](uint32_t v) { return surface.points.data() + 3 * std::size_t{v}; };
  return to_int(predicates::volume_sum_sign(triangles.size(), [&](std::size_t k, bool& negate) {
    const uint32_t t = triangles[k];
    const uint32_t* v = surface.triangles.data() + 3 * std::size_t{t};
    negate = reversed[t] != 0;
    return predicates::Coords<4>{point(v[0]), point(v[1]), point(v[2]), origin};
  }));
}

void nest_shells(const Surface& surface, const std::vector<std::vector<uint32_t>>& shell_triangles, std::vector<Shell>& shells) {
  const std::size_t k = shells.size();
  std::vector<Box> boxes(k);
  for (std::size_t i = 0; i < k; ++i) boxes[i] = box_of(surface, shell_triangles[i]);
  std::vector<std::vector<uint32_t>> containers(k);
  for (std::size_t a = 0; a < k; ++a) {
    const double* q = surface.points.data() + 3 * std::size_t{surface.triangles[3 * shell_triangles[a][0]]};
    for (std::size_t b = 0; b < k; ++b)
      if (a != b && boxes[b].contains(boxes[a]) && inside_shell(surface, shell_triangles[b], q))
        containers[a].push_back(static_cast<uint32_t>(b));
  }
  for (std::size_t a = 0; a < k; ++a) {
    shells[a].depth = static_cast<uint32_t>(containers[a].size());
    // Containers are nested, so the innermost one is the one with the most containers itself.
    for (uint32_t b : containers[a])
      if (shells[a].parent < 0 || containers[b].size() > containers[shells[a].parent].size()) shells[a].parent = static_cast<int32_t>(b);
  }
}

}  // namespace sweepcdt::io::detail
