// Vertex deletion (EditableCdt, paper §5) against recomputing the CDT: builds a CDT, deletes k
// random interior vertices one by one, timing each, and prints one JSON line with the time of
// cdt() from scratch, the mean deletion time, and per star size (simplices around the vertex,
// bucketed by powers of two) the mean µs per deletion and ns per n_s log2 n_v — n_s the star's
// simplices, n_v its link's vertices — which is flat if deletion costs O(n_s log n_v).
//
//   delete_bench DOMAIN D POINTS [--deletions K] [--seed S]
//   DOMAIN: hull   — POINTS random points in the unit D-cube, the convex hull as domain
//           facets — D = 3: a jittered icosphere (1280 triangles, notated) around POINTS random
//                    points inside it: a facet-bounded domain
//           centre — POINTS random points on the unit sphere (radially jittered by 1e-3) and its
//                    centre, the one interior vertex: its star holds most of the mesh, so one
//                    deletion per run measures stars from tens to ~10^5 simplices
//
// The star sizes come from a snapshot, untimed, taken once per round; within a round the vertices
// deleted share no simplex, so each star deleted is still the one the snapshot shows.
// The final mesh is checked with validate() against the PLC left, so a timing is never of a wrong
// result.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "surfaces.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/editable_cdt.h"

using namespace sweepcdt;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

template <int D>
Plc<D> make(const std::string& domain, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Plc<D> plc;
  if (domain == "hull") {
    for (int i = 0; i < D * n; ++i) plc.points.push_back(u(rng));
    return plc;
  }
  if (domain == "centre") {
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
    for (int i = 0; i < n; ++i) {
      std::array<double, D> p;
      double r2 = 0;
      for (double& x : p) r2 += (x = gauss(rng)) * x;
      const double scale = (1 + jitter(rng)) / std::sqrt(r2);
      for (double x : p) plc.points.push_back(x * scale);
    }
    plc.points.insert(plc.points.end(), D, 0.0);
    return plc;
  }
  if constexpr (D == 3) {
    if (domain == "facets") {
      bench::Mesh sphere = bench::icosphere(3);
      bench::jitter(sphere, 1e-3, seed);
      plc = bench::to_plc(sphere);
      for (int added = 0; added < n;) {  // uniform in the ball of radius 0.9, well inside the surface
        const double x = 2 * u(rng) - 1, y = 2 * u(rng) - 1, z = 2 * u(rng) - 1;
        if (x * x + y * y + z * z > 1) continue;
        plc.points.insert(plc.points.end(), {0.9 * x, 0.9 * y, 0.9 * z});
        ++added;
      }
      return plc;
    }
  }
  throw std::invalid_argument("unknown domain " + domain + " for D = " + std::to_string(D));
}

struct Bucket {
  int count = 0;
  double micros = 0, nanos_per_unit = 0;
};

