#!/usr/bin/env bash
# Runs bench_predicates and prints ns/call of sweepcdt and CGAL side by side, with their ratio.
# usage: bench/run_predicates.sh [BUILD_DIR] [extra Google Benchmark flags...]
#   BUILD_DIR defaults to ./build; build first with
#   cmake --build BUILD_DIR --target bench_predicates -j2
set -euo pipefail
build=${1:-build}
shift || true
bin="$build/bench/bench_predicates"
if [[ ! -x "$bin" ]]; then
  echo "no $bin: build it with  cmake --build $build --target bench_predicates -j2" >&2
  exit 1
fi
json=$(mktemp)
log=$(mktemp)
trap 'rm -f "$json" "$log"' EXIT
# Medians of 3 repetitions by default (later flags in "$@" override these).
"$bin" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_out="$json" --benchmark_out_format=json "$@" >/dev/null 2>"$log" || { cat "$log" >&2; exit 1; }
# The binary's own sanity lines (sign agreement with CGAL on every case, or "built without CGAL").
grep -E '^(check|built without)' "$log" || true
python3 - "$json" <<'PY'
import json, sys

data = json.load(open(sys.argv[1]))
rows = {}
have_medians = any(b.get("aggregate_name") == "median" for b in data["benchmarks"])
for b in data["benchmarks"]:
    if have_medians and b.get("aggregate_name") != "median":
        continue
    if not have_medians and b.get("run_type", "iteration") != "iteration":
        continue
    predicate, library, inputs = b.get("run_name", b["name"]).split("/")[:3]
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
    rows.setdefault((predicate, inputs), {})[library] = (b["real_time"] * scale, b.get("zeros"))

ctx = data.get("context", {})
load = ctx.get("load_avg") or []
print(f"host: {ctx.get('num_cpus', '?')} cpus @ {ctx.get('mhz_per_cpu', '?')} MHz, load "
      f"{' '.join(f'{x:.2f}' for x in load) or '?'}; ns per call, "
      f"{'median of repetitions' if have_medians else 'single run'}")
header = f"{'predicate':<20} {'inputs':<12} {'zeros':>6} {'sweepcdt ns':>12} {'CGAL ns':>10} {'sweepcdt/CGAL':>14}"
print(header)
print("-" * len(header))
order = ["random", "grid", "coplanar", "cospherical"]
for (predicate, inputs) in sorted(rows, key=lambda k: (k[0], order.index(k[1]) if k[1] in order else 99)):
    r = rows[(predicate, inputs)]
    ours, zeros = r.get("sweepcdt", (None, None))
    theirs = r.get("cgal", (None, None))[0]
    note = ""
    if theirs is None and predicate == "insphere_perturbed3":
        # CGAL's kernel has no lifting-map perturbation: compare with its plain exact insphere.
        theirs = rows.get(("insphere3", inputs), {}).get("cgal", (None, None))[0]
        note = "  (vs CGAL side_of_oriented_sphere)"
    fmt = lambda x: f"{x:.1f}" if x is not None else "-"
    ratio = f"{ours / theirs:.2f}" if ours is not None and theirs else "-"
    z = f"{zeros:.0%}" if zeros is not None else "-"
    print(f"{predicate:<20} {inputs:<12} {z:>6} {fmt(ours):>12} {fmt(theirs):>10} {ratio:>14}{note}")
PY
