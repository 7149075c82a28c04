#include "delaunay3.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>

#include "facet_groups.h"
#include "sweepcdt/error.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::detail {
namespace {

using predicates::Sign;
using predicates::Vertex;
using predicates::Vertices;
using Tet = std::array<uint32_t, 4>;

// The infinite vertex of the ghost tetrahedra. Never passed to a predicate: a ghost's infinite
// vertex is always replaced by a real point first.
constexpr uint32_t kInfinite = std::numeric_limits<uint32_t>::max();
// Neighbour links are 4 * tet + local index, so tetrahedron ids must stay below 2^30.
constexpr uint32_t kMaxTets = (1u << 30) - 1;

// ---------------------------------------------------------------------------------------------
// Insertion order: BRIO (Amenta, Choi, Rote) with Hilbert-sorted rounds, so that consecutive points
// are close (short walks) while the rounds keep the expected cavity sizes of a random order.

// Skilling's transform of 3 coordinates of `bits` bits into the Hilbert index, interleaved.
uint64_t hilbert_key(std::array<uint32_t, 3> x, int bits) {
  const uint32_t top = 1u << (bits - 1);
  for (uint32_t q = top; q > 1; q >>= 1) {
    const uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (x[i] & q) {
        x[0] ^= p;
      } else {
        const uint32_t t = (x[0] ^ x[i]) & p;
        x[0] ^= t;
        x[i] ^= t;
      }
    }
  }
  for (int i = 1; i < 3; ++i) x[i] ^= x[i - 1];
  uint32_t t = 0;
  for (uint32_t q = top; q > 1; q >>= 1)
    if (x[2] & q) t ^= q - 1;
  for (int i = 0; i < 3; ++i) x[i] ^= t;
  uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((x[i] >> b) & 1u);
  return key;
}

std::vector<uint64_t> hilbert_keys(const std::vector<double>& points) {
  const std::size_t n = points.size() / 3;
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], points[3 * i + k]);
      hi[k] = std::max(hi[k], points[3 * i + k]);
    }
  constexpr int kBits = 21;
  const double cells = static_cast<double>((1u << kBits) - 1);
  std::vector<uint64_t> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<uint32_t, 3> cell;
    for (int k = 0; k < 3; ++k) {
      const double extent = hi[k] - lo[k];
      const double f = extent > 0 ? (points[3 * i + k] - lo[k]) / extent : 0.0;
      // An overflowing extent (coordinates near +-DBL_MAX) gives inf or NaN: only the order suffers.
      cell[k] = f > 0 ? static_cast<uint32_t>(std::min(f, 1.0) * cells) : 0;
    }
    keys[i] = hilbert_key(cell, kBits);
  }
  return keys;
}

// A random permutation cut into rounds of doubling size (the last holds about half the points),
// each round sorted along the Hilbert curve. Deterministic: the seed is fixed.
std::vector<uint32_t> brio_order(const std::vector<double>& points) {
  const std::size_t n = points.size() / 3;
  std::vector<uint32_t> order(n);
  for (uint32_t i = 0; i < n; ++i) order[i] = i;
  std::mt19937 rng(12345);
  std::shuffle(order.begin(), order.end(), rng);
  const std::vector<uint64_t> keys = hilbert_keys(points);
  const auto by_key = [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; };
  constexpr std::size_t kFirstRound = 64;
  std::size_t end = n;
  while (end > 0) {
    const std::size_t begin = end <= kFirstRound ? 0 : end / 2;
    std::sort(order.begin() + begin, order.begin() + end, by_key);
    end = begin;
  }
  return order;
}

// ---------------------------------------------------------------------------------------------

class Delaunay3 {
 public:
  explicit Delaunay3(const std::vector<double>& points) : points_(points) {}

  std::vector<Tet> run(const std::vector<uint32_t>& order) {
    build(order);
    return finite_tets();
  }

