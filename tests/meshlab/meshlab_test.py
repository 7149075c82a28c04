#!/usr/bin/python3
"""Issue 15: Debian's MeshLab 2020.09 with the sweepcdt filter, run for real.

Each test sets up a private MeshLab tree (copies of /usr/bin/meshlabserver and /usr/bin/meshlab, whose
RUNPATH and plugin folder follow the binary: ../shared/HOSTS.md 2.4) holding Debian's
libmeshlab-common.so and io plugin and the plugin under test, and runs it under xvfb-run.

  convert  INPUT  : meshlabserver reads INPUT with MeshLab's importer, runs the filter, saves the
                    layer it read (binary PLY: the exact floats) and the cut-away layer; the volume
                    file must pass `sweepcdt check` against the saved layer (and against INPUT when
                    INPUT holds floats exactly: binary STL); the cut-away layer must have the face
                    count recomputed here from the volume file.
  bad INPUT KIND  : meshlabserver must fail cleanly (exit status of exit(-1), the message in its
                    log, no volume file); filter_host (a minimal MeshLab host) must see the faces
                    selected, compared with an expectation computed here or by MeshLab itself.
  gui             : MeshLab's GUI starts with the plugin, the filter is in its menu, and a
                    screenshot of the cut-away layer is saved (see gui_test in this file).

Exit status 0 = pass, 1 = fail, 77 = skipped (a prerequisite is missing; ctest SKIP_RETURN_CODE).
"""
import argparse
import os
import shutil
import struct
import subprocess
import sys
import tempfile

MESHLAB_LIB = "/usr/lib/x86_64-linux-gnu/meshlab"
SKIP = 77
HANG_GUARD = int(os.environ.get("SWEEPCDT_HANG_GUARD", "300"))  # seconds: only against a hang; a normal run takes a few seconds


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def skip(message):
    print("SKIPPED: " + message)
    sys.exit(SKIP)


# --- the private MeshLab tree ------------------------------------------------------------------

def meshlab_tree(tmp, plugin, extra_plugins=()):
    for tool in ("/usr/bin/meshlabserver", "/usr/bin/meshlab", "/usr/bin/xvfb-run", MESHLAB_LIB + "/libmeshlab-common.so"):
        if not os.path.exists(tool):
            skip(tool + " not found (scripts/setup.sh installs meshlab, xvfb, xauth)")
    bin_dir = os.path.join(tmp, "bin")
    lib_dir = os.path.join(tmp, "lib", "x86_64-linux-gnu", "meshlab")
    plugins = os.path.join(lib_dir, "plugins")
    os.makedirs(bin_dir)
    os.makedirs(plugins)
    for tool in ("meshlabserver", "meshlab"):
        shutil.copy("/usr/bin/" + tool, bin_dir)  # a copy, not a link: MeshLab finds its plugins beside its real path
    os.symlink(MESHLAB_LIB + "/libmeshlab-common.so", os.path.join(lib_dir, "libmeshlab-common.so"))
    for name in ("libio_base.so",) + tuple(extra_plugins):
        os.symlink(os.path.join(MESHLAB_LIB, "plugins", name), os.path.join(plugins, name))
    os.symlink(os.path.abspath(plugin), os.path.join(plugins, "libfilter_sweepcdt.so"))
    return bin_dir


def environment(tmp):
    env = dict(os.environ)
    runtime = os.path.join(tmp, "xdg-runtime")
    os.makedirs(runtime, mode=0o700, exist_ok=True)
    env["XDG_RUNTIME_DIR"] = runtime
    env["HOME"] = tmp  # MeshLab's settings stay in the test's folder
    return env


def xvfb(tmp, command, log_name):
    """Runs `command` under xvfb-run; returns (exit status, stdout+stderr text)."""
    # -a picks a free display from -n on; a start of our own keeps this away from other projects'
    # xvfb-run -a, which all start at 99 (two may pick one number at once; ctest's RESOURCE_LOCK
    # serialises ours).
    start = 200 + os.getpid() % 5000
    full = ["xvfb-run", "-a", "-n", str(start), "-s", "-screen 0 1280x1024x24"] + command
    try:
        p = subprocess.run(full, cwd=tmp, env=environment(tmp), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=HANG_GUARD)
    except subprocess.TimeoutExpired:
        raise Failure("hang guard: %s did not finish in %d s" % (command[0], HANG_GUARD))
    text = p.stdout.decode("utf-8", "replace")
    with open(os.path.join(tmp, log_name), "w") as f:
        f.write(text)
    return p.returncode, text


