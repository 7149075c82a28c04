#include "delaunay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>

#include "sweepcdt/error.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::detail {
namespace {

using predicates::Sign;
using predicates::Vertex;
using predicates::Vertices;

// The infinite vertex of the ghost simplices. Never passed to a predicate: a ghost's infinite vertex
// is always replaced by a real point first.
constexpr uint32_t kInfinite = std::numeric_limits<uint32_t>::max();

// ---------------------------------------------------------------------------------------------
// Insertion order: BRIO (Amenta, Choi, Rote) with Hilbert-sorted rounds, so that consecutive points
// are close (short walks) while the rounds keep the expected cavity sizes of a random order.

// Skilling's transform of D coordinates of `bits` bits into the Hilbert index, interleaved.
template <int D>
uint64_t hilbert_key(std::array<uint32_t, D> x, int bits) {
  const uint32_t top = 1u << (bits - 1);
  for (uint32_t q = top; q > 1; q >>= 1) {
    const uint32_t p = q - 1;
    for (int i = 0; i < D; ++i) {
      if (x[i] & q) {
        x[0] ^= p;
      } else {
        const uint32_t t = (x[0] ^ x[i]) & p;
        x[0] ^= t;
        x[i] ^= t;
      }
    }
  }
  for (int i = 1; i < D; ++i) x[i] ^= x[i - 1];
  uint32_t t = 0;
  for (uint32_t q = top; q > 1; q >>= 1)
    if (x[D - 1] & q) t ^= q - 1;
  for (int i = 0; i < D; ++i) x[i] ^= t;
  uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < D; ++i) key = (key << 1) | ((x[i] >> b) & 1u);
  return key;
}

template <int D>
std::vector<uint64_t> hilbert_keys(const std::vector<double>& points) {
  const std::size_t n = points.size() / D;
  std::array<double, D> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], points[D * i + k]);
      hi[k] = std::max(hi[k], points[D * i + k]);
    }
  constexpr int kBits = D <= 3 ? 21 : 63 / D;  // the key holds D * kBits bits
  const double cells = static_cast<double>((1u << kBits) - 1);
  std::vector<uint64_t> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<uint32_t, D> cell;
    for (int k = 0; k < D; ++k) {
      const double extent = hi[k] - lo[k];
      const double f = extent > 0 ? (points[D * i + k] - lo[k]) / extent : 0.0;
      // An overflowing extent (coordinates near +-DBL_MAX) gives inf or NaN: only the order suffers.
      cell[k] = f > 0 ? static_cast<uint32_t>(std::min(f, 1.0) * cells) : 0;
    }
    keys[i] = hilbert_key<D>(cell, kBits);
  }
  return keys;
}