  void build(const std::vector<uint32_t>& order, const std::function<void(std::size_t)>& inserted = {}) {
    vertex_tet_.assign(points_.size() / 3, kInfinite);
    touched_round_.assign(points_.size() / 3, round_);
    changed_.resize(points_.size() / 3);
    std::iota(changed_.begin(), changed_.end(), 0u);
    const std::vector<uint32_t> rest = start(order);
    cells_.reserve(7 * rest.size() + 16);
    constexpr std::size_t kReportEvery = 1024;
    for (std::size_t k = 0; k < rest.size(); ++k) {
      insert(rest[k]);
      if (inserted && k % kReportEvery == kReportEvery - 1) inserted(4 + k + 1);  // the first simplex's 4, then these
    }
  }

  // The live finite tetrahedra, renumbered densely, with their adjacency (delaunay3.h).
  DelaunayMesh mesh() const {
    std::vector<uint32_t> renumbered(cells_.size(), kInfinite);
    uint32_t count = 0;
    for (uint32_t t = 0; t < cells_.size(); ++t)
      if (!dead_[t] && infinite_index(t) == 4) renumbered[t] = count++;
    DelaunayMesh result;
    result.tets.reserve(4 * std::size_t{count});
    result.neighbors.reserve(4 * std::size_t{count});
    for (uint32_t t = 0; t < cells_.size(); ++t) {
      if (renumbered[t] == kInfinite) continue;
      for (int i = 0; i < 4; ++i) {
        result.tets.push_back(cells_[t].v[i]);
        const uint32_t across = cells_[t].n[i], u = renumbered[across >> 2];
        result.neighbors.push_back(u == kInfinite ? kInfinite : 4 * u + (across & 3u));
      }
    }
    return result;
  }

  // Inserts the points with ids from vertex_tet_.size() on (appended to the points since).
  void insert_new_points() {
    const std::size_t first = vertex_tet_.size(), n = points_.size() / 3;
    if (n == first) return;  // nothing changed: keep what touched() says
    vertex_tet_.resize(n, kInfinite);
    first_new_ = static_cast<uint32_t>(first);
    ++round_;
    touched_round_.resize(n, round_);
    changed_.resize(n - first);
    std::iota(changed_.begin(), changed_.end(), static_cast<uint32_t>(first));
    const std::vector<double> added(points_.begin() + 3 * first, points_.end());
    for (const uint32_t k : brio_order(added)) insert(static_cast<uint32_t>(first + k));
  }

  // Whether a tetrahedron at v was destroyed (or v was inserted) by the last build/insert_new_points:
  // an edge between two vertices that were not both touched is still there, or still missing.
  bool touched(uint32_t v) const { return touched_round_[v] == round_; }
  bool inserted_last(uint32_t v) const { return v >= first_new_; }
  std::size_t num_inserted() const { return vertex_tet_.size(); }
  // The points touched (new ones included) by the last build/insert_new_points, each once.
  const std::vector<uint32_t>& changed() const { return changed_; }

  // Whether ab is an edge: a search of the tetrahedra around a (ghosts included).
  bool has_edge(uint32_t a, uint32_t b) {
    stamp_ += 2;
    star_.assign(1, vertex_tet_[a]);
    marks_[star_[0]] = stamp_;
    for (std::size_t head = 0; head < star_.size(); ++head) {
      const Tet& v = cells_[star_[head]].v;
      for (int i = 0; i < 4; ++i) {
        if (v[i] == b) return true;
        if (v[i] == a) continue;
        const uint32_t u = neighbor(star_[head], i);  // shares the facet without v[i], which holds a
        if (marks_[u] != stamp_) marks_[u] = stamp_, star_.push_back(u);
      }
    }
    return false;
  }

 private:
  Vertex vertex(uint32_t id) const {
    return Vertex{id == kInfinite ? nullptr : points_.data() + 3 * std::size_t{id}, id};
  }
  const double* coords(uint32_t id) const { return points_.data() + 3 * std::size_t{id}; }

  // The tetrahedron's vertices with vertex `i` replaced by p (i = 4: none replaced).
  Vertices<4> with(uint32_t t, int i, const Vertex& p) const {
    Vertices<4> v;
    for (int k = 0; k < 4; ++k) v[k] = k == i ? p : vertex(cells_[t].v[k]);
    return v;
  }

  int infinite_index(uint32_t t) const {
    for (int k = 0; k < 4; ++k)
      if (cells_[t].v[k] == kInfinite) return k;
    return 4;
  }

