#!/usr/bin/env python3
"""Whether two .mesh files hold the same mesh up to the order of its elements: the same vertices in
the same order (coordinates and references, as written), and the same triangles and tetrahedra, each
with its reference, as sets of vertex sets. For changes that may reorder the elements an algorithm
emits but must not change the triangulation (bench/compare_outputs.sh --as-sets).

usage: bench/same_mesh_sets.py BEFORE.mesh AFTER.mesh   (exit 0: same; 1: different, says how)"""
import sys

ROW = {"Vertices": 4, "Triangles": 4, "Tetrahedra": 5}


def sections(path):
    tokens = open(path).read().split()
    out, i = {}, 0
    while i < len(tokens):
        if tokens[i] in ROW:
            width, n = ROW[tokens[i]], int(tokens[i + 1])
            out[tokens[i]] = [tuple(tokens[i + 2 + j * width:i + 2 + (j + 1) * width]) for j in range(n)]
            i += 2 + n * width
        else:
            i += 1
    return out


def main():
    before, after = sections(sys.argv[1]), sections(sys.argv[2])
    same = True
    if before.get("Vertices") != after.get("Vertices"):
        print("vertices differ")
        same = False
    for kind in ("Triangles", "Tetrahedra"):
        as_set = lambda rows: sorted((tuple(sorted(r[:-1])), r[-1]) for r in rows)
        if as_set(before.get(kind, [])) != as_set(after.get(kind, [])):
            print(kind.lower() + " differ")
            same = False
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
