#!/usr/bin/env python3
"""Colours in mesh exports (`make cli`): a model's color() calls reach the
3MF, PLY and OBJ files rayscad writes (openscad 2021.01 writes none).

  colors_test.py BUILD

The files are read here by hand (the 3MF's XML from its zip, PLY's binary
records, OBJ with its material file), not by the libraries that wrote them,
and every triangle is checked against the model: away from the edges where
two colours meet, a triangle on the red cube is red, one on the half-clear
blue sphere is blue with alpha 128, one on the cavity a lime sphere cuts
into a plain cube is lime, and the rest of that cube has openscad's default
colour (#f9d72c).
"""
import math
import os
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile

MODEL = """
color("red") cube(10);
color([0, 0, 1, 0.5]) translate([25, 5, 5]) sphere(5, $fn = 48);
difference() {
    translate([0, 25, 0]) cube(10);
    color("lime") translate([5, 30, 10]) sphere(4, $fn = 48);
}
"""
H = 0.25  # --mesh-size
RED, BLUE, LIME, DEFAULT = (255, 0, 0, 255), (0, 0, 255, 128), (0, 255, 0, 255), (249, 215, 44, 255)


def expected(c):
    """The colour the model gives the surface at centroid c, or None near
    an edge where two colours meet (within 2 cells)."""
    x, y, z = c
    if y < 15 and x < 15:
        return RED
    if x > 15:
        return BLUE
    d = math.dist(c, (5, 30, 10))
    if abs(d - 4) < 0.3 and z < 10 - 2 * H:
        return LIME
    if d > 4 + 2 * H:
        return DEFAULT
    return None


def centroid(v, f):
    return tuple(sum(v[i][k] for i in f) / 3 for k in range(3))


def read_3mf(path):
    ns = {"c": "http://schemas.microsoft.com/3dmanufacturing/core/2015/02",
          "m": "http://schemas.microsoft.com/3dmanufacturing/material/2015/02"}
    root = ET.fromstring(zipfile.ZipFile(path).read("3D/3dmodel.model"))
    groups = {}
    for g in root.iter("{%s}colorgroup" % ns["m"]):
        cols = []
        for col in g.findall("m:color", ns):
            h = col.get("color").lstrip("#")
            h += "FF" if len(h) == 6 else ""
            cols.append(tuple(int(h[k:k + 2], 16) for k in (0, 2, 4, 6)))
        groups[g.get("id")] = cols
    obj = root.find(".//c:object", ns)
    v = [tuple(float(e.get(k)) for k in "xyz") for e in obj.iter("{%s}vertex" % ns["c"])]
    tris = []
    for e in obj.iter("{%s}triangle" % ns["c"]):
        pid = e.get("pid", obj.get("pid"))
        idx = e.get("p1", obj.get("pindex"))
        col = groups[pid][int(idx)] if pid is not None else None
        tris.append(((int(e.get("v1")), int(e.get("v2")), int(e.get("v3"))), col))
    return v, tris


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:end].decode().split("\n")
    assert "format binary_little_endian 1.0" in head, head[:3]
    nv = int(next(l for l in head if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in head if l.startswith("element face")).split()[2])
    face_props = head[head.index(next(l for l in head if l.startswith("element face"))) + 1:]
    assert face_props[:5] == ["property list uchar int vertex_indices", "property uchar red",
                              "property uchar green", "property uchar blue",
                              "property uchar alpha"], face_props
    at = end
    v = [struct.unpack_from("<3f", data, at + 12 * i) for i in range(nv)]
    at += 12 * nv
    tris = []
    for _ in range(nf):
        n, a, b, c, r, g, bl, al = struct.unpack_from("<B3i4B", data, at)
        assert n == 3
        tris.append(((a, b, c), (r, g, bl, al)))
        at += 17
    assert at == len(data)
    return v, tris


def read_obj(path):
    mats, cur = {}, None
    folder = os.path.dirname(path)
    v, tris, lib = [], [], None
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "mtllib":
            lib = w[1]
        elif w[0] == "v":
            v.append(tuple(map(float, w[1:4])))
        elif w[0] == "usemtl":
            cur = w[1]
        elif w[0] == "f":
            tris.append((tuple(int(x.split("/")[0]) - 1 for x in w[1:4]), cur))
    assert lib == os.path.basename(path)[:-4] + ".mtl", lib
    name = None
    for line in open(os.path.join(folder, lib)):
        w = line.split()
        if w and w[0] == "newmtl":
            name = w[1]
            mats[name] = [0, 0, 0, 1.0]
        elif w and w[0] == "Kd":
            mats[name][:3] = [float(x) for x in w[1:4]]
        elif w and w[0] == "d":
            mats[name][3] = float(w[1])
    rgba = {k: tuple(int(round(x * 255)) for x in m) for k, m in mats.items()}
    return v, [(f, rgba[m]) for f, m in tris]


def check(name, v, tris):
    wrong, counted, seen = 0, 0, {}
    for f, col in tris:
        want = expected(centroid(v, f))
        if want is None:
            continue
        counted += 1
        seen[want] = seen.get(want, 0) + 1
        if col != want:
            wrong += 1
            if wrong <= 3:
                print("  %s: triangle at %s is %s, not %s" % (name, centroid(v, f), col, want))
    ok = wrong == 0 and counted > 0.9 * len(tris) and len(seen) == 4
    print("%s %s: %d triangles, %d checked, %d wrong, colours seen %s"
          % ("ok  " if ok else "FAIL", name, len(tris), counted, wrong, sorted(seen.values())))
    return ok


def main():
    rayscad = os.path.abspath(os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "rayscad"))
    with tempfile.TemporaryDirectory() as tmp:
        scad = os.path.join(tmp, "colors.scad")
        open(scad, "w").write(MODEL)
        outs = [os.path.join(tmp, "m." + e) for e in ("3mf", "ply", "obj")]
        args = [rayscad, scad, "-q", "--mesh-size", str(H)]
        for o in outs:
            args += ["-o", o]
        subprocess.run(args, check=True)
        results = [check("3mf", *read_3mf(outs[0])), check("ply", *read_ply(outs[1])),
                   check("obj", *read_obj(outs[2]))]
        # OBJ on the standard output: no material file can go with it, which
        # rayscad says (unless -q) and writes the OBJ without colours
        to_stdout = [rayscad, scad, "--mesh-size", str(H), "-o", "-", "--export-format", "obj"]
        loud = subprocess.run(to_stdout, capture_output=True, text=True)
        quiet = subprocess.run(to_stdout + ["-q"], capture_output=True, text=True)
        said = (loud.returncode == 0 and "colours not written" in loud.stderr
                and "mtllib" not in loud.stdout and loud.stdout.count("\nf ") > 1000
                and "colours not written" not in quiet.stderr)
        print("%s OBJ to stdout: said, no mtllib" % ("ok  " if said else "FAIL"))
        results.append(said)
        # without colours in the model, the files are as before: no colour at all
        open(scad, "w").write("cube(10);")
        subprocess.run([rayscad, scad, "-q", "--mesh-size", "1", "-o", outs[0], "-o", outs[2]],
                       check=True)
        plain = (b"colorgroup" not in zipfile.ZipFile(outs[0]).read("3D/3dmodel.model")
                 and "mtllib" not in open(outs[2]).read())
        print("%s no color(): no colours written" % ("ok  " if plain else "FAIL"))
        results.append(plain)
    print("colors: %d passed, %d failed" % (results.count(True), results.count(False)))
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
