#!/usr/bin/env bash
# Sample: the constrained Delaunay triangulation of a 2D Triangle .poly file (a square with a
# diamond-shaped hole), written as Triangle .node/.ele and as sweepcdt's .simplices text.
# Usage: samples/cdt_2d.sh [OUT_DIR]    (default: sample-output/; SWEEPCDT=path/to/sweepcdt)
set -euo pipefail
cd "$(dirname "$0")/.."
sweepcdt="${SWEEPCDT:-build/plugin/cli/sweepcdt}"
out="${1:-sample-output}"
mkdir -p "$out"

"$sweepcdt" cdt samples/data/diamond.poly -o "$out/diamond.node" --check
cat "$out/diamond.ele"
"$sweepcdt" cdt samples/data/diamond.poly -o "$out/diamond.simplices"