  bool same_point(uint32_t a, uint32_t b) const {
    const double* x = coords(a);
    const double* y = coords(b);
    return x[0] == y[0] && x[1] == y[1] && x[2] == y[2];
  }

  bool collinear(uint32_t a, uint32_t b, uint32_t c) const { return predicates::collinear<3>(coords(a), coords(b), coords(c)); }

  // ------------------------------------------------------------------------------------------
  // The first tetrahedron: the first four affinely independent points of the order, and its four
  // ghosts. Returns the other points, in order.
  std::vector<uint32_t> start(const std::vector<uint32_t>& order) {
    const std::array<std::size_t, 4> first = first_simplex(order);
    Tet t{order[first[0]], order[first[1]], order[first[2]], order[first[3]]};
    if (orient(t) == Sign::Negative) std::swap(t[0], t[1]);
    make_first_tetrahedron(t);

    std::vector<uint32_t> rest;
    rest.reserve(order.size() - 4);
    for (std::size_t k = 0; k < order.size(); ++k)
      if (std::find(first.begin(), first.end(), k) == first.end()) rest.push_back(order[k]);
    return rest;
  }

  // Positions in `order` of a first point, the next one distinct from it, the next one off their
  // line, and the next one off their plane.
  std::array<std::size_t, 4> first_simplex(const std::vector<uint32_t>& order) const {
    const std::size_t n = order.size();
    std::size_t b = 1;
    while (b < n && same_point(order[0], order[b])) ++b;
    std::size_t c = b + 1;
    while (c < n && collinear(order[0], order[b], order[c])) ++c;
    std::size_t d = c + 1;
    while (d < n && orient({order[0], order[b], order[c], order[d]}) == Sign::Zero) ++d;
    if (d >= n)
      throw Error("delaunay_tetrahedra: needs 4 affinely independent points; the " + std::to_string(n) +
                  " points lie in one plane");
    return {0, b, c, d};
  }

  Sign orient(const Tet& t) const {
    return predicates::orient<3>({coords(t[0]), coords(t[1]), coords(t[2]), coords(t[3])});
  }

  // The positive tetrahedron t and, on each facet i, the ghost t with vertex i replaced by the
  // infinite vertex and two other vertices swapped: a ghost is "positive" when its infinite vertex
  // replaced by a point strictly outside its hull triangle gives a positive tetrahedron.
  void make_first_tetrahedron(const Tet& t) {
    const uint32_t inner = new_tet(t);
    for (int i = 0; i < 4; ++i) {
      Tet g = t;
      g[i] = kInfinite;
      std::swap(g[(i + 1) % 4], g[(i + 2) % 4]);
      const uint32_t ghost = new_tet(g);
      link(inner, i, ghost, i);
    }
    // Ghost-ghost facets: match by vertex sets (5 tetrahedra, brute force is fine).
    for (uint32_t a = 1; a < 5; ++a)
      for (uint32_t b = a + 1; b < 5; ++b)
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            if (sorted_facet(a, i) == sorted_facet(b, j)) link(a, i, b, j);
    last_ = inner;
  }

  std::array<uint32_t, 3> sorted_facet(uint32_t t, int i) const {
    std::array<uint32_t, 3> f;
    for (int k = 0, r = 0; k < 4; ++k)
      if (k != i) f[r++] = cells_[t].v[k];
    std::sort(f.begin(), f.end());
    return f;
  }

  // ------------------------------------------------------------------------------------------
  // Storage: flat arrays, freed slots reused.

  uint32_t new_tet(const Tet& v) {
    for (const uint32_t id : v)
      if (id != kInfinite) vertex_tet_[id] = static_cast<uint32_t>(free_.empty() ? cells_.size() : free_.back());
    uint32_t t;
    if (!free_.empty()) {
      t = free_.back();
      free_.pop_back();
      cells_[t].v = v;
      dead_[t] = 0;
    } else {
      if (cells_.size() >= kMaxTets) throw Error("delaunay_tetrahedra: too many tetrahedra");
      t = static_cast<uint32_t>(cells_.size());
      cells_.push_back({v, {kInfinite, kInfinite, kInfinite, kInfinite}});
      marks_.push_back(0);
      dead_.push_back(0);
    }
    return t;
  }

