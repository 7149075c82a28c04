// notate_from_holes() / triangles_of_pslg(): Triangle's eating of triangles from the hull and from
// hole points, on an exact CDT of the PSLG (see pslg_holes.h).
#include "pslg_holes.h"

#include "facet_keys.h"
#include "reader_util.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io::detail {
namespace {

using predicates::Sign;

// Work bound for locating hole points by scanning the triangles (holes are few in practice; a file
// with many thousands of holes and triangles is refused rather than left to run for minutes).
constexpr uint64_t kMaxHoleScan = uint64_t{1} << 28;

struct Eaten {
  Triangulation<2> tri;
  std::vector<uint8_t> eaten;  // per triangle
};

Eaten eat(const Plc<2>& pslg, const std::vector<std::array<double, 2>>& holes, const std::string& file, const std::string& what) {
  Plc<2> hull = pslg;  // the convex hull as domain: no notations, no seeds
  hull.exterior.clear();
  hull.region_seeds.clear();
  Eaten e;
  try {
    e.tri = cdt(hull);
  } catch (const Error& error) {
    fail(InputErrorKind::BadPolygon, file, Location::none(), what + " is not a valid planar straight-line graph: " + error.what());
  }
  const std::size_t s = e.tri.num_simplices();
  if (s == 0) fail(InputErrorKind::BadPolygon, file, Location::none(), what + " has no triangle (fewer than three points, or all collinear)");
  const SimplexKeys<2> segments(pslg);
  auto facet = [&](std::size_t t, int i) {
    const uint32_t* v = e.tri.simplex(t);
    return std::array<uint32_t, 2>{v[(i + 1) % 3], v[(i + 2) % 3]};
  };
  e.eaten.assign(s, 0);
  std::vector<uint32_t> stack;
  for (std::size_t t = 0; t < s; ++t)
    for (int i = 0; i < 3; ++i)
      if (e.tri.neighbors[3 * t + i] == kNone && segments.index_of(facet(t, i).data()) == kNone && !e.eaten[t]) {
        e.eaten[t] = 1;
        stack.push_back(static_cast<uint32_t>(t));
      }
  if (holes.size() * uint64_t{s} > kMaxHoleScan)
    fail(InputErrorKind::Unsupported, file, Location::none(), std::to_string(holes.size()) + " hole points in " + std::to_string(s) + " triangles is too many to locate");
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const double* q = holes[h].data();
    for (std::size_t t = 0; t < s; ++t) {
      const uint32_t* v = e.tri.simplex(t);
      Sign side[3];
      bool inside = true;
      for (int i = 0; i < 3 && inside; ++i) {
        side[i] = predicates::orient<2>({e.tri.point(v[(i + 1) % 3]), e.tri.point(v[(i + 2) % 3]), q});
        inside = side[i] != Sign::Negative;
      }
      if (!inside) continue;
      for (int i = 0; i < 3; ++i)
        if (side[i] == Sign::Zero && segments.index_of(facet(t, i).data()) != kNone)
          fail(InputErrorKind::BadPolygon, file, Location::of("hole", h), "hole point lies on a segment of " + what + ", so it names no side");
      if (!e.eaten[t]) {
        e.eaten[t] = 1;
        stack.push_back(static_cast<uint32_t>(t));
      }
    }
  }
  while (!stack.empty()) {
    const uint32_t t = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const uint32_t nb = e.tri.neighbors[3 * t + i];
      if (nb == kNone || e.eaten[nb / 3] || segments.index_of(facet(t, i).data()) != kNone) continue;
      e.eaten[nb / 3] = 1;
      stack.push_back(nb / 3);
    }
  }
  if (std::find(e.eaten.begin(), e.eaten.end(), 0) == e.eaten.end())
    fail(InputErrorKind::BadPolygon, file, Location::none(), "the holes and the outside eat all of " + what + ": its domain is empty");
  return e;
}

}  // namespace

void notate_from_holes(Plc<2>& plc, const std::vector<std::array<double, 2>>& holes, const std::string& file) {
  // No segments and no holes: a plain point set, whose triangulation is its convex hull (eating from
  // the hull would leave nothing; Triangle users expect the Delaunay triangulation).
  if (plc.num_simplices() == 0 && holes.empty()) return;
  const Eaten e = eat(plc, holes, file, "the PSLG");
  // Per segment: is its positive (left of f0 -> f1) / negative side eaten? A side with no triangle is
  // outside the convex hull: eaten.
  const std::size_t m = plc.num_simplices();
  std::vector<uint8_t> positive_eaten(m, 1), negative_eaten(m, 1);
  const SimplexKeys<2> segments(plc);
  for (std::size_t t = 0; t < e.tri.num_simplices(); ++t) {
    const uint32_t* v = e.tri.simplex(t);
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = v[(i + 1) % 3], b = v[(i + 2) % 3];  // the triangle (counterclockwise) is left of a -> b
      const uint32_t ab[2] = {a, b};
      const uint32_t j = segments.index_of(ab);
      if (j == kNone) continue;
      const bool left_of_segment = plc.simplex(j)[0] == a;
      (left_of_segment ? positive_eaten : negative_eaten)[j] = e.eaten[t];
    }
  }
  Plc<2> out;
  out.points = std::move(plc.points);
  out.region_seeds = std::move(plc.region_seeds);
  const bool tagged = plc.tags.size() == m;
  for (std::size_t j = 0; j < m; ++j) {
    if (positive_eaten[j] && negative_eaten[j]) continue;
    out.simplices.insert(out.simplices.end(), plc.simplex(j), plc.simplex(j) + 2);
    out.exterior.push_back(positive_eaten[j] ? ExteriorSide::Positive : negative_eaten[j] ? ExteriorSide::Negative : ExteriorSide::None);
    out.tags.push_back(tagged ? plc.tags[j] : static_cast<uint32_t>(j));
  }
  // Nothing eaten at all: the domain is the convex hull, which is what no notations mean.
  if (std::find(e.eaten.begin(), e.eaten.end(), 1) == e.eaten.end()) out.exterior.clear();
  plc = std::move(out);
}

std::vector<uint32_t> triangles_of_pslg(const Plc<2>& pslg, const std::vector<std::array<double, 2>>& holes, const std::string& file,
                                        const std::string& what) {
  const Eaten e = eat(pslg, holes, file, what);
  std::vector<uint32_t> out;
  for (std::size_t t = 0; t < e.tri.num_simplices(); ++t)
    if (!e.eaten[t]) out.insert(out.end(), e.tri.simplex(t), e.tri.simplex(t) + 3);
  return out;
}

}  // namespace sweepcdt::io::detail