def filter_script(path, output, cut_position=0.5, cut_axis=0, steiner=0):
    """A filter script with every parameter: Debian's meshlabserver 2020.09 asserts (and aborts)
    when a script leaves one out (mainserver.cpp:614). Defaults as the filter's dialog shows them."""
    def enum(name, value, values):
        return ('  <Param type="RichEnum" value="%d" enum_cardinality="%d" %s name="%s" description="" tooltip=""/>\n'
                % (value, len(values), " ".join('enum_val%d="%s"' % (i, v) for i, v in enumerate(values)), name))
    with open(path, "w") as f:
        f.write('<!DOCTYPE FilterScript>\n<FilterScript>\n'
                ' <filter name="Tetrahedralize (constrained Delaunay)">\n'
                '  <Param type="RichSaveFile" value="%s" ext=".mesh" name="OutputFile" description="" tooltip=""/>\n'
                % output
                + enum("Algorithm", 0, ["cavity-sweep", "sweep-sphere", "sweep-plane", "giftwrap"])
                + enum("Steiner", steiner, ["auto", "none"])
                + enum("Facets", 1, ["triangles", "coplanar"])
                + '  <Param type="RichString" value="0" name="Snap" description="" tooltip=""/>\n'
                + '  <Param type="RichBool" value="false" name="Verify" description="" tooltip=""/>\n'
                + enum("CutAxis", cut_axis, ["x", "y", "z"])
                + '  <Param type="RichDynamicFloat" value="%r" min="0" max="1" name="CutPosition" description="" tooltip=""/>\n'
                % cut_position
                + enum("Colour", 0, ["element quality", "region"])
                + ' </filter>\n</FilterScript>\n')


# --- independent readers and expectations --------------------------------------------------------

