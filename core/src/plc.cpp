// Plc<D>::facet_bounded, find_problems() and check(): exact validation of a PLC (paper §1).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include "box_tree.h"
#include "delaunay/kept_tetrahedralization.h"
#include "parallel.h"
#include "refined_check.h"
#include "simplex_intersection.h"
#include "tuple_map.h"
#include "sweepcdt/plc.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt {
namespace {

class ProblemList {
 public:
  explicit ProblemList(std::size_t limit) : limit_(limit) {}
  void add(PlcProblemKind kind, std::vector<uint64_t> elements, const std::string& message) {
    ++total_;
    if (per_kind_[kind]++ < limit_) problems_.push_back({kind, std::move(elements), message});
  }
  uint64_t total() const { return total_; }
  std::size_t limit() const { return limit_; }
  std::vector<PlcProblem> take() { return std::move(problems_); }

  // Appends the problems `later` found after these (a later part of the same scan), as if one list
  // had counted them all: still the first `limit` of each kind in scan order.
  void append(ProblemList&& later) {
    detail::append_part(problems_, per_kind_, std::move(later.problems_), later.per_kind_, limit_,
                        [](const PlcProblem& p) { return p.kind; });
    total_ += later.total_;
  }

 private:
  std::size_t limit_;
  uint64_t total_ = 0;
  std::map<PlcProblemKind, std::size_t> per_kind_;
  std::vector<PlcProblem> problems_;
};

std::string n(uint64_t i) { return std::to_string(i); }

template <int D>
std::array<const double*, D> simplex_coords(const Plc<D>& plc, std::size_t j) {
  std::array<const double*, D> c;
  for (int i = 0; i < D; ++i) c[i] = plc.point(plc.simplex(j)[i]);
  return c;
}

template <int D>
std::array<uint32_t, D> simplex_ids(const Plc<D>& plc, std::size_t j) {
  std::array<uint32_t, D> ids;
  std::copy_n(plc.simplex(j), D, ids.begin());
  return ids;
}

// The simplex's vertices are affinely dependent iff every projection along an axis is degenerate.
template <int D>
bool degenerate(const std::array<const double*, D>& f) {
  for (int drop = 0; drop < D; ++drop)
    if (predicates::orient_projected<D>(f, drop) != predicates::Sign::Zero) return false;
  return true;
}

// Sizes, finiteness, index ranges and repeated vertices. False if geometry cannot be examined.
template <int D>
bool check_structure(const Plc<D>& plc, ProblemList& problems) {
  bool ok = true;
  if (plc.points.size() % D != 0) {
    problems.add(PlcProblemKind::BadShape, {}, "points: " + n(plc.points.size()) + " coordinates is not a multiple of D = " + n(D));
    ok = false;
  }
  if (plc.simplices.size() % D != 0) {
    problems.add(PlcProblemKind::BadShape, {}, "simplices: " + n(plc.simplices.size()) + " ids is not a multiple of D = " + n(D));
    ok = false;
  }
  if (!plc.exterior.empty() && plc.exterior.size() != plc.num_simplices()) {
    problems.add(PlcProblemKind::BadShape, {}, "exterior: " + n(plc.exterior.size()) + " notations for " + n(plc.num_simplices()) + " simplices");
    ok = false;
  }
  if (!plc.tags.empty() && plc.tags.size() != plc.num_simplices()) {
    problems.add(PlcProblemKind::BadShape, {}, "tags: " + n(plc.tags.size()) + " tags for " + n(plc.num_simplices()) + " simplices");
    ok = false;
  }
  if (!ok) return false;
  for (std::size_t i = 0; i < plc.num_points(); ++i) {
    const double* p = plc.point(static_cast<uint32_t>(i));
    if (!std::all_of(p, p + D, [](double x) { return std::isfinite(x); })) {
      problems.add(PlcProblemKind::NonFinitePoint, {i}, "point " + n(i) + " has a NaN or infinite coordinate");
      ok = false;
    }
  }
  for (std::size_t s = 0; s < plc.region_seeds.size(); ++s) {
    const auto& p = plc.region_seeds[s].point;
    if (!std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); }))
      problems.add(PlcProblemKind::BadRegionSeed, {s}, "region seed " + n(s) + " has a NaN or infinite coordinate");
  }
  for (std::size_t j = 0; j < plc.num_simplices(); ++j) {
    auto ids = simplex_ids(plc, j);
    for (uint32_t id : ids)
      if (id >= plc.num_points()) {
        problems.add(PlcProblemKind::IndexOutOfRange, {j}, "simplex " + n(j) + " names point " + n(id) + ", but there are only " + n(plc.num_points()));
        ok = false;
        break;
      }
    std::sort(ids.begin(), ids.end());
    if (const auto repeated = std::adjacent_find(ids.begin(), ids.end()); repeated != ids.end()) {
      problems.add(PlcProblemKind::RepeatedVertex, {j}, "simplex " + n(j) + " names point " + n(*repeated) + " twice");
      ok = false;
    }
  }
  return ok;
}

