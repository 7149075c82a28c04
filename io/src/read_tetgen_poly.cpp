// TetGen .poly / .smesh (3D): points (or the .node beside the file), facets, volume holes, regions.
//
// Facets: a .poly facet is polygons (1 or 2 corners: points and segments inside the facet) and facet
// holes; a .smesh facet is one polygon. Each facet must be planar (decided exactly with orient<3>).
// A facet of one polygon goes through io's polygon triangulation (polygon.cpp); any other is
// triangulated in a projection on a coordinate plane (exact: a coordinate is dropped) by the same
// exact CDT and eating as Triangle's .poly (pslg_holes.h): its polygons' edges are segments, facet
// holes eat. Every triangle is tagged with its facet's boundary marker when the file has
// markers, else with the facet index.
//
// Domain: TetGen eats tetrahedra from the convex hull inward and from volume hole points, never
// across a facet. With facets forming closed, manifold shells (io's surface checks) that is decided
// per cell of the shells' nesting: the cell inside shell S and outside its children is eaten iff a
// hole point lies in it (exact ray parity, nesting.h); the outside is always eaten. Each triangle is
// notated by which of its sides is eaten; a triangle with both sides eaten (inside a hole) is
// dropped. Facets that form no closed shell at all leave the convex hull as the domain (no
// notations; holes are then refused). Anything in between (open or non-manifold facet sets with a
// closed part, e.g. an interior partition wall) is refused with the surface problem found.
#include <algorithm>
#include <numeric>

