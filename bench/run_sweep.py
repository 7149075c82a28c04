#!/usr/bin/env python3
"""sweepcdt's algorithms against tetgen -pQM and CGAL's Delaunay_triangulation_3 on the same closed
surfaces, in one run on one machine. Prints a Markdown table of median times, peak memory (MB,
/usr/bin/time) and ratios, and the fitted growth exponent k of time ~ n^k.

  bench/run_sweep.py [BUILD_DIR] [--quick] [--repeat K] [--algorithms A,B,...]

The first algorithm listed (default: cavity-sweep, the library's default) is the one the ratios are
about; the others get their time and their ratio to TetGen. sweepcdt's times are cdt() in process
(the exact PLC check and the final validate() included, reading the surface not); TetGen's and
CGAL's whole processes, TetGen with -NEF (no output files; sweepcdt writes none either). A TetGen run
that added Steiner points is marked: the comparison is then not like for like.
"""
import argparse, json, math, os, re, subprocess, sys, tempfile

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("build", nargs="?", default="build")
parser.add_argument("--quick", action="store_true")
parser.add_argument("--repeat", type=int, default=3)
parser.add_argument("--algorithms", default="cavity-sweep,sweep-plane,sweep-sphere")
options = parser.parse_args()
build, quick, repeat = options.build, options.quick, options.repeat
algorithms = options.algorithms.split(",")
default = algorithms[0]
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

rows = []
with tempfile.TemporaryDirectory() as tmp:
    for surface, sizes in CASES:
        for size in sizes:
            off = os.path.join(tmp, f"{surface}{size}.off")
            subprocess.run([sweep, surface, str(size), "--off", off], check=True)
            row = {"surface": surface, "size": size}
            for algorithm in algorithms:
                out, _, _, mb = timed([sweep, surface, str(size), "--algorithm", algorithm, "--repeat", str(repeat)])
                j = json.loads(out.strip().splitlines()[-1])
                row["triangles"], row["points"] = j["triangles"], j["points"]
                row[algorithm] = j["median_seconds"] if not j["error"] else None
                row[algorithm + " MB"] = mb
                row[algorithm + " tets"] = j["tets"]
                row[algorithm + " error"] = j["error"]
                row[algorithm + " ran"] = j["algorithm"]  # the cavity sweep says when it swept the whole PLC
            times, mbs = [], []
            for _ in range(repeat):
                out, err, sec, mb = timed(["tetgen", "-pQMNEF", off])
                times.append(sec)
                mbs.append(mb)
            # tetgen -Q is quiet; rerun verbosely once to learn its Steiner points.
            verbose = subprocess.run(["tetgen", "-pMNEF", off], capture_output=True, text=True).stdout
            row["tetgen steiner"] = sum(int(n) for n in re.findall(r"Steiner points[^:\n]*:\s*(\d+)", verbose))
            row["tetgen"], row["tetgen MB"] = median(times), max(mbs)
            out, _, _, mb = timed([cgal, off, "--repeat", str(repeat)])
            row["cgal"], row["cgal MB"] = json.loads(out)["median_seconds"], mb
            rows.append(row)
            print(json.dumps(row), file=sys.stderr, flush=True)

def fmt(x, digits=3):
    return "fail" if x is None else f"{x:.{digits}f}"

def ratio(a, b, digits):
    return "—" if a is None else f"{a / b:.{digits}f}"

others = algorithms[1:]
print("| surface | triangles | " + " | ".join(f"{a} s" for a in algorithms) + " | tetgen -pQM s | CGAL Delaunay s | "
      f"{default}/tetgen | {default}/CGAL | " + " | ".join(f"{a}/tetgen" for a in others) +
      f" | MB {default} / tetgen | tets / tetgen Steiner |")
print("|---" * (2 + len(algorithms) + 2 + 2 + len(others) + 2) + "|")
for r in rows:
    d = r[default]
    errors = [r[a + " error"] for a in algorithms if r[a + " error"]]
    note = f" ({errors[0][:60]})" if errors else ""
    if r[default + " ran"] != default and d is not None:
        note += f" ({default} swept whole: {r[default + ' ran']})"
    print(f"| {r['surface']} | {r['triangles']} | " + " | ".join(fmt(r[a]) for a in algorithms) +
          f" | {fmt(r['tetgen'])} | {fmt(r['cgal'])} | {ratio(d, r['tetgen'], 2)} | {ratio(d, r['cgal'], 1)} | " +
          " | ".join(ratio(r[a], r["tetgen"], 2) for a in others) +
          f" | {r[default + ' MB']:.0f} / {r['tetgen MB']:.0f} | {r[default + ' tets']} / {r['tetgen steiner']}{note} |")
print()
for a in algorithms:
    for surface in dict.fromkeys(r["surface"] for r in rows):
        pts = [(r["triangles"], r[a]) for r in rows if r["surface"] == surface and r[a]]
        if len(pts) >= 2:
            (n0, t0), (n1, t1) = pts[0], pts[-1]
            print(f"- {surface}: time ~ n^{math.log(t1 / t0) / math.log(n1 / n0):.2f} from {n0} to {n1} triangles ({a})")
    mem = [(r["triangles"], r[a + " MB"]) for r in rows if r["surface"] == "icosphere" and r[a]]
    if len(mem) >= 2:
        (n0, m0), (n1, m1) = mem[0], mem[-1]
        print(f"- icosphere: peak memory ~ n^{math.log(m1 / m0) / math.log(n1 / n0):.2f} from {n0} to {n1} triangles ({a})")
# Exactly cospherical against the jittered sphere of the same level (triangle counts differ a little:
# the cospherical sphere has every integer point of its sphere, surfaces.h), per triangle.
for r in rows:
    if r["surface"] != "cospherical":
        continue
    for j in rows:
        if j["surface"] == "icosphere" and j["size"] == r["size"]:
            for a in algorithms:
                if r[a] and j[a]:
                    ratio = (r[a] / r["triangles"]) / (j[a] / j["triangles"])
                    print(f"- cospherical ({r['triangles']} triangles) / icosphere ({j['triangles']}), per triangle: {ratio:.2f}x ({a})")
