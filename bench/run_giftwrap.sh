#!/usr/bin/env bash
# Gift-wrapping (paper §2, O(n_v n_f n_s)) against the sweep sphere on random points in a cube
# (convex hull domain), 1k / 2k / 5k vertices. Prints a Markdown table.
# Usage: bench/run_giftwrap.sh [BUILD_DIR]
set -euo pipefail
build="${1:-build}"
echo "| vertices | tetrahedra | gift-wrap s | sweep-sphere s | ratio |"
echo "|---|---|---|---|---|"
for n in 1000 2000 5000; do
  gift=$("$build/bench/sweep_bench" cube-points "$n" --algorithm giftwrap)
  sweep=$("$build/bench/sweep_bench" cube-points "$n" --algorithm sweep-sphere --repeat 3)
  python3 - "$gift" "$sweep" <<'PY'
import json, sys
g, s = json.loads(sys.argv[1]), json.loads(sys.argv[2])
print(f"| {g['points']} | {g['tets']} | {g['median_seconds']:.2f} | {s['median_seconds']:.3f} | {g['median_seconds'] / s['median_seconds']:.0f}x |")
PY
done
