// Paper §1: occlusion of visibility by a constraining (D-1)-simplex.
#include "sweepcdt/predicates/occlusion.h"

#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::predicates {

template <int D>
Coords<D + 1> with_point(const Coords<D>& f, const double* p);  // sweep_sides.cpp

// With p and q strictly on opposite sides of t's hyperplane, the segment pq crosses it at one point
// x, and x lies in t (closed) iff x is on t's side of each ridge of t within the hyperplane. In
// terms of orientations: the signs (-1)^i orient(p, q, t without t_i) are never both > 0 and < 0.
// (D = 2: t_0 and t_1 are on opposite sides of line pq; D = 3: the classic three orient3d tests.)
template <int D>
bool occludes(const Coords<D>& t, const double* p, const double* q) {
  const Sign op = orient<D>(with_point<D>(t, p));
  const Sign oq = orient<D>(with_point<D>(t, q));
  if (op == Sign::Zero || oq == Sign::Zero || op == oq) return false;
  bool positive = false, negative = false;
  for (int i = 0; i < D; ++i) {
    Coords<D + 1> points;
    points[0] = p;
    points[1] = q;
    for (int j = 0, r = 2; j < D; ++j)
      if (j != i) points[r++] = t[j];
    Sign s = orient<D>(points);
    if (i & 1) s = -s;
    positive |= s == Sign::Positive;
    negative |= s == Sign::Negative;
  }
  return !(positive && negative);
}

template bool occludes<2>(const Coords<2>&, const double*, const double*);
template bool occludes<3>(const Coords<3>&, const double*, const double*);
template bool occludes<4>(const Coords<4>&, const double*, const double*);
template bool occludes<5>(const Coords<5>&, const double*, const double*);

}  // namespace sweepcdt::predicates