  void link(uint32_t t, int i, uint32_t u, int j) {
    cells_[t].n[i] = 4 * u + j;
    cells_[u].n[j] = 4 * t + i;
  }

  uint32_t neighbor(uint32_t t, int i) const { return cells_[t].n[i] >> 2; }

  // ------------------------------------------------------------------------------------------
  // Point location: a remembering stochastic visibility walk (Devillers, Pion, Teillaud) from the
  // last tetrahedron made. It ends in a finite tetrahedron whose closure holds p, or in a ghost whose
  // hull triangle p lies strictly outside of. Either one conflicts with p.

  uint32_t locate(const Vertex& p) {
    uint32_t t = last_;
    int came_from = 4;  // p is known to be strictly on t's side of this facet
    const std::size_t max_steps = cells_.size() + 16;  // the walk is acyclic in a Delaunay triangulation
    for (std::size_t step = 0; step < max_steps; ++step) {
      if (infinite_index(t) < 4) return t;
      const int r = static_cast<int>(next_random() & 3u);
      int exit = 4;
      for (int k = 0; k < 4 && exit == 4; ++k) {
        const int i = (r + k) & 3;
        if (i != came_from && predicates::orient<3>(coords_of(with(t, i, p))) == Sign::Negative) exit = i;
      }
      if (exit == 4) return t;
      const uint32_t next = cells_[t].n[exit];
      t = next >> 2;
      came_from = static_cast<int>(next & 3u);
    }
    throw Error("delaunay_tetrahedra: point location did not end (internal error)");
  }

  uint32_t next_random() {
    rng_ ^= rng_ << 13;
    rng_ ^= rng_ >> 17;
    rng_ ^= rng_ << 5;
    return rng_;
  }

  // ------------------------------------------------------------------------------------------
  // Conflicts (paper §6 perturbation throughout: no point is ever on a perturbed circumsphere).

  bool finite_conflict(uint32_t t, const Vertex& p) const {
    Vertices<5> v;
    for (int k = 0; k < 4; ++k) v[k] = vertex(cells_[t].v[k]);
    v[4] = p;
    // Stored tetrahedra are positive, so "inside" is a positive insphere.
    return predicates::insphere_perturbed<3>(v) == Sign::Positive;
  }

  bool in_conflict(uint32_t t, const Vertex& p) const {
    const int k = infinite_index(t);
    if (k == 4) return finite_conflict(t, p);
    const Sign side = predicates::orient<3>(coords_of(with(t, k, p)));
    if (side != Sign::Zero) return side == Sign::Positive;
    // p in the plane of the hull triangle: inside its perturbed circumcircle exactly when inside the
    // perturbed circumsphere of the finite tetrahedron behind it (see delaunay3.h).
    return finite_conflict(neighbor(t, k), p);
  }

  // ------------------------------------------------------------------------------------------
  // Bowyer–Watson: the conflict region, grown from the located tetrahedron through conflicting
  // neighbours, is replaced by the star of p over its boundary.

  struct BoundaryFacet {
    Tet vertices;      // the new tetrahedron: the conflict tetrahedron with vertex i replaced by p
    int i;             // p's local index in it
    uint32_t outside;  // 4 * u + j: the tetrahedron across the facet, not in conflict
  };

  void insert(uint32_t id) {
    const Vertex p = vertex(id);
    const uint32_t start = locate(p);
    if (infinite_index(start) == 4)
      for (const uint32_t v : cells_[start].v)
        if (same_point(v, id))
          throw Error("delaunay_tetrahedra: points " + std::to_string(v) + " and " + std::to_string(id) +
                      " coincide");
    if (!in_conflict(start, p)) throw Error("delaunay_tetrahedra: located tetrahedron not in conflict (internal error)");

    grow_cavity(start, p);
    for (const uint32_t c : conflicts_) {
      for (const uint32_t v : cells_[c].v)
        if (v != kInfinite && touched_round_[v] != round_) {
          touched_round_[v] = round_;
          changed_.push_back(v);
        }
      dead_[c] = 1;
      free_.push_back(c);
    }
    fill_cavity();
  }