template <int D>
void check_duplicate_points(const Plc<D>& plc, ProblemList& problems) {
  std::vector<uint32_t> order(plc.num_points());
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](uint32_t a, uint32_t b) {
    return std::lexicographical_compare(plc.point(a), plc.point(a) + D, plc.point(b), plc.point(b) + D);
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t i = 1; i < order.size(); ++i) {
    const uint32_t a = order[i - 1], b = order[i];
    if (std::equal(plc.point(a), plc.point(a) + D, plc.point(b)))
      problems.add(PlcProblemKind::DuplicatePoints, {std::min(a, b), std::max(a, b)},
                   "points " + n(std::min(a, b)) + " and " + n(std::max(a, b)) + " have equal coordinates");
  }
}

// Marks degenerate and duplicate simplices (excluded from the intersection tests), reported in
// simplex order. The shapes are tested in parts on `threads` threads (parallel.h); the earlier
// simplex with the same vertices is looked up in a flat hash map (a std::map of every simplex was
// two thirds of each lazy attempt's check of its refined PLC, 16 ms of 18 on a 75k-triangle scan).
template <int D>
std::vector<char> check_simplex_shapes(const Plc<D>& plc, ProblemList& problems, unsigned threads) {
  const std::size_t m = plc.num_simplices();
  std::vector<char> flat(m, 0);
  detail::for_each_part(m, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) flat[j] = degenerate<D>(simplex_coords(plc, j));
  });
  std::vector<char> usable(m, 1);
  detail::TupleMap<D> seen(m);
  for (std::size_t j = 0; j < m; ++j) {
    if (flat[j]) {
      problems.add(PlcProblemKind::DegenerateSimplex, {j}, "simplex " + n(j) + " is degenerate (its vertices are affinely dependent)");
      usable[j] = 0;
      continue;
    }
    auto ids = simplex_ids(plc, j);
    std::sort(ids.begin(), ids.end());
    const auto [first, inserted] = seen.emplace(ids, static_cast<uint32_t>(j));
    if (!inserted) {
      problems.add(PlcProblemKind::DuplicateSimplex, {first, j}, "simplices " + n(first) + " and " + n(j) + " have the same vertices");
      usable[j] = 0;
    }
  }
  return usable;
}

