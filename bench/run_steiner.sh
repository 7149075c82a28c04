#!/usr/bin/env bash
# Steiner points and time: sweepcdt --steiner auto (triangles and coplanar facets) against
# `tetgen -pQM` (which keeps the input facets as given, so its output is comparable) on the same
# surfaces, in the same run. Prints a Markdown table; times are wall-clock seconds of one run each,
# sweepcdt's from inside cdt() (import excluded), TetGen's of the whole process (its own file
# reading included, which is small next to meshing).
# Usage: bench/run_steiner.sh [BUILD_DIR] [FILE...]   (default: the shared meshes with Steiner points)
set -euo pipefail
build="${1:-build}"
shift || true
data="$(cd "$(dirname "$0")/../.." && pwd)/shared/data"
files=("$@")
if [ ${#files[@]} -eq 0 ]; then
  files=("$data/off/femur.off" "$data/stl_ascii/t13_data_ascii.stl" "$data/stl_binary/spot.stl"
         "$data/stl_binary/torus.stl" "$data/stl_ascii/gearwheel_ascii.stl" "$data/stl_binary/thingi_1706459.stl")
fi
command -v tetgen >/dev/null || { echo "tetgen not found (scripts/setup.sh installs it)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| input | triangles | sweepcdt points | s | coplanar points | s | tetgen -pQM points | s | time ratio |"
echo "|---|---|---|---|---|---|---|---|---|"
for file in "${files[@]}"; do
  name=$(basename "$file")
  tri=$("$build/bench/steiner_bench" "$file" --off "$work/in.off" || true)
  cop=$("$build/bench/steiner_bench" "$file" --facets coplanar || true)
  python3 - "$name" "$tri" "$cop" "$work" <<'PY'
import json, os, subprocess, sys, time
name, tri, cop, work = sys.argv[1:]
t, c = json.loads(tri), json.loads(cop)
start = time.monotonic()
try:
    ok = subprocess.run(["tetgen", "-pQM", "in.off"], cwd=work, stdout=subprocess.DEVNULL,
                        stderr=subprocess.DEVNULL, timeout=600).returncode == 0
except subprocess.TimeoutExpired:
    ok = False
tet_seconds = time.monotonic() - start
node = os.path.join(work, "in.1.node")
if ok and os.path.exists(node):
    with open(node) as f:
        tet_points = str(int(f.readline().split()[0]) - t["points"])
else:
    tet_points = "fails"
for f in os.listdir(work):
    if f.startswith("in.1."):
        os.remove(os.path.join(work, f))
def cell(r):
    return ("fails", f"{r['seconds']:.1f}") if r["error"] else (str(r["steiner_points"]), f"{r['seconds']:.1f}")
tp, ts = cell(t)
cp, cs = cell(c)
tet = (tet_points, f"{tet_seconds:.1f}") if tet_points != "fails" else ("fails (crash)" if not ok else "fails", "")
ratio = f"{t['seconds'] / tet_seconds:.1f}x" if tet[1] and not t["error"] else ""
print(f"| {name} | {t['triangles']} | {tp} | {ts} | {cp} | {cs} | {tet[0]} | {tet[1]} | {ratio} |")
PY
done