def read_ply(path):
    """(vertices as float tuples, faces as index tuples, per-face flags or None) of a PLY file."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    fmt = header[1].split()[1]
    elements = []  # (name, count, [(type, name) or ("list", count type, item type, name)])
    for line in header:
        w = line.split()
        if w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            elements[-1][2].append(tuple(w[1:]))
    codes = {"char": "b", "uchar": "B", "int8": "b", "uint8": "B", "short": "h", "ushort": "H", "int16": "h",
             "uint16": "H", "int": "i", "uint": "I", "int32": "i", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}
    out = {}
    if fmt == "ascii":
        tokens = data[end:].split()
        pos = 0

        def take(kind):
            nonlocal pos
            pos += 1
            return float(tokens[pos - 1]) if codes[kind] in "fd" else int(tokens[pos - 1])
    else:
        check(fmt == "binary_little_endian", path + ": unexpected PLY format " + fmt)
        pos = end

        def take(kind):
            nonlocal pos
            c = "<" + codes[kind]
            v = struct.unpack_from(c, data, pos)[0]
            pos += struct.calcsize(c)
            return v
    for name, count, props in elements:
        rows = []
        for _ in range(count):
            row = {}
            for p in props:
                if p[0] == "list":
                    n = take(p[1])
                    row[p[3]] = [take(p[2]) for _ in range(n)]
                else:
                    row[p[1]] = take(p[0])
            rows.append(row)
        out[name] = rows
    vertices = [(r["x"], r["y"], r["z"]) for r in out.get("vertex", [])]
    faces = [tuple(r.get("vertex_indices", r.get("vertex_index"))) for r in out.get("face", [])]
    flags = [r["flags"] for r in out["face"]] if out.get("face") and "flags" in out["face"][0] else None
    return vertices, faces, flags


def read_medit(path):
    """(points, tetrahedra 0-based) of a Medit .mesh file."""
    with open(path) as f:
        tokens = f.read().split()
    points, tets = [], []
    i = 0
    while i < len(tokens):
        if tokens[i] == "Vertices":
            n = int(tokens[i + 1])
            i += 2
            for _ in range(n):
                points.append(tuple(float(x) for x in tokens[i:i + 3]))
                i += 4
        elif tokens[i] == "Tetrahedra":
            n = int(tokens[i + 1])
            i += 2
            for _ in range(n):
                tets.append(tuple(int(x) - 1 for x in tokens[i:i + 4]))
                i += 5
        else:
            i += 1
    return points, tets


def cut_away_face_count(points, tets, axis, fraction):
    """The triangles bounding the tetrahedra whose centroid lies at or below the cut plane (the rule
    the filter's help states), recomputed from the volume file: facets of kept tetrahedra that are
    on no other kept tetrahedron."""
    lo = min(p[axis] for p in points)
    hi = max(p[axis] for p in points)
    position = hi if fraction == 1 else lo + fraction * (hi - lo)
    facets = {}
    for t in tets:
        s = 0.0
        for v in t:
            s += points[v][axis]
        kept = fraction == 1 or s / 4 <= position
        for i in range(4):
            key = tuple(sorted(t[:i] + t[i + 1:]))
            facets.setdefault(key, []).append(kept)
    return sum(1 for uses in facets.values() for kept in uses if kept and (len(uses) == 1 or not all(uses)))


def is_binary_stl(path):
    with open(path, "rb") as f:
        head = f.read(84)
    return len(head) == 84 and os.path.getsize(path) == 84 + 50 * struct.unpack_from("<I", head, 80)[0]


def sweepcdt_check(cli, surface, volume):
    p = subprocess.run([cli, "check", surface, volume], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=HANG_GUARD)
    text = p.stdout.decode("utf-8", "replace")
    check(p.returncode == 0, "sweepcdt check %s %s failed (%d):\n%s" % (surface, volume, p.returncode, text))
    print("sweepcdt check %s: %s" % (os.path.basename(surface), text.strip().splitlines()[-1] if text.strip() else ""))


# --- the tests -------------------------------------------------------------------------------------

def convert_test(args, tmp):
    source = args.input
    if not os.path.exists(source):
        raise Failure(source + ": shared mesh not found (../shared/data)")
    bin_dir = meshlab_tree(tmp, args.plugin)
    server = os.path.join(bin_dir, "meshlabserver")
    if args.via_ply:  # MeshLab's own PLY exporter and importer in between
        converted = os.path.join(tmp, "via.ply")
        status, text = xvfb(tmp, [server, "-i", source, "-o", converted], "convert.log")
        check(status == 0 and os.path.exists(converted), "meshlabserver could not write %s (%d):\n%s" % (converted, status, text))
        source = converted
    volume = os.path.join(tmp, "volume.mesh")
    script = os.path.join(tmp, "tetrahedralize.mlx")
    filter_script(script, volume)
    seen, cut = os.path.join(tmp, "layer0.ply"), os.path.join(tmp, "cut_away.ply")
    status, text = xvfb(tmp, [server, "-l", os.path.join(tmp, "filter.log"), "-i", source, "-s", script,
                              "-o", cut, "-l", "x", "-m", "fc", "fq", "-o", seen, "-l", "0"], "meshlabserver.log")
    with open(os.path.join(tmp, "filter.log")) as f:
        log = f.read()
    check(status == 0, "meshlabserver failed (%d):\n%s\n%s" % (status, text, log))
    # meshlabserver prints each new progress text of the filter's callback: the phases, in order.
    phases = ["checking the surface", "writing", "cut-away layer", "done"]
    at = -1
    for phase in phases:
        at = text.find(phase, at + 1)
        check(at != -1, "progress phases %s not all reported in order:\n%s" % (phases, text))
    summary = [line for line in log.splitlines() if "tetrahedra," in line and "Steiner points" in line]
    check(summary, "the filter's log has no summary line:\n" + log)
    print(summary[0].strip())
    check(os.path.exists(volume), "no volume file written")

    # The layer the filter read, as MeshLab saved it (binary PLY: its floats exactly).
    vertices, faces, _ = read_ply(seen)
    check(faces, seen + ": no faces")
    sweepcdt_check(args.cli, seen, volume)
    if is_binary_stl(args.input):  # float coordinates in the file: the original must pass as well
        sweepcdt_check(args.cli, args.input, volume)

    points, tets = read_medit(volume)
    expected = cut_away_face_count(points, tets, 0, 0.5)
    _, cut_faces, _ = read_ply(cut)
    print("cut-away layer: %d faces, %d recomputed from %d tetrahedra" % (len(cut_faces), expected, len(tets)))
    check(len(cut_faces) == expected, "cut-away layer has %d faces, the volume file gives %d" % (len(cut_faces), expected))
    check(0 < expected, "empty cut-away layer")


def read_off_faces(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    check(tokens[0] == "OFF", path + ": not OFF")
    nv, nf = int(tokens[1]), int(tokens[2])
    vertices = [tuple(float(x) for x in tokens[4 + 3 * i:7 + 3 * i]) for i in range(nv)]
    faces, i = [], 4 + 3 * nv
    for _ in range(nf):
        n = int(tokens[i])
        faces.append(tuple(vertices[int(x)] for x in tokens[i + 1:i + 1 + n]))
        i += 1 + n
    return faces


def boundary_edge_faces(faces):
    """Faces (corner coordinates) with an edge no other face has: the faces at the holes."""
    uses = {}
    for f in faces:
        for i in range(len(f)):
            uses.setdefault(frozenset((f[i], f[(i + 1) % len(f)])), []).append(f)
    return sorted({i for i, f in enumerate(faces) for k in range(len(f)) if len(uses[frozenset((f[k], f[(k + 1) % len(f)]))]) == 1})


def host_selection(args, tmp, source, extra=()):
    if not os.path.exists(args.host):
        raise Failure(args.host + " not built")
    env = environment(tmp)
    env["QT_QPA_PLATFORM"] = "offscreen"  # filter_host opens no window and needs no GL
    volume = os.path.join(tmp, "host.mesh")
    p = subprocess.run([args.host, args.plugin, source, volume] + list(extra), env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       timeout=HANG_GUARD)
    text = p.stdout.decode("utf-8", "replace")
    check(p.returncode == 0, "filter_host failed (%d):\n%s" % (p.returncode, text))
    lines = dict((line.split(" ", 1) + [""])[:2] for line in text.splitlines() if not line.startswith("log "))
    check(lines.get("result") == "failed", "the filter did not fail:\n" + text)
    check(not os.path.exists(volume), "a volume file was written for bad input")
    return lines["error"], [int(x) for x in lines["selected"].split()], int(lines["faces"]), text


# Exact self-intersection test, independent of sweepcdt: rational arithmetic on the layer's floats.
# Two triangles intersect improperly when they share more than their common vertices / edge.

def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _orient3(a, b, c, d):
    u, v, w = _sub(b, a), _sub(c, a), _sub(d, a)
    det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])
    return (det > 0) - (det < 0)


def _orient2(a, b, c):
    det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (det > 0) - (det < 0)


def _drop_axis(a, b, c):
    u, v = _sub(b, a), _sub(c, a)
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    k = max(range(3), key=lambda i: abs(n[i]))
    return lambda p: tuple(p[i] for i in range(3) if i != k)


def _segments_meet2(p, q, a, b):
    o1, o2, o3, o4 = _orient2(p, q, a), _orient2(p, q, b), _orient2(a, b, p), _orient2(a, b, q)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True

    def on(x, y, z):  # z on the closed segment xy, given collinear
        return min(x[0], y[0]) <= z[0] <= max(x[0], y[0]) and min(x[1], y[1]) <= z[1] <= max(x[1], y[1])
    return (o1 == 0 and on(p, q, a)) or (o2 == 0 and on(p, q, b)) or (o3 == 0 and on(a, b, p)) or (o4 == 0 and on(a, b, q))


def _inside2(p, a, b, c):
    s = {_orient2(a, b, p), _orient2(b, c, p), _orient2(c, a, p)}
    return not (1 in s and -1 in s)


def _segment_meets_triangle(p, q, a, b, c):
    o1, o2 = _orient3(a, b, c, p), _orient3(a, b, c, q)
    if o1 == o2 != 0:
        return False
    if o1 == o2 == 0:  # in the triangle's plane
        pr = _drop_axis(a, b, c)
        P, Q, A, B, C = pr(p), pr(q), pr(a), pr(b), pr(c)
        return (_inside2(P, A, B, C) or _inside2(Q, A, B, C) or _segments_meet2(P, Q, A, B)
                or _segments_meet2(P, Q, B, C) or _segments_meet2(P, Q, C, A))
    s = {_orient3(p, q, a, b), _orient3(p, q, b, c), _orient3(p, q, c, a)}
    return not (1 in s and -1 in s)


def intersect_improperly(t1, t2):
    """t1, t2: three exact points each (distinct points, non-degenerate triangles)."""
    shared = [p for p in t1 if p in t2]
    if len(shared) == 3:
        return True  # duplicate
    if len(shared) == 2:  # meet in more than the edge only when coplanar and on one side of it
        a = next(p for p in t1 if p not in shared)
        b = next(p for p in t2 if p not in shared)
        if _orient3(shared[0], shared[1], a, b) != 0:
            return False
        pr = _drop_axis(shared[0], shared[1], a)
        return _orient2(pr(shared[0]), pr(shared[1]), pr(a)) == _orient2(pr(shared[0]), pr(shared[1]), pr(b))
    if len(shared) == 1:  # then the edge opposite the shared vertex of one meets the other
        a, b = [p for p in t1 if p != shared[0]]
        c, d = [p for p in t2 if p != shared[0]]
        return _segment_meets_triangle(a, b, *t2) or _segment_meets_triangle(c, d, *t1)
    return any(_segment_meets_triangle(t1[i], t1[(i + 1) % 3], *t2) or _segment_meets_triangle(t2[i], t2[(i + 1) % 3], *t1)
               for i in range(3))


def intersecting_pairs(vertices, faces):
    from fractions import Fraction
    tris = [tuple(tuple(Fraction(x) for x in vertices[v]) for v in f) for f in faces]
    boxes = [tuple((min(p[k] for p in t), max(p[k] for p in t)) for k in range(3)) for t in tris]
    pairs = []
    for i in range(len(tris)):
        for j in range(i + 1, len(tris)):
            if all(boxes[i][k][0] <= boxes[j][k][1] and boxes[j][k][0] <= boxes[i][k][1] for k in range(3)) \
                    and intersect_improperly(tris[i], tris[j]):
                pairs.append((i, j))
    return pairs


def two_cubes_off(path):
    """Two unit cubes sharing the edge x = y = 1 (the shared data has no non-manifold file MeshLab
    reads): that edge has four triangles."""
    vertices, faces = [], []
    for ox, oy in ((0, 0), (1, 1)):
        base = len(vertices)
        vertices += [(ox + (i & 1), oy + (i >> 1 & 1), i >> 2 & 1) for i in range(8)]
        for q in ((0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)):
            faces += [(base + q[0], base + q[1], base + q[2]), (base + q[0], base + q[2], base + q[3])]
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        f.writelines("%d %d %d\n" % v for v in vertices)
        f.writelines("3 %d %d %d\n" % t for t in faces)


def bad_test(args, tmp):
    source = args.input
    if args.kind == "nonmanifold":
        source = os.path.join(tmp, "two_cubes.off")
        two_cubes_off(source)
    if not os.path.exists(source):
        raise Failure(source + ": shared mesh not found (../shared/data/bad)")
    bin_dir = meshlab_tree(tmp, args.plugin)
    server = os.path.join(bin_dir, "meshlabserver")
    volume = os.path.join(tmp, "volume.mesh")
    script = os.path.join(tmp, "tetrahedralize.mlx")
    steiner = 1 if args.kind == "nocdt" else 0  # none: the surface as given
    filter_script(script, volume, steiner=steiner)
    status, text = xvfb(tmp, [server, "-l", os.path.join(tmp, "filter.log"), "-i", source, "-s", script], "meshlabserver.log")
    with open(os.path.join(tmp, "filter.log")) as f:
        log = f.read()
    # meshlabserver ends a failed script with exit(-1) after printing "Problem with filter"; a crash
    # would end with a signal (status 128 + n from xvfb-run's shell).
    check(status == 255 and "Problem with filter: Tetrahedralize (constrained Delaunay)" in log,
          "meshlabserver did not fail cleanly (status %d):\n%s\n%s" % (status, text, log))
    messages = [line for line in log.splitlines() if "Tetrahedralize failed" in line]
    check(messages, "no error message in meshlabserver's log:\n" + log)
    print("meshlabserver: " + messages[0].strip())
    check(not os.path.exists(volume), "a volume file was written for bad input")

    error, selected, faces, host_text = host_selection(args, tmp, source, ["Steiner=%d" % steiner])
    print("filter_host: %s; selected %s" % (error, selected))
    if args.kind == "nocdt":
        check("no CDT" in error and "witness vertices" in error, "unexpected error: " + error)
        witness = [int(x) for x in error.split("witness vertices ")[1].split(")")[0].split()]
        # The layer's exact floats (MeshLab's importer, then its PLY exporter), welded as surface.h
        # documents: equal coordinates are one vertex, numbered in order of first use by the faces.
        layer = os.path.join(tmp, "layer.ply")
        status, text = xvfb(tmp, [server, "-i", source, "-o", layer], "layer.log")
        check(status == 0, "meshlabserver could not save the layer (%d):\n%s" % (status, text))
        vertices, layer_faces, _ = read_ply(layer)
        check(len(layer_faces) == faces, "MeshLab's layer has %d faces, filter_host's %d" % (len(layer_faces), faces))
        welded = {}
        for f in layer_faces:
            for v in f:
                welded.setdefault(vertices[v], len(welded))
        expected = [i for i, f in enumerate(layer_faces) if any(welded[vertices[v]] in witness for v in f)]
        check(len(witness) == 4 and expected, "witness %s selects nothing here" % witness)
        check(selected == expected, "selected faces %s, expected %s" % (selected, expected))
        return
    check("does not bound a volume" in error and "faces selected" in error, "unexpected error: " + error)
    if args.kind == "nonmanifold":
        faces_xyz = read_off_faces(source)
        uses = {}
        for i, f in enumerate(faces_xyz):
            for k in range(3):
                uses.setdefault(frozenset((f[k], f[(k + 1) % 3])), []).append(i)
        edge = [e for e, fs in uses.items() if len(fs) > 2]
        check(len(edge) == 1 and len(uses[edge[0]]) == 4, "the test's own two cubes: %s" % edge)
        at_edge = sorted(uses[edge[0]])
        at_ends = sorted(i for i, f in enumerate(faces_xyz) if any(p in edge[0] for p in f))
        check("1 non-manifold edges" in error, "the message does not name the non-manifold edge: " + error)
        # Every face at the edge, and (pinched ends, if reported) faces at its two vertices only.
        check(set(at_edge) <= set(selected) <= set(at_ends), "selected %s: not between %s and %s" % (selected, at_edge, at_ends))
        return
    if args.kind == "open":
        expected = boundary_edge_faces(read_off_faces(source))
        check(faces == len(read_off_faces(source)), "filter_host read %d faces" % faces)
        check("boundary edge" in error, "the message does not say the surface is open: " + error)
    else:
        check("%d self-intersecting triangle pairs" % args.pairs in error,
              "the message does not count the %d intersecting pairs of MANIFEST.md: %s" % (args.pairs, error))
        # The layer's exact floats, as MeshLab's importer made them and its PLY exporter wrote them.
        layer = os.path.join(tmp, "layer.ply")
        status, text = xvfb(tmp, [server, "-i", source, "-o", layer], "layer.log")
        check(status == 0, "meshlabserver could not save the layer (%d):\n%s" % (status, text))
        vertices, layer_faces, _ = read_ply(layer)
        check(len(layer_faces) == faces, "MeshLab's layer has %d faces, filter_host's %d" % (len(layer_faces), faces))
        pairs = intersecting_pairs(vertices, layer_faces)
        check(len(pairs) == args.pairs, "exact test here: %d intersecting pairs, MANIFEST.md: %d" % (len(pairs), args.pairs))
        expected = sorted({t for pair in pairs for t in pair})
        print("exact test here: %d pairs, faces %s" % (len(pairs), expected))
    check(selected == expected, "selected faces %s, expected %s" % (selected, expected))


def gui_test(args, tmp):
    """MeshLab's GUI with the filter and the test probe (gui_probe.cpp), which runs the filter from
    its menu with the dialog's defaults as a user would: the filter must be in Filters > Remeshing,
    Simplification and Reconstruction, write INPUT's volume mesh beside it (checked exactly), and add
    the cut-away layer, whose screenshot must show the cut's quality colours."""
    if not os.path.exists(args.input):
        raise Failure(args.input + ": shared mesh not found (../shared/data)")
    check(is_binary_stl(args.input), "the GUI test needs a binary STL (floats: checked against the file itself)")
    check(args.probe and os.path.exists(args.probe), "the GUI probe plugin is not built")
    bin_dir = meshlab_tree(tmp, args.plugin)
    os.symlink(os.path.abspath(args.probe), os.path.join(tmp, "lib", "x86_64-linux-gnu", "meshlab", "plugins", "libfilter_sweepcdt_gui_probe.so"))
    source = os.path.join(tmp, os.path.basename(args.input))  # the default output goes beside the layer's file
    shutil.copy(args.input, source)
    stem = os.path.splitext(os.path.basename(source))[0]
    os.environ.update({"SWEEPCDT_PROBE_DIR": tmp, "SWEEPCDT_PROBE_LAYER": os.path.basename(source)})
    status, text = xvfb(tmp, [os.path.join(bin_dir, "meshlab"), source], "meshlab.log")
    probe = os.path.join(tmp, "probe.txt")
    check(os.path.exists(probe), "the probe wrote nothing (MeshLab status %d):\n%s" % (status, text))
    with open(probe) as f:
        report = f.read()
    print(report.strip())
    check(status == 0, "MeshLab ended with status %d:\n%s" % (status, text))
    lines = dict((line.split(" ", 1) + [""])[:2] for line in report.splitlines())
    check(lines.get("menu") == "Filters/Remeshing, Simplification and Reconstruction/Tetrahedralize (constrained Delaunay)",
          "the filter is not in Filters > Remeshing, Simplification and Reconstruction")
    volume = os.path.join(tmp, stem + ".mesh")
    check(os.path.exists(volume), "the GUI run wrote no " + volume)
    sweepcdt_check(args.cli, args.input, volume)
    check(lines.get("screenshot", "").endswith("saved"), "no screenshot saved")
    warm = lines.get("warm", "0 of 1 pixels").split()
    check(int(warm[0]) * 20 > int(warm[2]), "under 5% of the view in the cut's quality colours (red to yellow)")
    if args.screenshot:
        shutil.copy(os.path.join(tmp, "screenshot.png"), args.screenshot)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("test", choices=["convert", "bad", "gui"])
    ap.add_argument("--probe")
    ap.add_argument("--screenshot", help="copy the GUI screenshot here")
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--cli", required=True)
    ap.add_argument("--host")
    ap.add_argument("--input", default="")
    ap.add_argument("--via-ply", action="store_true")
    ap.add_argument("--kind", choices=["open", "selfintersecting", "nocdt", "nonmanifold"])
    ap.add_argument("--pairs", type=int, default=0)
    args = ap.parse_args()
    if not os.path.exists(args.plugin):
        print("FAILED: %s not built" % args.plugin)
        return 1
    tmp = tempfile.mkdtemp(prefix="sweepcdt-meshlab-")
    try:
        {"convert": convert_test, "bad": bad_test, "gui": gui_test}[args.test](args, tmp)
    except Failure as e:
        print("FAILED: %s\n(files kept in %s)" % (e, tmp))
        return 1
    shutil.rmtree(tmp, ignore_errors=True)
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
