#!/usr/bin/env bash
# Sample: several surfaces in one run, two at a time, with statistics in JSON.
# Usage: samples/batch.sh [OUT_DIR]    (default: sample-output/; SWEEPCDT=path/to/sweepcdt)
set -euo pipefail
cd "$(dirname "$0")/.."
sweepcdt="${SWEEPCDT:-build/plugin/cli/sweepcdt}"
out="${1:-sample-output}"

"$sweepcdt" mesh samples/data/knot1.drc samples/data/icosahedron.off \
    --out-dir "$out/batch" --format vtu --threads 2 --stats "$out/batch/stats.json"
ls "$out/batch"
# The statistics: counts and per-phase times of each file, peak memory of the run.
if ! command -v python3 > /dev/null; then cat "$out/batch/stats.json"; exit 0; fi
python3 - "$out/batch/stats.json" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
for f in stats["files"]:
    print(f'{f["input"]}: {f["tetrahedra"]} tetrahedra, {f["steiner_points"]} Steiner points, sweep {f["seconds"]["build"]:.2f} s')
print(f'peak memory: {stats["peak_memory_bytes"] / 2**20:.0f} MiB')
PY