// The pairs of usable simplices with a suspect one (check_refined()) whose boxes overlap, tested
// exactly, each once, in parts on `threads` threads. Suspects are few (the facets that rounding may
// have moved: 1326 of a refined PLC's 167152 triangles on perforated_tube_std.stl), so the box tree
// holds only them and every simplex looks itself up there: a tree of every simplex, built for each
// lazy attempt, had been most of the check's time.
template <int D>
void check_suspect_pairs(const Plc<D>& plc, const std::vector<char>& usable, const std::vector<char>& suspect,
                         const std::vector<detail::Box<D>>& boxes, ProblemList& problems, unsigned threads) {
  std::vector<uint32_t> suspects;
  for (uint32_t j = 0; j < boxes.size(); ++j)
    if (suspect[j] && usable[j]) suspects.push_back(j);
  if (suspects.empty()) return;
  std::vector<detail::Box<D>> suspect_boxes;
  for (const uint32_t j : suspects) suspect_boxes.push_back(boxes[j]);
  const detail::BoxTree<D> tree(std::move(suspect_boxes));
  std::vector<ProblemList> found(detail::parts_for(boxes.size(), threads), ProblemList(problems.limit()));
  detail::for_each_part(boxes.size(), threads, [&](std::size_t part, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      if (!usable[k]) continue;
      tree.for_each_overlap(boxes[k], [&](uint32_t i) {
        const uint32_t j = suspects[i];
        // Two suspects: from the one with the larger index only.
        if (j == k || (suspect[k] && k < j)) return;
        if (detail::improper_intersection<D>(simplex_coords(plc, j), simplex_ids(plc, j), simplex_coords(plc, k), simplex_ids(plc, k)))
          found[part].add(PlcProblemKind::Intersection, {j, static_cast<uint32_t>(k)},
                          "simplices " + n(j) + " and " + n(k) + " intersect other than in a shared face");
      });
    }
  });
  for (ProblemList& part : found) problems.append(std::move(part));
}

// Pairs of simplices whose boxes overlap, tested exactly; in parts on `threads` threads (parallel.h).
// `suspect`, when given: only the pairs with a suspect simplex (check_refined()).
template <int D>
void check_intersections(const Plc<D>& plc, const std::vector<char>& usable, ProblemList& problems, unsigned threads,
                         const std::vector<char>* suspect = nullptr) {
  std::vector<char> used(plc.num_points(), 0);
  for (uint32_t id : plc.simplices) used[id] = 1;
  const bool every_point_used = std::all_of(used.begin(), used.end(), [](char c) { return c != 0; });
  // Nothing to test (a refined PLC whose facets are all exactly the input's, every point on them):
  // no spatial index either.
  if (suspect && every_point_used && std::none_of(suspect->begin(), suspect->end(), [](char c) { return c != 0; })) return;
  std::vector<detail::Box<D>> boxes(plc.num_simplices());
  for (std::size_t j = 0; j < boxes.size(); ++j) boxes[j] = detail::Box<D>::of_points(simplex_coords(plc, j).data(), D);
  if (suspect) {
    check_suspect_pairs(plc, usable, *suspect, boxes, problems, threads);
    if (every_point_used) return;
  }
  const detail::BoxTree<D> tree(boxes);

  if (!suspect) {
    std::vector<ProblemList> found(detail::parts_for(boxes.size(), threads), ProblemList(problems.limit()));
    detail::for_each_part(boxes.size(), threads, [&](std::size_t part, std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j) {
        if (!usable[j]) continue;
        const auto a = simplex_coords(plc, j);
        const auto ida = simplex_ids(plc, j);
        tree.for_each_overlap(boxes[j], [&](uint32_t k) {
          if (k <= j || !usable[k]) return;  // each pair once, from its first simplex
          if (detail::improper_intersection<D>(a, ida, simplex_coords(plc, k), simplex_ids(plc, k)))
            found[part].add(PlcProblemKind::Intersection, {j, k}, "simplices " + n(j) + " and " + n(k) + " intersect other than in a shared face");
        });
      }
    });
    for (ProblemList& part : found) problems.append(std::move(part));
  }

  // Points that are vertices of no simplex must not lie on one either.
  for (uint32_t i = 0; i < plc.num_points(); ++i) {
    if (used[i]) continue;
    const double* p = plc.point(i);
    const detail::Box<D> box = detail::Box<D>::of_points(&p, 1);
    tree.for_each_overlap(box, [&](uint32_t k) {
      if (usable[k] && detail::point_in_simplex<D>(p, simplex_coords(plc, k)))
        problems.add(PlcProblemKind::PointOnSimplex, {i, k}, "point " + n(i) + " lies on simplex " + n(k) + " but is not one of its vertices");
    });
  }
}

}  // namespace

template <int D>
bool Plc<D>::facet_bounded() const {
  return std::any_of(exterior.begin(), exterior.end(), [](ExteriorSide e) { return e != ExteriorSide::None; });
}

