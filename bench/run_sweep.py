#!/usr/bin/env python3
"""SweepCDT (both variants) against tetgen -pQM and CGAL's Delaunay_triangulation_3 on the same
closed surfaces, in one run on one machine. Prints a Markdown table of median wall times, peak
memory (MB, /usr/bin/time) and ratios, and the fitted growth exponent k of time ~ n^k.

  bench/run_sweep.py [BUILD_DIR] [--quick] [--repeat K]

TetGen runs with -NEF (no output files; sweepcdt writes none either). A TetGen run that added
Steiner points is marked: the comparison is then not like for like.
"""
import json, math, os, re, subprocess, sys, tempfile

args = [a for a in sys.argv[1:] if not a.startswith("--")]
build = args[0] if args else "build"
quick = "--quick" in sys.argv
repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 3
sweep = os.path.join(build, "bench", "sweep_bench")
cgal = os.path.join(build, "bench", "cgal_delaunay")

CASES = [("icosphere", [5, 6]), ("torus", [100]), ("cavity", [5]), ("cospherical", [5])] if quick else [
    ("icosphere", [5, 6, 7, 8]), ("torus", [100]), ("cavity", [5, 6]), ("cospherical", [5, 6])]

def timed(cmd):
    """Runs cmd under /usr/bin/time; returns (stdout, stderr, seconds, peak MB)."""
    r = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M"] + cmd, capture_output=True, text=True)
    m = re.search(r"TIME ([\d.]+) (\d+)", r.stderr)
    return r.stdout, r.stderr, float(m.group(1)), int(m.group(2)) / 1024.0

def median(xs):
    xs = sorted(xs)
    return xs[len(xs) // 2]

rows, growth, sphere_growth = [], {}, {}
with tempfile.TemporaryDirectory() as tmp:
    for surface, sizes in CASES:
        for size in sizes:
            off = os.path.join(tmp, f"{surface}{size}.off")
            subprocess.run([sweep, surface, str(size), "--off", off], check=True)
            row = {"surface": surface, "size": size}
            for algorithm in ("sweep-plane", "sweep-sphere"):
                out, _, _, mb = timed([sweep, surface, str(size), "--algorithm", algorithm, "--repeat", str(repeat)])
                j = json.loads(out.strip().splitlines()[-1])
                row["triangles"], row["points"] = j["triangles"], j["points"]
                row[algorithm] = j["median_seconds"] if not j["error"] else None
                row[algorithm + " MB"] = mb
                row[algorithm + " tets"] = j["tets"]
                row[algorithm + " error"] = j["error"]
            times, mbs, steiner = [], [], False
            for _ in range(repeat):
                out, err, sec, mb = timed(["tetgen", "-pQMNEF", off])
                times.append(sec)
                mbs.append(mb)
            # tetgen -Q is quiet; rerun verbosely once to learn its Steiner points and tets.
            verbose = subprocess.run(["tetgen", "-pMNEF", off], capture_output=True, text=True).stdout
            row["tetgen steiner"] = sum(int(n) for n in re.findall(r"Steiner points[^:\n]*:\s*(\d+)", verbose))
            row["tetgen"], row["tetgen MB"] = median(times), max(mbs)
            out, _, _, mb = timed([cgal, off, "--repeat", str(repeat)])
            row["cgal"], row["cgal MB"] = json.loads(out)["median_seconds"], mb
            rows.append(row)
            growth.setdefault(surface, []).append((row["triangles"], row["sweep-plane"]))
            sphere_growth.setdefault(surface, []).append((row["triangles"], row["sweep-sphere"]))
            print(json.dumps(row), file=sys.stderr, flush=True)

def fmt(x, digits=3):
    return "fail" if x is None else f"{x:.{digits}f}"

# sweep-sphere is the default algorithm: its ratios are the ones the targets (issue 16) are about.
print("| surface | triangles | sweep-plane s | sweep-sphere s | tetgen -pQM s | CGAL Delaunay s | plane/tetgen | plane/CGAL "
      "| sphere/tetgen | sphere/CGAL | MB sphere / tetgen | tets/tetgen Steiner |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
def ratio(a, b, digits):
    return "—" if a is None else f"{a / b:.{digits}f}"
for r in rows:
    p, q = r["sweep-plane"], r["sweep-sphere"]
    err = r["sweep-plane error"] or r["sweep-sphere error"]
    print(f"| {r['surface']} | {r['triangles']} | {fmt(p)} | {fmt(q)} | {fmt(r['tetgen'])} | {fmt(r['cgal'])} "
          f"| {ratio(p, r['tetgen'], 2)} | {ratio(p, r['cgal'], 1)} | {ratio(q, r['tetgen'], 2)} | {ratio(q, r['cgal'], 1)} "
          f"| {r['sweep-sphere MB']:.0f} / {r['tetgen MB']:.0f} | {r['sweep-plane tets']} / {r['tetgen steiner']}"
          + (f" ({err[:60]})" if err else "") + " |")
for surface, pts in growth.items():
    pts = [(n, t) for n, t in pts if t and t > 0]
    if len(pts) >= 2:
        (n0, t0), (n1, t1) = pts[0], pts[-1]
        print(f"\n{surface}: time ~ n^{math.log(t1 / t0) / math.log(n1 / n0):.2f} from {n0} to {n1} triangles (sweep-plane)")
for surface, pts in sphere_growth.items():
    pts = [(n, t) for n, t in pts if t and t > 0]
    if len(pts) >= 2:
        (n0, t0), (n1, t1) = pts[0], pts[-1]
        print(f"{surface}: time ~ n^{math.log(t1 / t0) / math.log(n1 / n0):.2f} from {n0} to {n1} triangles (sweep-sphere)")
# Exactly cospherical against the jittered sphere of the same size (same triangle count).
for r in rows:
    if r["surface"] != "cospherical":
        continue
    for j in rows:
        if j["surface"] == "icosphere" and j["triangles"] == r["triangles"]:
            for a in ("sweep-plane", "sweep-sphere"):
                if r[a] and j[a]:
                    print(f"cospherical / icosphere at {r['triangles']} triangles: {r[a] / j[a]:.1f}x ({a})")
