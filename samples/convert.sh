#!/usr/bin/env bash
# Sample: tetrahedralize the two sample surfaces into every volume-mesh format, then let
# `sweepcdt check` verify one of the outputs against its surface.
# Usage: samples/convert.sh [OUT_DIR]    (default: sample-output/; SWEEPCDT=path/to/sweepcdt)
set -euo pipefail
cd "$(dirname "$0")/.."
sweepcdt="${SWEEPCDT:-build/plugin/cli/sweepcdt}"
out="${1:-sample-output}"
mkdir -p "$out"

# Medit .mesh and VTK .vtu (ParaView) from one computation; the format comes from the extension.
"$sweepcdt" samples/data/knot1.drc -o "$out/knot1.mesh" -o "$out/knot1.vtu"
"$sweepcdt" samples/data/icosahedron.off -o "$out/icosahedron.msh" --format msh22   # Gmsh 2.2
"$sweepcdt" samples/data/icosahedron.off -o "$out/icosahedron.node"  # TetGen .node/.ele/.face
"$sweepcdt" samples/data/icosahedron.off -o "$out/icosahedron.inp" --check   # Abaqus, validated before writing
"$sweepcdt" check samples/data/knot1.drc "$out/knot1.mesh"
