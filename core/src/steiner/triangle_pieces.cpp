#include "triangle_pieces.h"

#include <algorithm>

#include "facet_groups.h"

namespace sweepcdt::detail {

void TrianglePieces::start(std::size_t num_points) {
  const auto n = static_cast<uint32_t>(tris_.size());
  next_.resize(n);
  position_.resize(n);
  for (uint32_t s = 0; s < n; ++s) next_[s] = s + 1 < n ? s + 1 : kNone, position_[s] = s;
  incident_.assign(num_points, {});
  for (uint32_t s = 0; s < n; ++s)
    for (const uint32_t v : tris_[s]) incident_[v].push_back(s);
  split_since_ordered_ = true;
}

void TrianglePieces::split(const std::unordered_map<uint64_t, uint32_t>& new_point, std::size_t num_points,
                           std::vector<uint32_t>& steiner_on, uint32_t first_steiner) {
  if (new_point.empty()) return;
  if (!split_since_ordered_) start(num_points);
  incident_.resize(num_points);
  // The triangles holding a split edge, in order: a triangle before the pieces of a later one. Two
  // triangles with one segment between them are pieces of different triangles of the last ordering
  // (the pieces of one tile it, and a segment lies on their boundary), so their positions tell.
  std::vector<uint32_t> found;
  for (const auto& [key, m] : new_point) {
    const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    for (const uint32_t s : incident_[a])
      if (std::find(tris_[s].begin(), tris_[s].end(), b) != tris_[s].end()) found.push_back(s);
  }
  std::sort(found.begin(), found.end(), [&](uint32_t s, uint32_t t) { return std::pair{position_[s], s} < std::pair{position_[t], t}; });
  found.erase(std::unique(found.begin(), found.end()), found.end());
  std::vector<Triangle> work;
  for (const uint32_t s : found) {
    // The triangle split along each of its split edges in turn: (a, b, c) at m on ab gives
    // (a, m, c), then (m, b, c) at the end; each piece looked at again for its other split edges.
    work.assign(1, tris_[s]);
    for (std::size_t w = 0; w < work.size(); ++w)
      for (int i = 0; i < 3; ++i) {
        const auto it = new_point.find(edge_key(work[w][i], work[w][(i + 1) % 3]));
        if (it == new_point.end()) continue;
        const uint32_t m = it->second;
        uint32_t& on = steiner_on[m - first_steiner];
        if (on == kNone) on = original_[s];
        Triangle second = work[w];
        work[w][(i + 1) % 3] = m;
        second[i] = m;
        work.push_back(second);
        --w;
        break;
      }
    for (const uint32_t v : tris_[s]) {
      auto& list = incident_[v];
      list.erase(std::find(list.begin(), list.end(), s));
    }
    tris_[s] = work[0];
    unflipped_[s] = 1;
    uint32_t last = s;
    const uint32_t after = next_[s];
    for (std::size_t k = 1; k < work.size(); ++k) {
      const auto slot = static_cast<uint32_t>(tris_.size());
      tris_.push_back(work[k]);
      original_.push_back(original_[s]);
      unflipped_.push_back(1);
      position_.push_back(position_[s]);
      next_.push_back(kNone);
      next_[last] = slot;
      last = slot;
    }
    next_[last] = after;
    for (uint32_t slot = s;; slot = next_[slot]) {
      for (const uint32_t v : tris_[slot]) incident_[v].push_back(slot);
      if (slot == last) break;
    }
  }
}

void TrianglePieces::changed(uint32_t slot, const Triangle& before) {
  if (!split_since_ordered_) return;  // start() lists them from the triangles as they are then
  for (const uint32_t v : before)
    if (std::find(tris_[slot].begin(), tris_[slot].end(), v) == tris_[slot].end()) {
      auto& list = incident_[v];
      list.erase(std::find(list.begin(), list.end(), slot));
    }
  for (const uint32_t v : tris_[slot])
    if (std::find(before.begin(), before.end(), v) == before.end()) incident_[v].push_back(slot);
}

void TrianglePieces::put_in_order() {
  if (!split_since_ordered_) return;
  std::vector<Triangle> tris;
  std::vector<uint32_t> original;
  std::vector<char> unflipped;
  tris.reserve(tris_.size());
  original.reserve(tris_.size());
  unflipped.reserve(tris_.size());
  for (uint32_t s = tris_.empty() ? kNone : 0; s != kNone; s = next_[s]) {  // slot 0 stays first: pieces follow their slot
    tris.push_back(tris_[s]);
    original.push_back(original_[s]);
    unflipped.push_back(unflipped_[s]);
  }
  tris_.swap(tris);
  original_.swap(original);
  unflipped_.swap(unflipped);
  split_since_ordered_ = false;
}

}  // namespace sweepcdt::detail
