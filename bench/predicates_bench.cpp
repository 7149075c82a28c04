// ns/call of sweepcdt's orient<3>, insphere<3> and insphere_perturbed<3>, next to CGAL's
// Exact_predicates_inexact_constructions_kernel orientation / side_of_oriented_sphere on the very same
// point arrays (when CGAL is available).
//
// Input sets (kCases cases each, pre-generated, looped over):
//   random       uniform doubles in [-1, 1]^3: the floating-point filters decide almost everything;
//   grid         integer points of {-1, 0, 1}^3: many tests are exactly zero, so the exact path runs;
//   coplanar     4 points exactly on a dyadic plane (orient is always exactly zero);
//   cospherical  5 points of the integer sphere x^2+y^2+z^2 = 9, translated by a dyadic offset
//                (insphere is always exactly zero; insphere_perturbed is then decided symbolically).
// The fraction of exact zeros of each set is reported as the counter `zeros`.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "sweepcdt/predicates.h"

#ifdef SWEEPCDT_BENCH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

namespace pr = sweepcdt::predicates;

constexpr std::size_t kCases = 4096;  // a power of two: the loop index wraps with a mask
using P3 = std::array<double, 3>;
using Case = std::array<P3, 5>;  // orient uses the first 4 points, insphere all 5

struct InputSet {
  explicit InputSet(std::string n) : name(std::move(n)) {}
  std::string name;
  std::vector<Case> cases;
  std::vector<pr::Coords<4>> orient_args;
  std::vector<pr::Coords<5>> insphere_args;
  std::vector<pr::Vertices<5>> vertex_args;
#ifdef SWEEPCDT_BENCH_CGAL
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<std::array<K::Point_3, 5>> cgal;
#endif

  void finish() {
    for (std::size_t n = 0; n < cases.size(); ++n) {
      auto& c = cases[n];
      orient_args.push_back({c[0].data(), c[1].data(), c[2].data(), c[3].data()});
      insphere_args.push_back({c[0].data(), c[1].data(), c[2].data(), c[3].data(), c[4].data()});
      pr::Vertices<5> v;
      for (int i = 0; i < 5; ++i) v[i] = {c[i].data(), static_cast<uint32_t>(5 * n + (i * 3) % 5)};
      vertex_args.push_back(v);
#ifdef SWEEPCDT_BENCH_CGAL
      std::array<K::Point_3, 5> q;
      for (int i = 0; i < 5; ++i) q[i] = K::Point_3(c[i][0], c[i][1], c[i][2]);
      cgal.push_back(q);
#endif
    }
  }
};

// Short dyadic doubles (26 significant bits) keep sums of a few small-dyadic multiples exact.
double short_double(std::mt19937_64& rng) {
  return std::ldexp(static_cast<double>(std::uniform_int_distribution<int>(-(1 << 25), 1 << 25)(rng)), -25);
}

// kCases cases with every coordinate drawn from `coordinate`.
template <class Distribution>
InputSet make_uniform(const char* name, std::mt19937_64& rng, Distribution coordinate) {
  InputSet s(name);
  for (std::size_t n = 0; n < kCases; ++n) {
    Case c;
    for (auto& p : c)
      for (double& x : p) x = coordinate(rng);
    s.cases.push_back(c);
  }
  return s;
}

InputSet make_random(std::mt19937_64& rng) {
  return make_uniform("random", rng, std::uniform_real_distribution<double>(-1.0, 1.0));
}

// Coordinates in {-1, 0, 1}: many exact zeros.
InputSet make_grid(std::mt19937_64& rng) {
  return make_uniform("grid", rng, std::uniform_int_distribution<int>(-1, 1));
}

InputSet make_coplanar(std::mt19937_64& rng) {
  InputSet s("coplanar");
  std::uniform_int_distribution<int> small(-4, 4);
  for (std::size_t n = 0; n < kCases; ++n) {
    // z = a x + b y + c with a, b, c multiples of 1/4: exact for 26-bit x and y.
    const double a = small(rng) / 4.0, b = small(rng) / 4.0, off = small(rng) / 4.0;
    Case c;
    for (auto& p : c) {
      p[0] = short_double(rng);
      p[1] = short_double(rng);
      p[2] = a * p[0] + b * p[1] + off;
    }
    s.cases.push_back(c);
  }
  return s;
}

InputSet make_cospherical(std::mt19937_64& rng) {
  InputSet s("cospherical");
  std::vector<P3> sphere;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = -3; z <= 3; ++z)
        if (x * x + y * y + z * z == 9) sphere.push_back({double(x), double(y), double(z)});
  std::uniform_int_distribution<std::size_t> pick(0, sphere.size() - 1);
  for (std::size_t n = 0; n < kCases; ++n) {
    const P3 offset{short_double(rng), short_double(rng), short_double(rng)};
    Case c;
    std::array<std::size_t, 5> idx;
    for (int i = 0; i < 5; ++i) {
      bool fresh;
      do {
        idx[i] = pick(rng);
        fresh = true;
        for (int j = 0; j < i; ++j) fresh &= idx[j] != idx[i];
      } while (!fresh);
      for (int k = 0; k < 3; ++k) c[i][k] = sphere[idx[i]][k] + offset[k];
    }
    s.cases.push_back(c);
  }
  return s;
}

