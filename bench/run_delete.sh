#!/usr/bin/env bash
# Vertex deletion (paper §5) against recomputing the CDT with cdt(): random points in a cube (convex
# hull domain, D = 2, 3, 4) and random points inside a notated icosphere (facet-bounded, D = 3);
# k random interior vertices deleted one by one. Then the centre of points on a sphere, whose star
# is most of the mesh (D = 2, 3): one deletion each, stars up to ~10^5 simplices. Prints three
# Markdown tables: the runs, the per-deletion cost by star size, and the large stars. The runs' JSON lines are kept in BUILD_DIR/bench/delete_runs.jsonl.
# SIZES_3D overrides the 3D point counts (default 1500 15000 150000: about 10k, 100k and 1M
# tetrahedra).
# Usage: bench/run_delete.sh [BUILD_DIR]
set -euo pipefail
build="${1:-build}"
bench="$build/bench/delete_bench"
runs="$build/bench/delete_runs.jsonl"
: > "$runs"
for n in ${SIZES_3D:-1500 15000 150000}; do
  for k in 100 1000; do
    "$bench" hull 3 "$n" --deletions "$k" >> "$runs"
    "$bench" facets 3 "$n" --deletions "$k" >> "$runs"
  done
done
for n in 5000 50000; do "$bench" hull 2 "$n" --deletions 1000 >> "$runs"; done
for n in 1000 3000; do "$bench" hull 4 "$n" --deletions 100 >> "$runs"; done
for n in 100 1000 10000 100000; do "$bench" centre 2 "$n" --deletions 1 >> "$runs"; done
for n in 100 1000 10000 30000; do "$bench" centre 3 "$n" --deletions 1 >> "$runs"; done
python3 - "$runs" <<'PY'
import json, math, sys
runs = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
stars = [r for r in runs if r["domain"] == "centre"]
runs = [r for r in runs if r["domain"] != "centre"]
print("| domain | D | points | simplices | cdt() s | deletions | mean µs per deletion | deletions per cdt() | valid |")
print("|---|---|---|---|---|---|---|---|---|")
for r in runs:
    per_cdt = r["seconds_cdt"] * 1e6 / r["mean_us"]
    print(f"| {r['domain']} | {r['dimension']} | {r['points']} | {r['simplices']} | {r['seconds_cdt']:.3f} | "
          f"{r['deletions']} | {r['mean_us']:.1f} | {per_cdt:.0f} | {r['valid']} |")
print()
print("| domain | D | simplices | star size n_s | deletions | mean µs | ns per n_s log2 n_v |")
print("|---|---|---|---|---|---|---|")
for r in runs:
    if r["deletions"] < 1000 and r["dimension"] != 4:  # the k = 1000 runs (D = 4: k = 100)
        continue
    for b in r["buckets"]:
        if b["count"] >= 5:
            print(f"| {r['domain']} | {r['dimension']} | {r['simplices']} | {b['star_from']}-{b['star_to']} | "
                  f"{b['count']} | {b['mean_us']:.1f} | {b['ns_per_ns_log_nv']:.0f} |")
print()
print("| centre of a sphere: D | points | cdt() s | star size n_s | link n_v | µs | ns per n_s log2 n_v |")
print("|---|---|---|---|---|---|---|")
for r in stars:
    n_s, n_v = r["largest_star"], r["largest_link"]
    unit = r["largest_us"] * 1e3 / (n_s * math.log2(n_v))
    print(f"| {r['dimension']} | {r['points']} | {r['seconds_cdt']:.3f} | {n_s} | {n_v} | {r['largest_us']:.0f} | {unit:.0f} |")
PY