template <int D>
int run(const std::string& domain, int n, int deletions, uint64_t seed) {
  const Plc<D> plc = make<D>(domain, n, seed);
  auto start = Clock::now();
  Plc<D> triangulated;
  Triangulation<D> tri = cdt(plc, Options{}, &triangulated);
  const double seconds_cdt = since(start);

  start = Clock::now();
  EditableCdt<D> mesh(triangulated, tri);
  const double seconds_editable = since(start);

  // Candidates: vertices on no constraint, in random order (those on the convex hull's boundary
  // are refused by EditableCdt; that is not what this measures, so they are skipped untimed).
  std::vector<char> on_constraint(tri.num_points(), 0), refused(tri.num_points(), 0);
  for (uint32_t v : triangulated.simplices) on_constraint[v] = 1;
  std::vector<uint32_t> order(tri.num_points());
  for (uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  std::mt19937_64 rng(seed + 1);
  std::shuffle(order.begin(), order.end(), rng);
  if (domain == "centre")  // the centre (the last point) first: the jittered sphere has inner points too
    std::iter_swap(order.begin(), std::find(order.begin(), order.end(), static_cast<uint32_t>(order.size() - 1)));

  std::map<int, Bucket> buckets;  // by floor(log2(n_s))
  double total = 0;
  int done = 0, hull = 0, rounds = 0;
  std::size_t largest_star = 0, largest_link = 0;  // the deletion with the largest star
  double largest_us = 0;
  while (done < deletions) {
    // A round: stars from a snapshot (untimed), then deletions of vertices no two of which share a
    // simplex, so that every star deleted is still the one the snapshot shows.
    ++rounds;
    const auto now = mesh.snapshot();
    std::vector<std::vector<uint32_t>> star(tri.num_points());  // by id: simplices of the snapshot
    for (uint32_t t = 0; t < now.triangulation.num_simplices(); ++t)
      for (int i = 0; i <= D; ++i) star[now.old_ids[now.triangulation.simplex(t)[i]]].push_back(t);
    std::vector<char> blocked(tri.num_points(), 0);
    const int before = done;
    for (uint32_t v : order) {
      if (done == deletions) break;
      if (blocked[v] || refused[v] || on_constraint[v] || star[v].empty()) continue;
      std::set<uint32_t> link;
      for (uint32_t t : star[v])
        for (int i = 0; i <= D; ++i) link.insert(now.old_ids[now.triangulation.simplex(t)[i]]);
      link.erase(v);
      const auto t0 = Clock::now();
      try {
        mesh.remove_vertex(v);
      } catch (const VertexRemovalError&) {
        refused[v] = 1;
        ++hull;
        continue;
      }
      const double micros = since(t0) * 1e6;
      blocked[v] = 1;
      for (uint32_t x : link) blocked[x] = 1;
      const double ns = static_cast<double>(star[v].size());
      Bucket& b = buckets[static_cast<int>(std::floor(std::log2(ns)))];
      ++b.count;
      b.micros += micros;
      b.nanos_per_unit += micros * 1e3 / (ns * std::log2(static_cast<double>(link.size())));
      total += micros;
      ++done;
      if (star[v].size() > largest_star) largest_star = star[v].size(), largest_link = link.size(), largest_us = micros;
    }
    if (done == before) break;  // nothing left to delete
  }

  start = Clock::now();
  const auto now = mesh.snapshot();
  const bool valid = validate_triangulated(now.triangulation, now.plc).ok();
  const double seconds_validate = since(start);

  std::printf("{\"domain\": \"%s\", \"dimension\": %d, \"points\": %zu, \"simplices\": %zu, \"seconds_cdt\": %.4f, "
              "\"seconds_editable\": %.4f, \"deletions\": %d, \"rounds\": %d, \"hull_refusals\": %d, \"mean_us\": %.2f, "
              "\"largest_star\": %zu, \"largest_link\": %zu, \"largest_us\": %.1f, \"seconds_validate\": %.3f, \"valid\": %s, "
              "\"buckets\": [",
              domain.c_str(), D, tri.num_points(), tri.num_simplices(), seconds_cdt, seconds_editable, done, rounds, hull,
              done ? total / done : 0.0, largest_star, largest_link, largest_us, seconds_validate, valid ? "true" : "false");
  bool first = true;
  for (const auto& [log, b] : buckets) {
    std::printf("%s{\"star_from\": %d, \"star_to\": %d, \"count\": %d, \"mean_us\": %.2f, \"ns_per_ns_log_nv\": %.2f}",
                first ? "" : ", ", 1 << log, (2 << log) - 1, b.count, b.micros / b.count, b.nanos_per_unit / b.count);
    first = false;
  }
  std::printf("]}\n");
  return valid && done == deletions ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s hull|facets|centre D POINTS [--deletions K] [--seed S]\n", argv[0]);
    return 2;
  }
  int deletions = 100;
  uint64_t seed = 7;
  for (int i = 4; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--deletions")) deletions = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed")) seed = std::strtoull(argv[i + 1], nullptr, 10);
    else {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  }
  const std::string domain = argv[1];
  const int n = std::atoi(argv[3]);
  try {
    switch (std::atoi(argv[2])) {
      case 2: return run<2>(domain, n, deletions, seed);
      case 3: return run<3>(domain, n, deletions, seed);
      case 4: return run<4>(domain, n, deletions, seed);
      default: std::fprintf(stderr, "D must be 2, 3 or 4\n"); return 2;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 4;
  }
}
