#!/usr/bin/env python3
"""--measure against openscad 2021.01 on random faceted CSG.

Random unions, differences and intersections of turned boxes, spheres,
cylinders and cones, every curve faceted ($fn), so that openscad's CGAL mesh
is the same solid as rayscad's: its volume and area (summed from the STL it
writes, to the float precision of the file) are the truth that the exact
measurement (rays, no grid) must meet to 2e-5, and to 1e-6 in volume and
1e-5 in area where the STL's digits tell no better (a sliver of 1.3e-4).
The scenes come from a fixed seed; openscad's STLs stay in
BUILD/measure_openscad/.  Where openscad's result is empty, so must ours
be.

usage: tests/cli/measure_openscad.py [BUILD] [--count N]
"""
import argparse
import json
import os
import random
import subprocess
import sys

TOL = 2e-5
VOLUME_FLOOR = 1e-6
AREA_FLOOR = 1e-5


def prim(rng):
    t = ",".join("%.2f" % rng.uniform(-3, 3) for _ in range(3))
    r = ",".join("%.2f" % rng.uniform(0, 90) for _ in range(3))
    kind = rng.choice(["cube", "sphere", "cylinder", "cone"])
    if kind == "cube":
        s = "cube([%.2f,%.2f,%.2f], center=true)" % tuple(rng.uniform(1, 5) for _ in range(3))
    elif kind == "sphere":
        s = "sphere(%.2f, $fn=%d)" % (rng.uniform(1, 3.5), rng.choice([6, 8, 10, 16]))
    elif kind == "cylinder":
        s = "cylinder(r=%.2f, h=%.2f, center=true, $fn=%d)" % (
            rng.uniform(0.5, 2.5), rng.uniform(1, 6), rng.choice([5, 7, 8, 12, 13]))
    else:
        s = "cylinder(r1=%.2f, r2=%.2f, h=%.2f, center=true, $fn=%d)" % (
            rng.uniform(0.5, 3), rng.uniform(0, 3), rng.uniform(1, 6), rng.choice([5, 8, 13]))
    return "translate([%s]) rotate([%s]) %s;" % (t, r, s)


def scene(rng):
    op = rng.choice(["union", "difference", "intersection", "difference"])
    body = "\n".join("    " + prim(rng) for _ in range(rng.choice([2, 3, 4])))
    return "%s() {\n%s\n}\n" % (op, body)


def stl_measure(path):
    """Volume and area of an ASCII STL."""
    vol = area = 0.0
    tri = []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "vertex":
                tri.append([float(x) for x in w[1:4]])
                if len(tri) == 3:
                    a, b, c = tri
                    u = [b[i] - a[i] for i in range(3)]
                    v = [c[i] - a[i] for i in range(3)]
                    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]]
                    vol += (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6
                    area += 0.5 * (n[0] ** 2 + n[1] ** 2 + n[2] ** 2) ** 0.5
                    tri = []
    return vol, area


def openscad_stl(out, name, src):
    """Scene src as out/name.scad and openscad's STL of it, out/name.stl
    (kept while the scene is unchanged; absent where openscad writes
    none): their paths."""
    scad = os.path.join(out, name + ".scad")
    stl = os.path.join(out, name + ".stl")
    old = open(scad).read() if os.path.exists(scad) else None
    if old != src or not os.path.exists(stl):
        with open(scad, "w") as f:
            f.write(src)
        if os.path.exists(stl):
            os.remove(stl)
        subprocess.run(["openscad", "-o", stl, scad], capture_output=True, timeout=300)
    return scad, stl


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build", nargs="?", default="build")
    ap.add_argument("--count", type=int, default=40)
    a = ap.parse_args()
    out = os.path.join(a.build, "measure_openscad")
    os.makedirs(out, exist_ok=True)
    rng = random.Random(7)
    passed = failed = 0
    for i in range(a.count):
        name = "m%03d" % i
        scad, stl = openscad_stl(out, name, scene(rng))
        ref = stl_measure(stl) if os.path.exists(stl) else (0.0, 0.0)
        p = subprocess.run([os.path.join(a.build, "rayscad"), scad, "--measure", "--json"],
                           capture_output=True, text=True, timeout=300)
        try:
            m = json.loads(p.stdout)
        except ValueError:
            print("FAIL %s: rayscad said %s" % (name, p.stderr.strip()))
            failed += 1
            continue
        dv = abs(m["volume"] - ref[0])
        da = abs(m["area"] - ref[1])
        ok = (m.get("method") == "exact" and dv <= TOL * ref[0] + VOLUME_FLOOR
              and da <= TOL * ref[1] + AREA_FLOOR)
        dv /= max(ref[0], VOLUME_FLOOR)
        da /= max(ref[1], AREA_FLOOR)
        print("%s %s: volume %.9g (openscad %.9g, %.1e off), area %.9g (%.9g, %.1e off), "
              "%s, %s rays" % ("ok  " if ok else "FAIL", name, m["volume"], ref[0], dv,
                               m["area"], ref[1], da, m.get("method"), m.get("rays")))
        passed += ok
        failed += not ok
    print("measure_openscad: %d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
