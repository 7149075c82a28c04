// Where SteinerMode::Auto splits a segment (core/src/steiner/refine.h), exposed so that tools which
// check a mesh (`sweepcdt check`) can reproduce a Steiner point bit for bit instead of trusting a
// tolerance.
//
// The concentric-shell rule of Ruppert and Shewchuk: a segment with exactly one input vertex v as an
// end is split at distance 2^k from v (the power of two nearest half its length), so subsegments that
// meet at v end on common spheres about it; any other segment at its midpoint. In double arithmetic,
// operation for operation:
//   shell:    L = sqrt(sum (w - v)^2), t = 2^round(log2(L / 2)) / L, point = v + t (w - v)
//   midpoint: point = a + (b - a) / 2, a being the end with the smaller point id
#pragma once
#include <cmath>

namespace sweepcdt {

// The split point of the segment from a to b (3D). `a_is_input`/`b_is_input`: whether each end is
// an input vertex; for a midpoint the caller passes the end with the smaller id as `a`.

inline void segment_split_point(const double* a, bool a_is_input, const double* b, bool b_is_input, double* out) {
  if (a_is_input != b_is_input) {
    const double* v = a_is_input ? a : b;
    const double* w = a_is_input ? b : a;
    double length2 = 0;
    for (int k = 0; k < 3; ++k) length2 += (w[k] - v[k]) * (w[k] - v[k]);
    const double length = std::sqrt(length2);
    const double t = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(length / 2)))) / length;
    for (int k = 0; k < 3; ++k) out[k] = v[k] + t * (w[k] - v[k]);
  } else {
    for (int k = 0; k < 3; ++k) out[k] = a[k] + (b[k] - a[k]) / 2;
  }
}

}  // namespace sweepcdt