std::vector<InputSet>& sets() {
  static std::vector<InputSet> all = [] {
    std::mt19937_64 rng(20240601);
    std::vector<InputSet> v;
    v.push_back(make_random(rng));
    v.push_back(make_grid(rng));
    v.push_back(make_coplanar(rng));
    v.push_back(make_cospherical(rng));
    for (auto& s : v) s.finish();
    return v;
  }();
  return all;
}

double zero_fraction(const InputSet& s, bool insphere) {
  std::size_t zeros = 0;
  for (std::size_t n = 0; n < s.cases.size(); ++n)
    zeros += (insphere ? pr::insphere<3>(s.insphere_args[n]) : pr::orient<3>(s.orient_args[n])) == pr::Sign::Zero;
  return static_cast<double>(zeros) / static_cast<double>(s.cases.size());
}

// Registers name = predicate/library/set, timing one call per iteration over the set's cases.
template <class Call>
void add(const std::string& predicate, const std::string& library, const InputSet& set, double zeros, Call call) {
  benchmark::RegisterBenchmark((predicate + "/" + library + "/" + set.name).c_str(),
                               [&set, zeros, call](benchmark::State& state) {
                                 std::size_t i = 0;
                                 for (auto _ : state) {
                                   benchmark::DoNotOptimize(call(set, i));
                                   i = (i + 1) & (kCases - 1);
                                 }
                                 state.counters["zeros"] = zeros;
                               });
}

#ifdef SWEEPCDT_BENCH_CGAL
int cgal_sign(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : s == CGAL::NEGATIVE ? -1 : 0; }

// CGAL's sign conventions differ from Shewchuk's; find the factor and check it on every case, so
// that both libraries demonstrably compute the same predicate.
void check_against_cgal() {
  for (const InputSet& s : sets()) {
    int orient_factor = 0, insphere_factor = 0;
    bool orient_ok = true, insphere_ok = true;
    for (std::size_t n = 0; n < s.cases.size(); ++n) {
      const auto& q = s.cgal[n];
      const int o = pr::to_int(pr::orient<3>(s.orient_args[n]));
      const int oc = cgal_sign(CGAL::orientation(q[0], q[1], q[2], q[3]));
      if (orient_factor == 0 && o != 0) orient_factor = o * oc;
      orient_ok &= o == orient_factor * oc || (o == 0 && oc == 0);
      const int i = pr::to_int(pr::insphere<3>(s.insphere_args[n]));
      const int ic = cgal_sign(CGAL::side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4]));
      if (insphere_factor == 0 && i != 0) insphere_factor = i * ic;
      insphere_ok &= i == insphere_factor * ic || (i == 0 && ic == 0);
    }
    std::fprintf(stderr, "check %-12s orient3 %s CGAL (factor %+d), insphere3 %s CGAL (factor %+d)\n", s.name.c_str(),
                 orient_ok ? "agrees with" : "DISAGREES with", orient_factor,
                 insphere_ok ? "agrees with" : "DISAGREES with", insphere_factor);
    if (!orient_ok || !insphere_ok) std::exit(1);
  }
}
#endif

void register_all() {
  for (const InputSet& s : sets()) {
    const double oz = zero_fraction(s, false), iz = zero_fraction(s, true);
    if (s.name != "cospherical")
      add("orient3", "sweepcdt", s, oz, [](const InputSet& set, std::size_t i) { return pr::orient<3>(set.orient_args[i]); });
#ifdef SWEEPCDT_BENCH_CGAL
    if (s.name != "cospherical")
      add("orient3", "cgal", s, oz, [](const InputSet& set, std::size_t i) {
        const auto& q = set.cgal[i];
        return CGAL::orientation(q[0], q[1], q[2], q[3]);
      });
#endif
    if (s.name == "coplanar") continue;
    add("insphere3", "sweepcdt", s, iz, [](const InputSet& set, std::size_t i) { return pr::insphere<3>(set.insphere_args[i]); });
#ifdef SWEEPCDT_BENCH_CGAL
    add("insphere3", "cgal", s, iz, [](const InputSet& set, std::size_t i) {
      const auto& q = set.cgal[i];
      return CGAL::side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4]);
    });
#endif
    if (s.name == "grid" || s.name == "cospherical")
      add("insphere_perturbed3", "sweepcdt", s, iz,
          [](const InputSet& set, std::size_t i) { return pr::insphere_perturbed<3>(set.vertex_args[i]); });
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
#ifdef SWEEPCDT_BENCH_CGAL
  check_against_cgal();
#else
  std::fprintf(stderr, "built without CGAL: only sweepcdt's predicates are timed\n");
#endif
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
