#!/usr/bin/env python3
"""Meshes of random plane-faced CSG against openscad 2021.01's.

The scenes of tests/cli/measure_openscad.py (the same seed: unions,
differences and intersections of turned boxes and of spheres, cylinders and
cones faceted by $fn), meshed with --facets=openscad: every curve then a
facet, every primitive plane-faced, so the mesh is the exact boundary of the
booleans (src/mesh/polyhedral.c) wherever that comes out closed, else the
contour.  Each mesh must be closed (every edge once each way, vertices
welded by position) with its volume within 0.5 % of openscad's CGAL mesh;
and the exact path must carry nine scenes in ten: their volumes within 2e-5
of openscad's (the ASCII STLs' digits), where a contour is off by a
thousandth.  openscad's STLs are measure_openscad.py's (BUILD/
measure_openscad/), made there when missing.

usage: tests/cli/mesh_exact_openscad.py [BUILD] [--count N]
"""
import argparse
import importlib.util
import os
import subprocess
import sys
from collections import Counter

EXACT = 2e-5
LOOSE = 5e-3


def load_measure():
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "measure_openscad.py")
    spec = importlib.util.spec_from_file_location("measure_openscad", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def stl_triangles(path):
    tris, tri = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "vertex":
                tri.append(tuple(float(x) for x in w[1:4]))
                if len(tri) == 3:
                    tris.append(tri)
                    tri = []
    return tris


def closed(tris):
    """Every directed edge once and its reverse once, vertices by position."""
    e = Counter()
    for t in tris:
        for k in range(3):
            if t[k] == t[(k + 1) % 3]:
                return False
            e[(t[k], t[(k + 1) % 3])] += 1
    return all(c == 1 and e.get((b, a), 0) == 1 for (a, b), c in e.items())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build", nargs="?", default="build")
    ap.add_argument("--count", type=int, default=40)
    a = ap.parse_args()
    m = load_measure()
    ref_dir = os.path.join(a.build, "measure_openscad")
    out = os.path.join(a.build, "mesh_exact_openscad")
    os.makedirs(ref_dir, exist_ok=True)
    os.makedirs(out, exist_ok=True)
    rng = m.random.Random(7)
    failed = exact = solids = 0
    for i in range(a.count):
        name = "m%03d" % i
        scad, stl = m.openscad_stl(ref_dir, name, m.scene(rng))
        ref = m.stl_measure(stl)[0] if os.path.exists(stl) else 0.0
        ours = os.path.join(out, name + ".stl")
        if os.path.exists(ours):
            os.remove(ours)
        p = subprocess.run([os.path.join(a.build, "rayscad"), scad, "--facets=openscad", "-o", ours],
                           capture_output=True, text=True, timeout=300)
        if ref <= 0:
            ok = p.returncode != 0 or not os.path.exists(ours)
            print("%s %s: openscad empty, ours %s" % ("ok  " if ok else "FAIL", name,
                                                      "empty" if ok else "not"))
            failed += not ok
            continue
        solids += 1
        if p.returncode != 0 or not os.path.exists(ours):
            print("FAIL %s: rayscad said %s" % (name, p.stderr.strip()))
            failed += 1
            continue
        tris = stl_triangles(ours)
        vol = m.stl_measure(ours)[0]
        dv = abs(vol - ref) / ref
        is_closed = closed(tris)
        ok = is_closed and dv <= LOOSE
        exact += ok and dv <= EXACT
        print("%s %s: %d triangles, %s, volume %.9g (openscad %.9g, %.1e off)%s" % (
            "ok  " if ok else "FAIL", name, len(tris), "closed" if is_closed else "OPEN", vol, ref,
            dv, ", exact" if dv <= EXACT else ""))
        failed += not ok
    enough = exact * 10 >= 9 * solids
    print("mesh_exact_openscad: %d of %d solids exact (%s), %d failed" % (
        exact, solids, "enough" if enough else "FEWER THAN 9 IN 10", failed))
    return 1 if failed or not enough else 0


if __name__ == "__main__":
    sys.exit(main())