#include "nesting.h"
#include "poly_files.h"
#include "pslg_holes.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io::detail {
namespace {

using predicates::Sign;

struct Facet {
  std::vector<std::vector<uint32_t>> polygons;  // 0-based point ids
  std::vector<std::array<double, 3>> holes;
  uint32_t tag = 0;
  uint64_t line = 0;
};

bool collinear(const double* a, const double* b, const double* c) {
  for (int drop = 0; drop < 3; ++drop)
    if (predicates::orient_projected<3>({a, b, c}, drop) != Sign::Zero) return false;
  return true;
}

// Appends the facet's triangles (3D ids) to `soup.triangles` (soup.points: the file's points).
void triangulate_facet(Soup& soup, const Facet& f) {
  const std::vector<double>& points = soup.points;
  const std::string& file = soup.file;
  auto p = [&](uint32_t id) { return points.data() + 3 * std::size_t{id}; };
  auto bad = [&](const std::string& why) { fail(InputErrorKind::BadPolygon, file, Location::line(f.line), "facet " + why); };
  std::vector<uint32_t> ids;
  bool has_polygon = false;
  for (const auto& poly : f.polygons) {
    ids.insert(ids.end(), poly.begin(), poly.end());
    has_polygon |= poly.size() >= 3;
  }
  if (!has_polygon) bad("has no polygon of 3 or more corners (sweepcdt constrains triangles only)");
  if (f.polygons.size() == 1 && f.holes.empty()) {
    // One polygon: io's polygon triangulation (polygon.cpp: exact planarity, convex fan, ear
    // clipping up to 256 vertices), much cheaper than a CDT per facet. Larger non-convex polygons
    // go through the CDT below.
    try {
      add_polygon(soup, f.polygons[0], Location::line(f.line));
      return;
    } catch (const InputError& e) {
      if (e.kind() != InputErrorKind::Unsupported) throw;
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  // The plane through three non-collinear corners; every corner on it.
  const uint32_t a = ids[0];
  std::size_t ib = 1;
  while (ib < ids.size() && std::equal(p(a), p(a) + 3, p(ids[ib]))) ++ib;
  std::size_t ic = ib + 1;
  while (ic < ids.size() && collinear(p(a), p(ids[ib]), p(ids[ic]))) ++ic;
  if (ic >= ids.size()) bad("is degenerate: all its corners are collinear");
  const uint32_t b = ids[ib], c = ids[ic];
  for (uint32_t v : ids)
    if (predicates::orient<3>({p(a), p(b), p(c), p(v)}) != Sign::Zero)
      bad("is not planar: point " + std::to_string(v) + " is off the plane of points " + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c));
  int drop = 0;
  while (predicates::orient_projected<3>({p(a), p(b), p(c)}, drop) == Sign::Zero) ++drop;
  auto project = [&](const double* q) {
    std::array<double, 2> r{};
    for (int k = 0, j = 0; k < 3; ++k)
      if (k != drop) r[j++] = q[k];
    return r;
  };
  Plc<2> pslg;
  for (uint32_t v : ids) {
    const auto q = project(p(v));
    pslg.points.insert(pslg.points.end(), q.begin(), q.end());
  }
  auto local = [&](uint32_t v) { return static_cast<uint32_t>(std::lower_bound(ids.begin(), ids.end(), v) - ids.begin()); };
  std::vector<std::array<uint32_t, 2>> segments;
  for (const auto& poly : f.polygons) {
    if (poly.size() < 2) continue;
    for (std::size_t i = 0; i < (poly.size() == 2 ? 1 : poly.size()); ++i) {
      std::array<uint32_t, 2> s{local(poly[i]), local(poly[(i + 1) % poly.size()])};
      if (s[0] == s[1]) bad("has a polygon naming point " + std::to_string(poly[i]) + " twice in a row");
      if (s[0] > s[1]) std::swap(s[0], s[1]);
      segments.push_back(s);
    }
  }
  std::sort(segments.begin(), segments.end());
  segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
  for (const auto& s : segments) pslg.simplices.insert(pslg.simplices.end(), s.begin(), s.end());
  std::vector<std::array<double, 2>> holes;
  for (const auto& h : f.holes) holes.push_back(project(h.data()));
  for (uint32_t t : triangles_of_pslg(pslg, holes, file, "facet at line " + std::to_string(f.line))) soup.triangles.push_back(ids[t]);
}

// The domain of the facets with TetGen's meaning, as notations (see the file comment).
void notate(Plc<3>& plc, const std::vector<std::array<double, 3>>& holes, const std::string& file) {
  Surface surface;
  surface.file = file;
  surface.points = plc.points;
  surface.triangles = plc.simplices;
  surface.points_in_file = surface.num_points();
  const SurfaceReport report = inspect(surface);
  if (!report.valid()) {
    if (report.closed_shells() == 0 && holes.empty()) return;  // open constraints: the convex hull
    std::string first = report.problems.empty() ? "not a closed manifold surface" : report.problems.front().message;
    fail(InputErrorKind::Unsupported, file, Location::none(),
         "the facets " + std::string(holes.empty() ? "enclose a volume but " : "must form closed, manifold shells for hole points; they ") +
             "do not form closed, manifold, non-intersecting shells: " + first);
  }
  // Shell of each triangle: components through shared vertices, named by their smallest triangle
  // (Shell::first_triangle).
  const std::size_t m = plc.num_simplices();
  std::vector<uint32_t> parent(plc.num_points());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (std::size_t t = 0; t < m; ++t)
    for (int k = 1; k < 3; ++k) parent[root(plc.simplices[3 * t + k])] = root(plc.simplices[3 * t]);
  std::vector<int32_t> shell_of_first(m, -1);
  for (std::size_t s = 0; s < report.shells.size(); ++s) shell_of_first[report.shells[s].first_triangle] = static_cast<int32_t>(s);
  std::vector<int32_t> shell_of_root(plc.num_points(), -1), shell(m);
  std::vector<std::vector<uint32_t>> members(report.shells.size());
  for (std::size_t t = 0; t < m; ++t) {
    int32_t& s = shell_of_root[root(plc.simplices[3 * t])];
    if (s < 0) s = shell_of_first[t];  // the first triangle met is the component's smallest
    shell[t] = s;
    members[s].push_back(static_cast<uint32_t>(t));
  }
  // Cells eaten by hole points: the innermost shell containing each. Each hole costs a scan of the
  // triangles; a file with very many of both is refused rather than left to run for minutes.
  if (holes.size() * uint64_t{m} > (uint64_t{1} << 28))
    fail(InputErrorKind::Unsupported, file, Location::none(), std::to_string(holes.size()) + " hole points in " + std::to_string(m) + " triangles is too many to locate");
  std::vector<uint8_t> eaten(report.shells.size(), 0);
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const double* q = holes[h].data();
    for (std::size_t t = 0; t < m; ++t) {  // inside_shell() needs q off the shell
      const uint32_t* v = plc.simplex(t);
      const double *a = plc.point(v[0]), *b = plc.point(v[1]), *c = plc.point(v[2]);
      if (predicates::orient<3>({a, b, c, q}) != Sign::Zero) continue;
      int drop = 0;
      while (drop < 3 && predicates::orient_projected<3>({a, b, c}, drop) == Sign::Zero) ++drop;
      const Sign turn = predicates::orient_projected<3>({a, b, c}, drop);
      if (predicates::orient_projected<3>({a, b, q}, drop) != -turn && predicates::orient_projected<3>({b, c, q}, drop) != -turn &&
          predicates::orient_projected<3>({c, a, q}, drop) != -turn)
        fail(InputErrorKind::BadPolygon, file, Location::of("hole", h), "hole point lies on a facet, so it names no side");
    }
    int32_t innermost = -1;
    for (std::size_t s = 0; s < members.size(); ++s)
      if (inside_shell(surface, members[s], q) && (innermost < 0 || report.shells[s].depth > report.shells[innermost].depth))
        innermost = static_cast<int32_t>(s);
    if (innermost >= 0) eaten[innermost] = 1;  // outside every shell: eaten anyway
  }
  Plc<3> out;
  out.points = std::move(plc.points);
  out.region_seeds = std::move(plc.region_seeds);
  for (std::size_t t = 0; t < m; ++t) {
    const Shell& s = report.shells[shell[t]];
    const bool inside_eaten = eaten[shell[t]], outside_eaten = s.parent < 0 || eaten[s.parent];
    // reverse[t] makes t counterclockwise seen from outside the material: outward for bodies (even
    // depth), inward for cavities. Counterclockwise from outside the shell = its inside is positive.
    const bool outward = !(report.reverse[t] ^ (s.depth % 2 == 1));
    const bool positive_eaten = outward ? inside_eaten : outside_eaten, negative_eaten = outward ? outside_eaten : inside_eaten;
    if (positive_eaten && negative_eaten) continue;
    out.simplices.insert(out.simplices.end(), plc.simplex(t), plc.simplex(t) + 3);
    out.exterior.push_back(positive_eaten ? ExteriorSide::Positive : negative_eaten ? ExteriorSide::Negative : ExteriorSide::None);
    out.tags.push_back(plc.tags[t]);
  }
  if (out.simplices.empty()) fail(InputErrorKind::BadPolygon, file, Location::none(), "the holes eat the whole domain");
  plc = std::move(out);
}

}  // namespace