  // Breadth-first search from `start`; fills conflicts_ and boundary_. Each tetrahedron is tested at
  // most once per insertion (marks_ holds this insertion's stamp: in or out).
  void grow_cavity(uint32_t start, const Vertex& p) {
    stamp_ += 2;
    const uint32_t in = stamp_, out = stamp_ + 1;
    conflicts_.clear();
    boundary_.clear();
    marks_[start] = in;
    conflicts_.push_back(start);
    for (std::size_t head = 0; head < conflicts_.size(); ++head) {
      const uint32_t c = conflicts_[head];
      for (int i = 0; i < 4; ++i) {
        const uint32_t u = neighbor(c, i);
        if (marks_[u] == in) continue;
        if (marks_[u] != out) {
          if (in_conflict(u, p)) {
            marks_[u] = in;
            conflicts_.push_back(u);
            continue;
          }
          marks_[u] = out;
        }
        Tet v = cells_[c].v;
        v[i] = p.id;
        boundary_.push_back({v, i, cells_[c].n[i]});
      }
    }
  }

  // The star of p: one tetrahedron per boundary facet, linked to the outside across that facet and
  // to each other across the facets through p, which pair up by their edge on the cavity boundary
  // (the boundary is a closed surface, so each edge belongs to exactly two boundary facets).
  void fill_cavity() {
    start_ridge_pairing(3 * boundary_.size());
    bool have_finite = false;
    for (const BoundaryFacet& b : boundary_) {
      const uint32_t t = new_tet(b.vertices);
      link(t, b.i, b.outside >> 2, static_cast<int>(b.outside & 3u));
      for (int m = 0; m < 4; ++m) {
        if (m == b.i) continue;
        std::array<uint32_t, 2> edge;
        for (int k = 0, r = 0; k < 4; ++k)
          if (k != m && k != b.i) edge[r++] = b.vertices[k];
        pair_ridge(edge_key(edge[0], edge[1]), t, m);
      }
      if (!have_finite && infinite_index(t) == 4) {
        last_ = t;
        have_finite = true;
      }
    }
    if (2 * ridges_paired_ != 3 * boundary_.size() || !have_finite)
      throw Error("delaunay_tetrahedra: cavity boundary is not a closed surface (internal error)");
  }

  // Ridge pairing: a small open-addressing table keyed by the edge, cleared by bumping a generation
  // instead of refilling (cavities are small, insertions many).
  struct RidgeSlot {
    uint64_t key;
    uint32_t generation;
    uint32_t link;  // 4 * tet + local index of the first facet seen, kInfinite once paired
  };

  void start_ridge_pairing(std::size_t entries) {
    std::size_t capacity = 64;
    while (capacity < 2 * entries) capacity *= 2;
    if (ridge_table_.size() < capacity) {
      ridge_table_.assign(capacity, RidgeSlot{0, 0, 0});
      ridge_generation_ = 0;
    }
    ++ridge_generation_;
    ridges_paired_ = 0;
  }

  void pair_ridge(uint64_t key, uint32_t t, int m) {
    const std::size_t mask = ridge_table_.size() - 1;
    for (std::size_t h = (key * 0x9E3779B97F4A7C15ull) >> 40 & mask;; h = (h + 1) & mask) {
      RidgeSlot& slot = ridge_table_[h];
      if (slot.generation != ridge_generation_) {
        slot = RidgeSlot{key, ridge_generation_, 4 * t + static_cast<uint32_t>(m)};
        return;
      }
      if (slot.key != key) continue;
      if (slot.link == kInfinite) throw Error("delaunay_tetrahedra: cavity edge in three facets (internal error)");
      link(t, m, slot.link >> 2, static_cast<int>(slot.link & 3u));
      slot.link = kInfinite;
      ++ridges_paired_;
      return;
    }
  }

  std::vector<Tet> finite_tets() const {
    std::vector<Tet> result;
    for (uint32_t t = 0; t < cells_.size(); ++t)
      if (!dead_[t] && infinite_index(t) == 4) result.push_back(cells_[t].v);
    return result;
  }

