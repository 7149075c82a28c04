// Where SteinerMode::Auto places a point on a segment (core/src/steiner/refine.h), exposed so that
// tools which check a mesh (`sweepcdt check`) can recognise a Steiner point exactly instead of
// trusting a tolerance.
//
// Every Steiner point is the rounded point a + t (b - a) of the two points a, b it splits, computed
// coordinate by coordinate in double arithmetic, operation for operation:
//     out[k] = a[k] + t * (b[k] - a[k])          for some double t in (0, 1)
// refine chooses t by the concentric-shell rule of Ruppert and Shewchuk: a segment with exactly one
// input vertex v as an end is split at distance 2^k from v (the power of two nearest half its
// length; t rounded to 20 bits, below), so subsegments that meet at v end on common spheres about
// it; any other segment at its midpoint t = 1/2 (a being the end with the smaller point id). When that point coincides with an
// existing one (two segments within rounding of each other), it takes t = 1/2, 1/4 or 3/4 instead.
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

// The concentric-shell split point of the segment ab (above). `a_is_input`/`b_is_input`: whether
// each end is an input vertex; for a midpoint the caller passes the end with the smaller id as `a`.
inline void segment_split_point(const double* a, bool a_is_input, const double* b, bool b_is_input, double* out) {
  if (a_is_input == b_is_input) return point_on_segment(a, b, 0.5, out);
  const double* v = a_is_input ? a : b;
  const double* w = a_is_input ? b : a;
  double length2 = 0;
  for (int k = 0; k < 3; ++k) length2 += (w[k] - v[k]) * (w[k] - v[k]);
  const double length = std::sqrt(length2);
  const double t = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(length / 2)))) / length;
  // t rounded to a multiple of 2^-kShellBits: a short t keeps the point exactly on the segment when
  // the ends' coordinates have few significant bits (float32 surfaces: STL, glTF, Draco, PLY), and a
  // point exactly on the segment makes no folds (refine.h). Shell radii then agree to 2^-20, which
  // protects segments meeting at angles down to about a tenth of a degree.
  point_on_segment(v, w, std::ldexp(std::round(std::ldexp(t, kShellBits)), -kShellBits), out);
}

// Whether x == point_on_segment(a, b, t) for some double t in (0, 1), or the same from b to a, and x
// is neither a nor b. Exact: no tolerance.
bool is_point_on_segment(const double* a, const double* b, const double* x);

}  // namespace sweepcdt
