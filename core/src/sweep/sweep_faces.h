// The triangulation data structure of SWEEPCDT (paper §3, Figure 12): hyperface records, each on D
// circular doubly-linked lists — one per ridge, in rotary order around the ridge — with a drop list
// of the vertices whose drop face it is; the ridge dictionary (sorted (D-1)-tuple -> one face on the
// ridge's list); and a face dictionary (sorted D-tuple -> face) to tell preexisting faces from new
// ones. Faces are indices into a vector; lists are index links.
//
//   ridge i of a face = the face without its vertex v[i] (v sorted by id)
//   next[i] / prev[i] = the neighbouring faces on ridge i's list, in the positive rotary sense:
//   b follows a when orient(ridge (sorted), a's apex, b's apex) > 0 (predicates/rotary.h)
#pragma once
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "../facet_hash.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail::sweep {

template <int D>
using FaceKey = std::array<uint32_t, D>;
template <int D>
using RidgeKey = std::array<uint32_t, D - 1>;

template <int D>
struct Face {
  FaceKey<D> v;                   // sorted vertex ids
  std::array<uint32_t, D> next;   // per ridge: next face in positive rotary order
  std::array<uint32_t, D> prev;
  uint32_t drop = kNone;          // head of the drop list (vertex ids, linked by Sweep::drop_next_)
  uint32_t version = 0;           // bumped when its candidate changes: stale queue items are skipped
  uint32_t constraint = kNone;    // the constraining simplex it is, if any
  int8_t front = 0;               // sign of orient(v sorted, x) for x in front of the face
  bool built_front = false;       // the simplex in front exists (or the front is exterior)
  bool built_behind = false;      // the simplex behind exists (or the behind is exterior)
};

template <int D>
RidgeKey<D> ridge_of(const FaceKey<D>& f, int i) {
  RidgeKey<D> r;
  for (int k = 0, j = 0; k < D; ++k)
    if (k != i) r[j++] = f[k];
  return r;
}

// The local index of the ridge `r` in face f (the position of f's vertex not in r).
template <int D>
int ridge_index(const FaceKey<D>& f, const RidgeKey<D>& r) {
  for (int i = 0; i < D; ++i)
    if (ridge_of<D>(f, i) == r) return i;
  return -1;
}

}  // namespace sweepcdt::detail::sweep