Plc<3> read_tetgen_poly(const std::string& bytes, const std::filesystem::path& file, bool smesh) {
  const std::string name = file.string();
  TextScanner in(bytes, name, '#');
  std::filesystem::path node_file = file;
  node_file.replace_extension(".node");
  NodeList nodes = read_node_list(in, 3, node_file);
  Plc<3> plc;
  plc.points = std::move(nodes.points);
  const uint64_t n = plc.num_points();
  auto corner = [&](std::string_view token) {
    const int64_t v = in.to_integer(token, "a corner");
    if (v < nodes.base || v - nodes.base >= static_cast<int64_t>(n))
      in.fail(InputErrorKind::IndexOutOfRange, "corner " + std::to_string(v) + " does not exist (" + std::to_string(n) + " points from " + std::to_string(nodes.base) + ")");
    return static_cast<uint32_t>(v - nodes.base);
  };

  const uint64_t facets = static_cast<uint64_t>(in.to_integer(in.next_token(), "number of facets", 0, INT64_MAX));
  if (facets > in.bytes_left() / 6) in.fail(InputErrorKind::AbsurdCount, std::to_string(facets) + " facets announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
  const bool markers = in.to_integer(in.next_token(), "number of facet markers", 0, 1) == 1;
  Soup soup;  // the facets' triangles, over the file's points
  soup.file = name;
  soup.points = std::move(plc.points);
  std::vector<std::string_view> line;
  for (uint64_t j = 0; j < facets; ++j) {
    Facet f;
    f.tag = static_cast<uint32_t>(j);
    if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, "the file ends inside the facet list");
    f.line = in.line();
    auto polygon = [&](const std::vector<std::string_view>& l, std::size_t corners_at) {
      const int64_t k = in.to_integer(l[corners_at], "number of corners", 1, 1 << 20);
      if (l.size() < corners_at + 1 + static_cast<std::size_t>(k)) in.fail(InputErrorKind::Syntax, "a polygon line lists fewer corners than it announces");
      std::vector<uint32_t> ids;
      for (int64_t c = 0; c < k; ++c) ids.push_back(corner(l[corners_at + 1 + c]));
      return std::pair{ids, corners_at + 1 + static_cast<std::size_t>(k)};
    };
    if (smesh) {  // <corners> <c1> ... [marker]
      auto [ids, used] = polygon(line, 0);
      f.polygons.push_back(std::move(ids));
      if (markers && line.size() > used) f.tag = static_cast<uint32_t>(in.to_integer(line[used], "a facet marker", 0, UINT32_MAX - 1));
      if (line.size() > used + (markers ? 1 : 0)) in.fail(InputErrorKind::Syntax, "extra numbers after the facet");
    } else {  // <polygons> [holes] [marker], then the polygons and holes
      if (line.size() > 3) in.fail(InputErrorKind::Syntax, "a facet line is '<polygons> [holes] [marker]'");
      const int64_t polygons = in.to_integer(line[0], "number of polygons", 1, 1 << 20);
      const int64_t hole_count = line.size() > 1 ? in.to_integer(line[1], "number of facet holes", 0, 1 << 20) : 0;
      if (markers && line.size() > 2) f.tag = static_cast<uint32_t>(in.to_integer(line[2], "a facet marker", 0, UINT32_MAX - 1));
      for (int64_t k = 0; k < polygons; ++k) {
        if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, "the file ends inside a facet");
        auto [ids, used] = polygon(line, 0);
        if (line.size() != used) in.fail(InputErrorKind::Syntax, "extra numbers after the polygon");
        f.polygons.push_back(std::move(ids));
      }
      for (int64_t k = 0; k < hole_count; ++k) {
        in.to_integer(in.next_token(), "a facet hole id");
        f.holes.push_back({in.to_double(in.next_token(), "x"), in.to_double(in.next_token(), "y"), in.to_double(in.next_token(), "z")});
      }
    }
    const std::size_t before = soup.num_triangles();
    triangulate_facet(soup, f);
    plc.tags.insert(plc.tags.end(), soup.num_triangles() - before, f.tag);
  }

  plc.points = std::move(soup.points);
  plc.simplices = std::move(soup.triangles);

  std::vector<std::array<double, 3>> holes;
  const std::string_view hole_count = in.next_token();
  if (!hole_count.empty()) {
    const uint64_t h = static_cast<uint64_t>(in.to_integer(hole_count, "number of holes", 0, INT64_MAX));
    if (h > in.bytes_left() / 8) in.fail(InputErrorKind::AbsurdCount, std::to_string(h) + " holes announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
    for (uint64_t i = 0; i < h; ++i) {
      in.to_integer(in.next_token(), "a hole id");
      holes.push_back({in.to_double(in.next_token(), "x"), in.to_double(in.next_token(), "y"), in.to_double(in.next_token(), "z")});
    }
    if (in.next_line(line)) {
      const uint64_t r = static_cast<uint64_t>(in.to_integer(line[0], "number of regions", 0, INT64_MAX));
      if (r > in.bytes_left() / 10) in.fail(InputErrorKind::AbsurdCount, std::to_string(r) + " regions announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
      for (uint64_t i = 0; i < r; ++i) {
        if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, "the file ends inside the region list");
        if (line.size() < 5 || line.size() > 6) in.fail(InputErrorKind::Syntax, "a region line is '<id> <x> <y> <z> <region number> [<attribute>]'");
        const int64_t region = in.to_integer(line[4], "a region number", 0, INT32_MAX - 1);
        plc.region_seeds.push_back({{in.to_double(line[1], "x"), in.to_double(line[2], "y"), in.to_double(line[3], "z")}, static_cast<int32_t>(region)});
      }
      if (in.next_line(line)) in.fail(InputErrorKind::Syntax, "unexpected text after the region list");
    }
  }
  notate(plc, holes, name);
  return plc;
}

}  // namespace sweepcdt::io::detail
