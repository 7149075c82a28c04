#!/bin/sh
# Same results before and after a change: runs the default command of two sweepcdt binaries on the
# CAD parts (tests/data/cad) and the closed shared meshes and compares exit codes and output files
# byte for byte (.mesh: same points, same tetrahedra in the same order). With --as-sets, files that
# differ only in the order of their triangles and tetrahedra count as the same (same_mesh_sets.py).
# usage: bench/compare_outputs.sh [--as-sets] SWEEPCDT_BEFORE SWEEPCDT_AFTER
# Prints one line per difference and "N inputs: all identical" when there is none; exit 1 on any.
set -u
as_sets=0
[ "${1:-}" = "--as-sets" ] && { as_sets=1; shift; }
[ $# -eq 2 ] || { echo "usage: $0 [--as-sets] SWEEPCDT_BEFORE SWEEPCDT_AFTER" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
shared="$root/../shared/data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inputs=$(ls "$root"/tests/data/cad/*.stl "$root"/tests/data/cad/*.obj "$root"/tests/data/cad/*.ply)
for f in off/femur.off off/icosahedron.off stl_ascii/t13_data_ascii.stl stl_binary/spot.stl stl_binary/torus.stl \
         stl_ascii/gearwheel_ascii.stl stl_binary/thingi_1706459.stl drc/knot1.drc glb/moon.glb drc/cube_att.drc; do
  if [ -f "$shared/$f" ]; then inputs="$inputs $shared/$f"; else echo "missing (skipped): $shared/$f"; fi
done
count=0
differ=0
reordered=0
for f in $inputs; do
  count=$((count + 1))
  "$1" "$f" -o "$work/before.mesh" --quiet >/dev/null 2>&1; a=$?
  "$2" "$f" -o "$work/after.mesh" --quiet >/dev/null 2>&1; b=$?
  if [ $a -ne $b ]; then
    echo "$f: exit code $a before, $b after"; differ=1
  elif [ $a -eq 0 ] && ! cmp -s "$work/before.mesh" "$work/after.mesh"; then
    if [ $as_sets -eq 1 ] && python3 "$root/bench/same_mesh_sets.py" "$work/before.mesh" "$work/after.mesh" >/dev/null; then
      reordered=$((reordered + 1))
    else
      echo "$f: outputs differ"; differ=1
    fi
  fi
  rm -f "$work/before.mesh" "$work/after.mesh"
done
[ $differ -eq 0 ] && echo "$count inputs: all identical (exit codes and output files; $reordered of them with elements in another order)"
exit $differ