// A random permutation cut into rounds of doubling size (the last holds about half the points),
// each round sorted along the Hilbert curve. Deterministic: the seed is fixed.
template <int D>
std::vector<uint32_t> brio_order(const std::vector<double>& points) {
  const std::size_t n = points.size() / D;
  std::vector<uint32_t> order(n);
  for (uint32_t i = 0; i < n; ++i) order[i] = i;
  std::mt19937 rng(12345);
  std::shuffle(order.begin(), order.end(), rng);
  const std::vector<uint64_t> keys = hilbert_keys<D>(points);
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

// Do the K + 1 points (in E^D) span a K-flat? Exactly: K = D is their orientation; otherwise some
// projection onto K of the D axes has a nonzero orientation (a K x D matrix has rank K exactly when
// one of its K x K minors is nonzero). For K = 1: the two points differ; for K = 2: not collinear.
template <int K, int D>
bool spans_flat(const std::array<const double*, K + 1>& p) {
  if constexpr (K == D) {
    return predicates::orient<D>(p) != Sign::Zero;
  } else {
    std::array<int, K> axes;
    std::iota(axes.begin(), axes.end(), 0);
    std::array<std::array<double, K>, K + 1> projected;
    predicates::Coords<K + 1> q;
    for (;;) {
      for (int i = 0; i <= K; ++i) {
        for (int k = 0; k < K; ++k) projected[i][k] = p[i][axes[k]];
        q[i] = projected[i].data();
      }
      if (predicates::orient<K>(q) != Sign::Zero) return true;
      int k = K - 1;  // the next K-subset of 0..D-1 in lexicographic order
      while (k >= 0 && axes[k] == D - K + k) --k;
      if (k < 0) return false;
      ++axes[k];
      for (int j = k + 1; j < K; ++j) axes[j] = axes[j - 1] + 1;
    }
  }
}

// ---------------------------------------------------------------------------------------------

template <int D>
class Delaunay {
  using Simplex = std::array<uint32_t, D + 1>;
  using Ridge = std::array<uint32_t, D - 1>;  // sorted ids
  // Neighbour links are (simplex << kLinkBits) | local index.
  static constexpr int kLinkBits = D + 1 <= 4 ? 2 : 3;
  static constexpr uint32_t kLinkMask = (1u << kLinkBits) - 1;
  static constexpr uint32_t kMaxSimplices = (1u << (32 - kLinkBits)) - 1;
  // About how many simplices, ghosts included, a point brings (random points: 6.5 in 3D, 29 in 4D,
  // 145 in 5D).
  static constexpr std::size_t kCellsPerPoint = D == 2 ? 4 : D == 3 ? 7 : D == 4 ? 32 : 160;

 public:
  explicit Delaunay(const std::vector<double>& points) : points_(&points) {}
  // The same points in another vector (its first num_inserted() points equal to these).
  void rebind(const std::vector<double>& points) { points_ = &points; }
  const std::vector<double>& points() const { return *points_; }

  std::vector<Simplex> run(const std::vector<uint32_t>& order) {
    build(order);
    return finite_simplices();
  }

  void build(const std::vector<uint32_t>& order, const std::function<void(std::size_t)>& inserted = {}) {
    const std::size_t n = points_->size() / D;
    vertex_simplex_.assign(n, kInfinite);
    touched_round_.assign(n, round_);
    changed_.resize(n);
    std::iota(changed_.begin(), changed_.end(), 0u);
    const std::vector<uint32_t> rest = start(order);
    cells_.reserve(kCellsPerPoint * rest.size() + 16);
    constexpr std::size_t kReportEvery = 1024;
    for (std::size_t k = 0; k < rest.size(); ++k) {
      insert(rest[k]);
      if (inserted && k % kReportEvery == kReportEvery - 1) inserted(D + 1 + k + 1);  // the first simplex's, then these
    }
  }

  // The triangulation `mesh` (as mesh() gives it) of all the points, taken as if built here: the
  // finite simplices in its order, then a ghost on each hull facet (add_ghost, link_ghosts, as
  // make_first_simplex() makes them). Every point counts as inserted last (as after build()). False when some point is
  // no vertex of the mesh.
  bool adopt(const DelaunayMesh& mesh) {
    const std::size_t n = points_->size() / D, count = mesh.tets.size() / (D + 1);
    vertex_simplex_.assign(n, kInfinite);
    touched_round_.assign(n, round_);
    changed_.resize(n);
    std::iota(changed_.begin(), changed_.end(), 0u);
    first_new_ = 0;
    cells_.clear();
    marks_.clear();
    dead_.clear();
    free_.clear();
    cells_.reserve(kCellsPerPoint * n + 16);
    if (std::any_of(mesh.tets.begin(), mesh.tets.end(), [&](uint32_t v) { return v >= n; })) return false;
    for (std::size_t t = 0; t < count; ++t) {
      Simplex v;
      std::copy_n(mesh.tets.begin() + (D + 1) * t, D + 1, v.begin());
      new_simplex(v);
    }
    std::vector<uint32_t> ghosts;
    for (uint32_t t = 0; t < count; ++t)
      for (int i = 0; i <= D; ++i) {
        const uint32_t across = mesh.neighbors[(D + 1) * t + i];
        if (across == kInfinite) ghosts.push_back(add_ghost(t, i));
        else cells_[t].n[i] = across / (D + 1) << kLinkBits | across % (D + 1);
      }
    link_ghosts(ghosts);
    std::fill(vertex_simplex_.begin(), vertex_simplex_.end(), kInfinite);
    for (uint32_t t = 0; t < count; ++t)  // a finite simplex at each point
      for (const uint32_t v : cells_[t].v) vertex_simplex_[v] = t;
    last_ = 0;
    return std::find(vertex_simplex_.begin(), vertex_simplex_.end(), kInfinite) == vertex_simplex_.end();
  }

  // The live finite simplices, renumbered densely, with their adjacency (delaunay.h).
  DelaunayMesh mesh() const {
    std::vector<uint32_t> renumbered(cells_.size(), kInfinite);
    uint32_t count = 0;
    for (uint32_t t = 0; t < cells_.size(); ++t)
      if (!dead_[t] && infinite_index(t) == D + 1) renumbered[t] = count++;
    DelaunayMesh result;
    result.tets.reserve((D + 1) * std::size_t{count});
    result.neighbors.reserve((D + 1) * std::size_t{count});
    for (uint32_t t = 0; t < cells_.size(); ++t) {
      if (renumbered[t] == kInfinite) continue;
      for (int i = 0; i <= D; ++i) {
        result.tets.push_back(cells_[t].v[i]);
        const uint32_t across = cells_[t].n[i], u = renumbered[across >> kLinkBits];
        result.neighbors.push_back(u == kInfinite ? kInfinite : (D + 1) * u + (across & kLinkMask));
      }
    }
    return result;
  }

  // Inserts the points with ids from vertex_simplex_.size() on (appended to the points since), each
  // located from near(id) when that is an inserted point (DelaunayEdges::insert_new_points).
  void insert_new_points(const std::function<uint32_t(uint32_t)>& near = {}) {
    const std::size_t first = vertex_simplex_.size(), n = points_->size() / D;
    if (n == first) return;  // nothing changed: keep what touched() says
    vertex_simplex_.resize(n, kInfinite);
    first_new_ = static_cast<uint32_t>(first);
    ++round_;
    touched_round_.resize(n, round_);
    changed_.resize(n - first);
    std::iota(changed_.begin(), changed_.end(), static_cast<uint32_t>(first));
    const std::vector<double> added(points_->begin() + D * first, points_->end());
    for (const uint32_t k : brio_order<D>(added)) {
      const uint32_t id = static_cast<uint32_t>(first + k);
      insert(id, near ? near(id) : kInfinite);
    }
  }

  // Whether a simplex at v was destroyed (or v was inserted) by the last build/insert_new_points:
  // an edge between two vertices that were not both touched is still there, or still missing.
  bool touched(uint32_t v) const { return touched_round_[v] == round_; }
  bool inserted_last(uint32_t v) const { return v >= first_new_; }
  std::size_t num_inserted() const { return vertex_simplex_.size(); }
  // The points touched (new ones included) by the last build/insert_new_points, each once.
  const std::vector<uint32_t>& changed() const { return changed_; }

  // The vertices of the tetrahedra around a (the infinite one excluded; with repeats).
  void link_vertices(uint32_t a, std::vector<uint32_t>& out) {
    any_star_vertex(a, [&](uint32_t u) {
      if (u != kInfinite) out.push_back(u);
      return false;
    });
  }
  // Whether ab is an edge: a search of the simplices around a (ghosts included).
  bool has_edge(uint32_t a, uint32_t b) {
    return any_star_vertex(a, [&](uint32_t u) { return u == b; });
  }
  // Whether visit(u) is true for some vertex u != a of a tetrahedron around a, visiting them
  // tetrahedron by tetrahedron out from a's (with repeats) until it is.
  template <class Visit>
  bool any_star_vertex(uint32_t a, Visit&& visit) {
    stamp_ += 2;
    star_.assign(1, vertex_simplex_[a]);
    marks_[star_[0]] = stamp_;
    for (std::size_t head = 0; head < star_.size(); ++head) {
      const Simplex& v = cells_[star_[head]].v;
      for (int i = 0; i <= D; ++i)  // the marks all asked for before the first is read (as in grow_cavity)
        if (v[i] != a) __builtin_prefetch(&marks_[neighbor(star_[head], i)]);
      for (int i = 0; i <= D; ++i) {
        if (v[i] == a) continue;
        if (visit(v[i])) return true;
        const uint32_t u = neighbor(star_[head], i);  // shares the facet without v[i], which holds a
        if (marks_[u] != stamp_) marks_[u] = stamp_, star_.push_back(u), __builtin_prefetch(&cells_[u]);
      }
    }
    return false;
  }

 private:
  Vertex vertex(uint32_t id) const {
    return Vertex{id == kInfinite ? nullptr : points_->data() + D * std::size_t{id}, id};
  }
  const double* coords(uint32_t id) const { return points_->data() + D * std::size_t{id}; }

  // The simplex's vertices with vertex `i` replaced by p (i = D + 1: none replaced).
  Vertices<D + 1> with(uint32_t t, int i, const Vertex& p) const {
    Vertices<D + 1> v;
    for (int k = 0; k <= D; ++k) v[k] = k == i ? p : vertex(cells_[t].v[k]);
    return v;
  }

  int infinite_index(uint32_t t) const {
    for (int k = 0; k <= D; ++k)
      if (cells_[t].v[k] == kInfinite) return k;
    return D + 1;
  }

  bool same_point(uint32_t a, uint32_t b) const { return std::equal(coords(a), coords(a) + D, coords(b)); }

  // ------------------------------------------------------------------------------------------
  // The first simplex: the first D + 1 affinely independent points of the order, and its ghosts.
  // Returns the other points, in order.
  std::vector<uint32_t> start(const std::vector<uint32_t>& order) {
    const std::array<std::size_t, D + 1> first = first_simplex(order);
    Simplex s;
    for (int k = 0; k <= D; ++k) s[k] = order[first[k]];
    if (orient(s) == Sign::Negative) std::swap(s[0], s[1]);
    make_first_simplex(s);

    std::vector<uint32_t> rest;
    rest.reserve(order.size() - (D + 1));
    for (std::size_t k = 0; k < order.size(); ++k)
      if (std::find(first.begin(), first.end(), k) == first.end()) rest.push_back(order[k]);
    return rest;
  }

  // Positions in `order` of a first point, the next one distinct from it, the next one off their
  // line, the next one off their plane, and so on up to a D-simplex.
  std::array<std::size_t, D + 1> first_simplex(const std::vector<uint32_t>& order) const {
    std::array<std::size_t, D + 1> first{};
    std::size_t next = 1;
    if (order.empty()) throw_flat(0);
    choose<1>(order, first, next);
    return first;
  }

  // Chooses first[K], the next point from `next` on that spans a K-flat with first[0..K-1].
  template <int K>
  void choose(const std::vector<uint32_t>& order, std::array<std::size_t, D + 1>& first, std::size_t& next) const {
    std::array<const double*, K + 1> p;
    for (int k = 0; k < K; ++k) p[k] = coords(order[first[k]]);
    for (;; ++next) {
      if (next >= order.size()) throw_flat(order.size());
      p[K] = coords(order[next]);
      if (spans_flat<K, D>(p)) break;
    }
    first[K] = next++;
    if constexpr (K < D) choose<K + 1>(order, first, next);
  }

  [[noreturn]] static void throw_flat(std::size_t n) {
    throw Error("delaunay_simplices: needs " + std::to_string(D + 1) + " affinely independent points; the " +
                std::to_string(n) + " points lie in one " + (D == 3 ? "plane" : "hyperplane"));
  }

  Sign orient(const Simplex& s) const {
    predicates::Coords<D + 1> c;
    for (int k = 0; k <= D; ++k) c[k] = coords(s[k]);
    return predicates::orient<D>(c);
  }

  // The positive simplex s and, on each facet i, the ghost s with vertex i replaced by the infinite
  // vertex and two other vertices swapped: a ghost is "positive" when its infinite vertex replaced by
  // a point strictly outside its hull facet gives a positive simplex.
  void make_first_simplex(const Simplex& s) {
    const uint32_t inner = new_simplex(s);
    std::vector<uint32_t> ghosts;
    for (int i = 0; i <= D; ++i) ghosts.push_back(add_ghost(inner, i));
    link_ghosts(ghosts);
    last_ = inner;
  }

  // A ghost on facet i of the finite simplex t (a hull facet), linked to t: t with vertex i replaced
  // by the infinite vertex and two other vertices swapped, so positive as ghosts are (above).
  uint32_t add_ghost(uint32_t t, int i) {
    Simplex g = cells_[t].v;
    g[i] = kInfinite;
    std::swap(g[(i + 1) % (D + 1)], g[(i + 2) % (D + 1)]);
    const uint32_t ghost = new_simplex(g);
    link(t, i, ghost, i);
    return ghost;
  }

  // The ghosts' facets through the infinite vertex, linked in pairs: those with the same finite
  // vertices (a ridge of the hull) face each other. Sorted, not a map: on a surface whose vertices
  // are all on the hull (a sphere) a tetrahedralization taken back (adopt) has a ghost per surface
  // triangle, and a map of their ridges was half of adopting it.
  void link_ghosts(const std::vector<uint32_t>& ghosts) {
    struct Open {
      std::array<uint32_t, D - 1> ridge;
      uint32_t ghost;
      int facet;
    };
    std::vector<Open> open;
    open.reserve(ghosts.size() * D);
    for (const uint32_t g : ghosts) {
      const int at = infinite_index(g);
      for (int j = 0; j <= D; ++j) {
        if (j == at) continue;
        Open o{{}, g, j};
        for (int k = 0, r = 0; k <= D; ++k)
          if (k != at && k != j) o.ridge[r++] = cells_[g].v[k];
        std::sort(o.ridge.begin(), o.ridge.end());
        open.push_back(o);
      }
    }
    std::sort(open.begin(), open.end(), [](const Open& x, const Open& y) { return x.ridge < y.ridge; });
    for (std::size_t k = 0; k + 1 < open.size(); ++k)
      if (open[k].ridge == open[k + 1].ridge) {
        link(open[k].ghost, open[k].facet, open[k + 1].ghost, open[k + 1].facet);
        ++k;
      }
  }

  // ------------------------------------------------------------------------------------------
  // Storage: flat arrays, freed slots reused.

  uint32_t new_simplex(const Simplex& v) {
    for (const uint32_t id : v)
      if (id != kInfinite) vertex_simplex_[id] = static_cast<uint32_t>(free_.empty() ? cells_.size() : free_.back());
    uint32_t t;
    if (!free_.empty()) {
      t = free_.back();
      free_.pop_back();
      cells_[t].v = v;
      dead_[t] = 0;
    } else {
      if (cells_.size() >= kMaxSimplices) throw Error("delaunay_simplices: too many simplices");
      t = static_cast<uint32_t>(cells_.size());
      Cell cell;
      cell.v = v;
      cell.n.fill(kInfinite);
      cells_.push_back(cell);
      marks_.push_back(0);
      dead_.push_back(0);
    }
    return t;
  }

  void link(uint32_t t, int i, uint32_t u, int j) {
    cells_[t].n[i] = u << kLinkBits | static_cast<uint32_t>(j);
    cells_[u].n[j] = t << kLinkBits | static_cast<uint32_t>(i);
  }

  uint32_t neighbor(uint32_t t, int i) const { return cells_[t].n[i] >> kLinkBits; }

  // ------------------------------------------------------------------------------------------
  // Point location: a remembering stochastic visibility walk (Devillers, Pion, Teillaud) from a
  // finite simplex at `near` when that is an inserted point, else from the last simplex made. It
  // ends in a finite simplex whose closure holds p, or in a ghost whose hull facet p lies strictly
  // outside of. Either one conflicts with p. (Steiner points come a batch at a time, spread over the
  // surface, each beside an end of the piece it splits: walked to from the last simplex made, each
  // took 38 steps on oblique_cylinders_fine.stl, from that end 14.5, and its refinement 0.81x the
  // time, with the same triangulation.)

  uint32_t locate(const Vertex& p, uint32_t near) {
    uint32_t t = last_;
    if (near < vertex_simplex_.size() && vertex_simplex_[near] != kInfinite) {
      t = vertex_simplex_[near];
      if (const int k = infinite_index(t); k <= D) t = neighbor(t, k);  // a ghost's finite neighbour, across its hull facet
    }
    int came_from = D + 1;  // p is known to be strictly on t's side of this facet
    const std::size_t max_steps = cells_.size() + 16;  // the walk is acyclic in a Delaunay triangulation
    for (std::size_t step = 0; step < max_steps; ++step) {
      if (infinite_index(t) <= D) return t;
      const int r = static_cast<int>(next_random() % (D + 1));
      int exit = D + 1;
      for (int k = 0; k <= D && exit == D + 1; ++k) {
        const int i = (r + k) % (D + 1);
        if (i != came_from && predicates::orient<D>(coords_of(with(t, i, p))) == Sign::Negative) exit = i;
      }
      if (exit == D + 1) return t;
      const uint32_t next = cells_[t].n[exit];
      t = next >> kLinkBits;
      came_from = static_cast<int>(next & kLinkMask);
    }
    throw Error("delaunay_simplices: point location did not end (internal error)");
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
    Vertices<D + 2> v;
    for (int k = 0; k <= D; ++k) v[k] = vertex(cells_[t].v[k]);
    v[D + 1] = p;
    // Stored simplices are positive, so "inside" is a positive insphere.
    return predicates::insphere_perturbed<D>(v) == Sign::Positive;
  }

  bool in_conflict(uint32_t t, const Vertex& p) const {
    const int k = infinite_index(t);
    if (k == D + 1) return finite_conflict(t, p);
    const Sign side = predicates::orient<D>(coords_of(with(t, k, p)));
    if (side != Sign::Zero) return side == Sign::Positive;
    // p in the hyperplane of the hull facet: inside its perturbed circumsphere there exactly when
    // inside the perturbed circumsphere of the finite simplex behind it (see delaunay.h).
    return finite_conflict(neighbor(t, k), p);
  }

  // ------------------------------------------------------------------------------------------
  // Bowyer–Watson: the conflict region, grown from the located simplex through conflicting
  // neighbours, is replaced by the star of p over its boundary.

  struct BoundaryFacet {
    Simplex vertices;  // the new simplex: the conflict simplex with vertex i replaced by p
    int i;             // p's local index in it
    uint32_t outside;  // the link to the simplex across the facet, not in conflict
  };

  void insert(uint32_t id, uint32_t near = kInfinite) {
    const Vertex p = vertex(id);
    const uint32_t start = locate(p, near);
    if (infinite_index(start) == D + 1)
      for (const uint32_t v : cells_[start].v)
        if (same_point(v, id))
          throw Error("delaunay_simplices: points " + std::to_string(v) + " and " + std::to_string(id) + " coincide");
    if (!in_conflict(start, p)) throw Error("delaunay_simplices: located simplex not in conflict (internal error)");

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

  // Breadth-first search from `start`; fills conflicts_ and boundary_. Each simplex is tested at
  // most once per insertion (marks_ holds this insertion's stamp: in or out).
  void grow_cavity(uint32_t start, const Vertex& p) {
    stamp_ += 2;
    const uint32_t in = stamp_, out = stamp_ + 1;
    conflicts_.clear();
    boundary_.clear();
    marks_[start] = in;
    conflicts_.push_back(start);
    prefetch_neighbors(start);
    for (std::size_t head = 0; head < conflicts_.size(); ++head) {
      const uint32_t c = conflicts_[head];
      for (int i = 0; i <= D; ++i) {
        const uint32_t u = neighbor(c, i);
        if (marks_[u] == in) continue;
        if (marks_[u] != out) {
          if (in_conflict(u, p)) {
            marks_[u] = in;
            conflicts_.push_back(u);
            prefetch_neighbors(u);
            continue;
          }
          marks_[u] = out;
        }
        Simplex v = cells_[c].v;
        v[i] = p.id;
        boundary_.push_back({v, i, cells_[c].n[i]});
      }
    }
  }

  // The cells and marks of t's neighbours, asked for as t joins the cavity, so that they are in the
  // cache when the search tests them: the cavity's simplices lie scattered in memory, and waiting
  // for each load in turn was most of an insertion's own time (perforated_tube_std's refinement:
  // its 80k insertions 0.88 s before, 0.66 s after; medians of five runs).
  void prefetch_neighbors(uint32_t t) const {
    for (int i = 0; i <= D; ++i) {
      const uint32_t u = neighbor(t, i);
      __builtin_prefetch(&cells_[u]);
      __builtin_prefetch(&marks_[u]);
    }
  }

  // The star of p: one simplex per boundary facet, linked to the outside across that facet and to
  // each other across the facets through p, which pair up by their ridge on the cavity boundary (the
  // boundary is a closed (D-1)-manifold, so each of its ridges belongs to exactly two of its facets).
  void fill_cavity() {
    start_ridge_pairing(D * boundary_.size());
    bool have_finite = false;
    for (const BoundaryFacet& b : boundary_) {
      const uint32_t t = new_simplex(b.vertices);
      link(t, b.i, b.outside >> kLinkBits, static_cast<int>(b.outside & kLinkMask));
      for (int m = 0; m <= D; ++m) {
        if (m == b.i) continue;
        Ridge ridge;
        for (int k = 0, r = 0; k <= D; ++k)
          if (k != m && k != b.i) ridge[r++] = b.vertices[k];
        std::sort(ridge.begin(), ridge.end());
        pair_ridge(ridge, t, m);
      }
      if (!have_finite && infinite_index(t) == D + 1) {
        last_ = t;
        have_finite = true;
      }
    }
    if (2 * ridges_paired_ != D * boundary_.size() || !have_finite)
      throw Error("delaunay_simplices: cavity boundary is not a closed surface (internal error)");
  }

  // Ridge pairing: a small open-addressing table keyed by the ridge, cleared by bumping a generation
  // instead of refilling (cavities are small, insertions many).
  struct RidgeSlot {
    Ridge key;
    uint32_t generation;
    uint32_t link;  // the link of the first facet seen, kInfinite once paired
  };

  // Each insertion hashes into the first slots only, as many as it needs: after one large cavity
  // (cospherical points: thousands of tetrahedra) the table stays large, and small cavities hashed
  // over all of it missed the cache at nearly every ridge (29% of the insertion's own time on
  // hollow_sphere_fine's Steiner points).
  void start_ridge_pairing(std::size_t entries) {
    std::size_t capacity = 64;
    while (capacity < 2 * entries) capacity *= 2;
    if (ridge_table_.size() < capacity) {
      ridge_table_.assign(capacity, RidgeSlot{{}, 0, 0});
      ridge_generation_ = 0;
    }
    ridge_mask_ = capacity - 1;
    ++ridge_generation_;
    ridges_paired_ = 0;
  }

  void pair_ridge(const Ridge& key, uint32_t t, int m) {
    uint64_t hash = 0;
    for (const uint32_t id : key) hash = (hash ^ id) * 0x9E3779B97F4A7C15ull;
    const std::size_t mask = ridge_mask_;
    for (std::size_t h = hash >> 32 & mask;; h = (h + 1) & mask) {
      RidgeSlot& slot = ridge_table_[h];
      if (slot.generation != ridge_generation_) {
        slot = RidgeSlot{key, ridge_generation_, t << kLinkBits | static_cast<uint32_t>(m)};
        return;
      }
      if (slot.key != key) continue;
      if (slot.link == kInfinite) throw Error("delaunay_simplices: cavity ridge in three facets (internal error)");
      link(t, m, slot.link >> kLinkBits, static_cast<int>(slot.link & kLinkMask));
      slot.link = kInfinite;
      ++ridges_paired_;
      return;
    }
  }

  std::vector<Simplex> finite_simplices() const {
    std::vector<Simplex> result;
    for (uint32_t t = 0; t < cells_.size(); ++t)
      if (!dead_[t] && infinite_index(t) == D + 1) result.push_back(cells_[t].v);
    return result;
  }

  const std::vector<double>* points_;
  // A simplex: its vertices and, per facet i (opposite v[i]), the link to the neighbour across it.
  // One array, so a walk step touches one cache line (in 3D).
  struct Cell {
    Simplex v;
    Simplex n;
  };
  std::vector<Cell> cells_;
  std::vector<uint32_t> marks_;
  std::vector<uint8_t> dead_;
  std::vector<uint32_t> free_;
  std::vector<uint32_t> vertex_simplex_;  // per inserted point: a live simplex holding it
  std::vector<uint32_t> star_;            // any_star_vertex's search
  std::vector<uint32_t> touched_round_;   // per point: the last round (insert_new_points call) touching it
  std::vector<uint32_t> changed_;         // the points touched_round_ marks with round_
  uint32_t round_ = 0;
  uint32_t first_new_ = 0;  // the first point of the last build/insert_new_points
  std::vector<uint32_t> conflicts_;
  std::vector<BoundaryFacet> boundary_;
  std::vector<RidgeSlot> ridge_table_;
  std::size_t ridge_mask_ = 0;  // this insertion's slots: 0..ridge_mask_
  uint32_t ridge_generation_ = 0;
  std::size_t ridges_paired_ = 0;
  uint32_t stamp_ = 0;
  uint32_t last_ = 0;
  uint32_t rng_ = 2463534242u;
};

// From point `first` on (the points appended since the last check).
template <int D>
void check_points(const std::vector<double>& points, std::size_t first = 0) {
  if (points.size() % D != 0)
    throw Error("delaunay_simplices: the coordinate count is not a multiple of " + std::to_string(D));
  if (points.size() / D >= kInfinite) throw Error("delaunay_simplices: too many points");
  for (std::size_t i = D * first; i < points.size(); ++i)
    if (!std::isfinite(points[i]))
      throw Error("delaunay_simplices: point " + std::to_string(i / D) + " has a non-finite coordinate");
}

}  // namespace

struct DelaunayEdges::Impl {
  explicit Impl(const std::vector<double>& p) : triangulation(p) {}
  Delaunay<3> triangulation;
};

DelaunayEdges::DelaunayEdges(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted)
    : impl_(std::make_unique<Impl>(points)) {
  check_points<3>(points);
  impl_->triangulation.build(brio_order<3>(points), inserted);
}

std::unique_ptr<DelaunayEdges> DelaunayEdges::from_mesh(const std::vector<double>& points, const DelaunayMesh& mesh) {
  std::unique_ptr<DelaunayEdges> edges(new DelaunayEdges());
  edges->impl_ = std::make_unique<Impl>(points);
  if (!edges->impl_->triangulation.adopt(mesh)) return nullptr;
  return edges;
}

DelaunayEdges::~DelaunayEdges() = default;

void DelaunayEdges::rebind(const std::vector<double>& points) { impl_->triangulation.rebind(points); }

void DelaunayEdges::insert_new_points(const std::function<uint32_t(uint32_t)>& near) {
  check_points<3>(impl_->triangulation.points(), impl_->triangulation.num_inserted());
  impl_->triangulation.insert_new_points(near);
}

bool DelaunayEdges::has_edge(uint32_t a, uint32_t b) { return impl_->triangulation.has_edge(a, b); }
void DelaunayEdges::link_vertices(uint32_t a, std::vector<uint32_t>& out) { impl_->triangulation.link_vertices(a, out); }

DelaunayMesh DelaunayEdges::mesh() const { return impl_->triangulation.mesh(); }

bool DelaunayEdges::may_have_changed(uint32_t a, uint32_t b) const {
  const Delaunay<3>& t = impl_->triangulation;
  return (t.touched(a) && t.touched(b)) || t.inserted_last(a) || t.inserted_last(b);
}

const std::vector<uint32_t>& DelaunayEdges::changed_points() const { return impl_->triangulation.changed(); }

template <int D>
std::vector<std::array<uint32_t, D + 1>> delaunay_simplices(const std::vector<double>& points) {
  check_points<D>(points);
  return Delaunay<D>(points).run(brio_order<D>(points));
}

template <int D>
DelaunayMesh delaunay_mesh(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted) {
  check_points<D>(points);
  Delaunay<D> triangulation(points);
  triangulation.build(brio_order<D>(points), inserted);
  return triangulation.mesh();
}

template <int D>
std::vector<std::array<uint32_t, D + 1>> delaunay_simplices_in_order(const std::vector<double>& points,
                                                                     const std::vector<uint32_t>& order) {
  check_points<D>(points);
  const std::size_t n = points.size() / D;
  std::vector<uint8_t> seen(n, 0);
  for (const uint32_t id : order)
    if (id >= n || seen[id]++) throw Error("delaunay_simplices_in_order: the order is not a permutation");
  if (order.size() != n) throw Error("delaunay_simplices_in_order: the order is not a permutation");
  return Delaunay<D>(points).run(order);
}

#define SWEEPCDT_DELAUNAY(D)                                                                                        \
  template std::vector<std::array<uint32_t, D + 1>> delaunay_simplices<D>(const std::vector<double>&);              \
  template DelaunayMesh delaunay_mesh<D>(const std::vector<double>&, const std::function<void(std::size_t)>&);      \
  template std::vector<std::array<uint32_t, D + 1>> delaunay_simplices_in_order<D>(const std::vector<double>&,      \
                                                                                    const std::vector<uint32_t>&);
SWEEPCDT_DELAUNAY(2)
SWEEPCDT_DELAUNAY(3)
SWEEPCDT_DELAUNAY(4)
SWEEPCDT_DELAUNAY(5)
#undef SWEEPCDT_DELAUNAY

}  // namespace sweepcdt::detail
