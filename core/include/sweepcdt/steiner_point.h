// Where SteinerMode::Auto places a point on a segment (core/src/steiner/refine.h), exposed so that
// tools which check a mesh (`sweepcdt check`) can recognise a Steiner point exactly instead of
// trusting a tolerance.
//
// Every Steiner point on a segment is the rounded point u + t (v - u) of the segment's two input
// ends u, v (u the one with the smaller id), computed coordinate by coordinate in double arithmetic,
// operation for operation:
//     out[k] = u[k] + t * (v[k] - u[k])          for some double t in (0, 1)
// — however often the segment was split before: refine keeps each point's t along its input
// segment and splits a piece [ta, tb] of it at a t between (split_parameter below), so no point is
// a rounding of other rounded points, and `check` needs no other Steiner point to recognise it (the
// deletion pass may delete any of them). That holds when v - u is exact in double (always for
// float32 coordinates; refine.cpp says why it matters); on other segments a point is the same
// construction from the ends a, b of the piece it splits (0 and 1 their t), as it is inside a fold
// (below). t follows the concentric-shell rule of Ruppert and
// Shewchuk: a piece with exactly one input vertex as an end is split at distance 2^k from it (the
// power of two nearest half its length; the distance rounded to 20 significant bits of the piece,
// below), so pieces that meet at an input vertex end on common spheres about it; a piece between
// two Steiner points where the vertex that encroaches it most projects onto it (parameter_between),
// any other at its middle. When that point coincides with an existing one (two segments within rounding of
// each other), it takes a quarter or three quarters of the piece instead. A fold point (a point inside
// a facet, refine.h) is the rounded point a + t (b - a) of the two points a, b of the fold it splits.
// The recogniser below does not need to know which t: each coordinate is a monotone function of t,
// so whether some t gives exactly the stored point is decided exactly by a search over the doubles
// t. A point that passes lies on its segment up to the rounding of that one construction — no
// tolerance is involved.
#pragma once
#include <cmath>

namespace sweepcdt {

// The rounded point a + t (b - a) (3D), as above.
inline void point_on_segment(const double* a, const double* b, double t, double* out) {
  for (int k = 0; k < 3; ++k) out[k] = a[k] + t * (b[k] - a[k]);
}

inline constexpr int kShellBits = 20;

// The parameter at which refine splits the piece [ta, tb] (ta < tb) of a segment of length `length`
// (above). `a_is_input`/`b_is_input`: whether the piece's end at ta/tb is an input vertex.
inline double split_parameter(double ta, bool a_is_input, double tb, bool b_is_input, double length) {
  if (a_is_input == b_is_input) return 0.5 * (ta + tb);
  const double span = tb - ta;
  const double radius = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(span * length / 2))));
  // The distance rounded to a multiple of 2^-kShellBits of the piece: a short t keeps the point
  // exactly on the segment when the ends' coordinates have few significant bits (float32 surfaces:
  // STL, glTF, Draco, PLY), and a point exactly on the segment makes no folds (refine.h). Shell radii
  // then agree to 2^-20, which protects segments meeting at angles down to about a tenth of a degree.
  const double quantum = std::ldexp(1.0, std::ilogb(span) - kShellBits);
  const double step = std::round(radius / length / quantum) * quantum;
  return a_is_input ? ta + step : tb - step;
}

// The parameter `fraction` of the way from ta to tb (either order), its distance from ta rounded to
// 2^-kShellBits of the piece as split_parameter rounds the shells' (refine splits a piece between
// two Steiner points where the vertex encroaching it most projects onto it).
inline double parameter_between(double ta, double tb, double fraction) {
  const double span = std::fabs(tb - ta);
  const double quantum = std::ldexp(1.0, std::ilogb(span) - kShellBits);
  return ta + std::copysign(std::round(fraction * span / quantum) * quantum, tb - ta);
}

// Whether x == point_on_segment(a, b, t) for some double t in (0, 1), or the same from b to a, and x
// is neither a nor b. Exact: no tolerance.
bool is_point_on_segment(const double* a, const double* b, const double* x);

}  // namespace sweepcdt