  const std::vector<double>& points_;
  // A tetrahedron: its vertices and, per facet i (opposite v[i]), 4 * neighbour + the neighbour's
  // local index of the same facet. One array, so a walk step touches one cache line.
  struct Cell {
    Tet v;
    Tet n;
  };
  std::vector<Cell> cells_;
  std::vector<uint32_t> marks_;
  std::vector<uint8_t> dead_;
  std::vector<uint32_t> free_;
  std::vector<uint32_t> vertex_tet_;  // per inserted point: a live tetrahedron holding it
  std::vector<uint32_t> star_;        // has_edge's search
  std::vector<uint32_t> touched_round_;  // per point: the last round (insert_new_points call) touching it
  std::vector<uint32_t> changed_;        // the points touched_round_ marks with round_
  uint32_t round_ = 0;
  uint32_t first_new_ = 0;  // the first point of the last build/insert_new_points
  std::vector<uint32_t> conflicts_;
  std::vector<BoundaryFacet> boundary_;
  std::vector<RidgeSlot> ridge_table_;
  uint32_t ridge_generation_ = 0;
  std::size_t ridges_paired_ = 0;
  uint32_t stamp_ = 0;
  uint32_t last_ = 0;
  uint32_t rng_ = 2463534242u;
};

// From point `first` on (the points appended since the last check).
void check_points(const std::vector<double>& points, std::size_t first = 0) {
  if (points.size() % 3 != 0) throw Error("delaunay_tetrahedra: the coordinate count is not a multiple of 3");
  if (points.size() / 3 >= kInfinite) throw Error("delaunay_tetrahedra: too many points");
  for (std::size_t i = 3 * first; i < points.size(); ++i)
    if (!std::isfinite(points[i]))
      throw Error("delaunay_tetrahedra: point " + std::to_string(i / 3) + " has a non-finite coordinate");
}

}  // namespace

struct DelaunayEdges::Impl {
  explicit Impl(const std::vector<double>& p) : points(p), triangulation(p) {}
  const std::vector<double>& points;
  Delaunay3 triangulation;
};

DelaunayEdges::DelaunayEdges(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted)
    : impl_(std::make_unique<Impl>(points)) {
  check_points(points);
  impl_->triangulation.build(brio_order(points), inserted);
}

DelaunayEdges::~DelaunayEdges() = default;

void DelaunayEdges::insert_new_points() {
  check_points(impl_->points, impl_->triangulation.num_inserted());
  impl_->triangulation.insert_new_points();
}

bool DelaunayEdges::has_edge(uint32_t a, uint32_t b) { return impl_->triangulation.has_edge(a, b); }

DelaunayMesh DelaunayEdges::mesh() const { return impl_->triangulation.mesh(); }

bool DelaunayEdges::may_have_changed(uint32_t a, uint32_t b) const {
  const Delaunay3& t = impl_->triangulation;
  return (t.touched(a) && t.touched(b)) || t.inserted_last(a) || t.inserted_last(b);
}

const std::vector<uint32_t>& DelaunayEdges::changed_points() const { return impl_->triangulation.changed(); }

std::vector<std::array<uint32_t, 4>> delaunay_tetrahedra(const std::vector<double>& points) {
  check_points(points);
  return Delaunay3(points).run(brio_order(points));
}

DelaunayMesh delaunay_mesh(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted) {
  check_points(points);
  Delaunay3 triangulation(points);
  triangulation.build(brio_order(points), inserted);
  return triangulation.mesh();
}

std::vector<std::array<uint32_t, 4>> delaunay_tetrahedra_in_order(const std::vector<double>& points,
                                                                  const std::vector<uint32_t>& order) {
  check_points(points);
  const std::size_t n = points.size() / 3;
  std::vector<uint8_t> seen(n, 0);
  for (const uint32_t id : order)
    if (id >= n || seen[id]++) throw Error("delaunay_tetrahedra_in_order: the order is not a permutation");
  if (order.size() != n) throw Error("delaunay_tetrahedra_in_order: the order is not a permutation");
  return Delaunay3(points).run(order);
}

}  // namespace sweepcdt::detail