template <int D>
bool PlcCheck<D>::covers(const Plc<D>& plc) const {
  // Bitwise: the checks' answers depend on the exact coordinates (a NaN or a -0.0 compares as itself).
  return plc.points.size() == points_.size() && plc.simplices == simplices_ &&
         (points_.empty() || std::memcmp(plc.points.data(), points_.data(), points_.size() * sizeof(double)) == 0);
}

namespace {

// find_problems(), and find_problems_before_cdt() with `kept` (its tetrahedralization under way).
template <int D>
std::vector<PlcProblem> find_problems_keeping(const Plc<D>& plc, std::size_t limit_per_kind, uint64_t* total,
                                              std::shared_ptr<const PlcCheck<D>>* record, unsigned threads,
                                              std::shared_ptr<detail::KeptTetrahedralization> kept) {
  ProblemList problems(limit_per_kind);
  if (check_structure(plc, problems) && !(plc.checked && plc.checked->covers(plc))) {
    check_duplicate_points(plc, problems);
    const auto usable = check_simplex_shapes(plc, problems, threads);
    check_intersections(plc, usable, problems, threads);
  }
  if (total) *total = problems.total();
  if (record) {
    record->reset();
    if (problems.total() == 0) *record = detail::PlcCheckAccess::make<D>(plc, std::move(kept));
  }
  return problems.take();
}

}  // namespace

template <int D>
std::vector<PlcProblem> find_problems(const Plc<D>& plc, std::size_t limit_per_kind, uint64_t* total,
                                      std::shared_ptr<const PlcCheck<D>>* record, unsigned threads) {
  return find_problems_keeping<D>(plc, limit_per_kind, total, record, threads, nullptr);
}

// The tetrahedralization takes a thread of its own and the checks the others (as in cdt(): they
// share no data), when there is a record to keep it in, a second thread, and a PLC not checked
// already. A PLC with problems gets no record, and its tetrahedralization is stopped.
std::vector<PlcProblem> find_problems_before_cdt(const Plc<3>& plc, std::size_t limit_per_kind, uint64_t* total,
                                                 std::shared_ptr<const PlcCheck<3>>* record, unsigned threads) {
  const unsigned available = detail::thread_count(threads);
  std::shared_ptr<detail::KeptTetrahedralization> kept;
  if (record && available > 1 && plc.num_points() >= 4 && !(plc.checked && plc.checked->covers(plc)))
    kept = std::make_shared<detail::KeptTetrahedralization>(plc.points);
  return find_problems_keeping<3>(plc, limit_per_kind, total, record, kept ? available - 1 : threads, std::move(kept));
}

template <int D>
void check(const Plc<D>& plc, unsigned threads) {
  uint64_t total = 0;
  auto problems = find_problems<D>(plc, 10, &total, nullptr, threads);
  if (total > 0) throw PlcError(std::move(problems), total);
}

namespace detail {

template <int D>
void check_refined(const Plc<D>& plc, const std::vector<char>& suspect, unsigned threads) {
  if (suspect.size() != plc.num_simplices()) throw std::invalid_argument("check_refined: one flag per simplex");
  ProblemList problems(10);
  if (check_structure(plc, problems)) {
    check_duplicate_points(plc, problems);
    const auto usable = check_simplex_shapes(plc, problems, threads);
    check_intersections(plc, usable, problems, threads, &suspect);
  }
  if (problems.total() > 0) {
    const uint64_t total = problems.total();
    throw PlcError(problems.take(), total);
  }
}
template void check_refined<3>(const Plc<3>&, const std::vector<char>&, unsigned);

}  // namespace detail

#define SWEEPCDT_INSTANTIATE(D)                                                                    \
  template struct Plc<D>;                                                                          \
  template class PlcCheck<D>;                                                                      \
  template std::vector<PlcProblem> find_problems<D>(const Plc<D>&, std::size_t, uint64_t*,        \
                                                    std::shared_ptr<const PlcCheck<D>>*, unsigned); \
  template void check<D>(const Plc<D>&, unsigned);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt
