#!/usr/bin/env python3
"""make bench: rayscad against its peers, side by side in one run.

Rendering: rayscad and POV-Ray (rendering rayscad's own .pov export of the
same scene) at the same size, no antialiasing on either side, the same thread
count, run alternately REPS times; medians of the whole process (wall clock)
and of the render alone (rayscad's RAYSCAD_STATS line, POV-Ray's "Trace
Time").  Meshing: rayscad -o x.stl against openscad -o x.stl (CGAL) and
manifold-3d (bench/manifold_mesh.mjs), alternately, with each one's volume
error against the exact value.  Scaling: rayscad's render time over unions
of 10 … 10,000 primitives.  Evaluation (bench/eval_bench.py): CPU time of
rayscad and openscad on BOSL2's whole test pass, on its 10 heaviest scripts
(ratios rayscad / openscad: lower is better) and at start-up.

Nothing here is a test: it prints medians and ratios and writes
bench/results/<date>.json.  Usage:
    bench/run.py BUILD_DIR [--reps N] [--quick] [--out FILE]
"""
import argparse
import datetime
import json
import math
import os
import platform
import re
import shutil
import statistics
import struct
import subprocess
import sys
import time

import eval_bench
import viewer_bench

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
EXAMPLES = "/usr/share/openscad/examples"

# (name, path relative to bench/scenes or absolute, rayscad args)
RENDER_SCENES = [
    ("few", "few.scad"),
    ("csg_deep", "csg_deep.scad"),
    ("glass", "glass.scad"),
    ("example001", f"{EXAMPLES}/Old/example001.scad"),
    ("example005", f"{EXAMPLES}/Old/example005.scad"),
    ("CSG", f"{EXAMPLES}/Basics/CSG.scad"),
    ("logo", f"{EXAMPLES}/Basics/logo.scad"),
    ("module_recursion", f"{EXAMPLES}/Advanced/module_recursion.scad"),
]
UNION_SIZES = [10, 100, 1000, 10000]

# Meshing scenes: exact volumes (see the .scad files).
MESH_SCENES = [
    ("cube_holes", "mesh_cube_holes.scad", 2404.778358),
    ("spheres", "mesh_spheres.scad", 7068.583471),
]
MESH_SIZES = [0.25, 0.125]  # rayscad --mesh-size, model units (the scenes are 20–30 wide)
OPENSCAD_FN = 64
# A second CGAL run whose tessellation error is about rayscad's at --mesh-size
# 0.25 (cube_holes: $fn = 192 gives +0.050 %, rayscad +0.031 %), so the mesh
# ratio is also stated at equal or better accuracy; one rep (it takes ~40 s).
OPENSCAD_FN_FINE = 192
MANIFOLD_SEGMENTS = [64, 128]
# rayscad --mesh-size 0.25 simplified to these --mesh-tolerance distances
# (issue 22: as few triangles as manifold-3d at 128 segments, at no larger
# deviation from the exact surface; the mesh lies within D, measured by
# tests/tools/meshdev: 0.93-0.94 D on both scenes at 0.008, against
# manifold-3d's 0.0089 and 0.0081).
MESH_TOLERANCES = [0.008]


def surface_deviation(scene, tris):
    """The largest distance of points of the triangles (corners, centroid,
    edge midpoints and four more) from the scene's exact surfaces, each taken
    whole (a sphere, an infinite cylinder or plane), the nearest of them."""
    if scene == "cube_holes":
        def dist(p):
            x, y, z = p
            return min(abs(math.sqrt(x * x + y * y + z * z) - 11), abs(math.hypot(y, z) - 6.5),
                       abs(math.hypot(x, z) - 6.5), abs(math.hypot(x, y) - 6.5),
                       abs(max(abs(x), abs(y), abs(z)) - 10))
    else:  # spheres: r = 10 at the origin and at x = 10
        def dist(p):
            x, y, z = p
            return min(abs(math.sqrt(x * x + y * y + z * z) - 10),
                       abs(math.sqrt((x - 10) ** 2 + y * y + z * z) - 10))
    worst = 0.0
    for a, b, c in tris:
        for u, w in ((0, 0), (1, 0), (0, 1), (1 / 3, 1 / 3), (0.5, 0), (0, 0.5), (0.5, 0.5),
                     (0.25, 0.25), (0.5, 0.25), (0.25, 0.5)):
            worst = max(worst, dist([a[k] + u * (b[k] - a[k]) + w * (c[k] - a[k])
                                     for k in range(3)]))
    return worst


def run(cmd, env=None, timeout=300):
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
    return time.perf_counter() - t0, p


def med(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def gmean(xs):
    xs = [x for x in xs if x]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else None


def stl_triangles(path):
    """The triangles of a binary or ASCII STL."""
    data = open(path, "rb").read()
    tris = []
    if len(data) >= 84 and 84 + 50 * struct.unpack_from("<I", data, 80)[0] == len(data):
        n = struct.unpack_from("<I", data, 80)[0]
        for i in range(n):
            f = struct.unpack_from("<12f", data, 84 + 50 * i)
            tris.append((f[3:6], f[6:9], f[9:12]))
    else:
        v = [tuple(map(float, m.groups())) for m in re.finditer(
            rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)]
        tris = [(v[i], v[i + 1], v[i + 2]) for i in range(0, len(v) - 2, 3)]
    return tris


def stl_volume(path):
    """Signed volume of a binary or ASCII STL (divergence theorem)."""
    tris = stl_triangles(path)
    vol = 0.0
    for a, b, c in tris:
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0]))
    return vol / 6.0, len(tris)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="fewer scenes, 1 rep (a smoke run)")
    ap.add_argument("--size", default="640,480")
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--out")
    a = ap.parse_args()
    reps = 1 if a.quick else a.reps
    W, H = map(int, a.size.split(","))
    rayscad = os.path.join(ROOT, a.build, "rayscad")
    maskcmp = os.path.join(ROOT, a.build, "tools", "maskcmp")
    work = os.path.join(ROOT, a.build, "bench")
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, RAYSCAD_STATS="1")
    have = {t: shutil.which(t) is not None for t in ("povray", "openscad", "node")}
    result = {
        "date": datetime.datetime.now().isoformat(timespec="seconds"),
        "machine": f"{platform.machine()}, {os.cpu_count()} cores, shared with other work",
        "git": subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True).stdout.strip(),
        "settings": {"size": [W, H], "threads": a.threads, "reps": reps,
                     "antialiasing": "none on either side (rayscad --samples 1, povray -A)"},
        "versions": {},
        "render": [], "scaling": [], "mesh": [], "summary": {},
    }
    for tool, cmd in (("povray", ["povray", "--version"]), ("openscad", ["openscad", "--version"]),
                      ("node", ["node", "--version"])):
        if have[tool]:
            p = subprocess.run(cmd, capture_output=True, text=True)
            result["versions"][tool] = (p.stdout + p.stderr).strip().splitlines()[0]

    # ---- rendering -------------------------------------------------------
    scenes = [(n, p if os.path.isabs(p) else os.path.join(HERE, "scenes", p))
              for n, p in RENDER_SCENES]
    sizes = UNION_SIZES[:2] if a.quick else UNION_SIZES
    for n in sizes:
        path = os.path.join(work, f"union_{n}.scad")
        subprocess.run([sys.executable, os.path.join(HERE, "scenes", "gen_union.py"), str(n), path],
                       check=True)
        scenes.append((f"union_{n}", path))
    if a.quick:
        scenes = scenes[:2] + scenes[-2:]
    print(f"render: {W}x{H}, {a.threads} threads, no antialiasing, {reps} alternating reps")
    print(f"{'scene':18} {'rayscad s':>10} {'povray s':>10} {'ratio':>7} | "
          f"{'ray render':>10} {'pov trace':>10} {'ratio':>7} | {'Mrays/s':>8} {'IoU':>7}")
    for name, path in scenes:
        pov = os.path.join(work, f"{name}.pov")
        png_r = os.path.join(work, f"{name}.rayscad.png")
        png_p = os.path.join(work, f"{name}.povray.png")
        common = [f"--imgsize={W},{H}"]
        t_export, p = run([rayscad, path, "-o", pov] + common)
        if p.returncode != 0:
            print(f"{name}: export failed: {p.stderr.strip()[:200]}")
            continue
        row = {"scene": name, "export_s": t_export, "rayscad_s": [], "rayscad_render_s": [],
               "povray_s": [], "povray_trace_s": [], "rays_per_s": []}
        for _ in range(reps):
            t, p = run([rayscad, path, "-o", png_r, "--threads", str(a.threads)] + common, env=env)
            m = re.search(r"stats: (\d+) rays in ([\d.]+) s, (\d+) rays/s", p.stderr)
            if p.returncode == 0:
                row["rayscad_s"].append(t)
            if p.returncode == 0 and m:  # RAYSCAD_STATS: the render alone
                row["rayscad_render_s"].append(float(m.group(2)))
                row["rays_per_s"].append(float(m.group(3)))
            if have["povray"]:
                t, p = run(["povray", f"+W{W}", f"+H{H}", "-D", "-A", f"+WT{a.threads}",
                            f"+I{pov}", f"+O{png_p}"], timeout=600)
                m = re.search(r"Trace Time:.*\(([\d.]+) seconds\)", p.stderr)
                if p.returncode == 0 and m:
                    row["povray_s"].append(t)
                    row["povray_trace_s"].append(float(m.group(1)))
        for k in ("rayscad_s", "rayscad_render_s", "povray_s", "povray_trace_s", "rays_per_s"):
            row[k + "_median"] = med(row[k])
        rs, ps = row["rayscad_s_median"], row["povray_s_median"]
        rr, pt = row["rayscad_render_s_median"], row["povray_trace_s_median"]
        row["speedup_whole"] = ps / rs if rs and ps else None
        row["speedup_render"] = pt / rr if rr and pt else None
        if os.path.exists(png_r) and os.path.exists(png_p) and os.path.exists(maskcmp):
            p = subprocess.run([maskcmp, png_r, png_p, "--min-iou", "0"], capture_output=True,
                               text=True)
            m = re.search(r"iou=([\d.]+)", p.stdout)
            row["mask_iou"] = float(m.group(1)) if m else None
        result["render"].append(row)

        def f(x, fmt="10.3f"):
            return format(x, fmt) if x is not None else "-".rjust(int(fmt.split(".")[0]))
        print(f"{name:18} {f(rs)} {f(ps)} {f(row['speedup_whole'], '7.2f')} | {f(rr)} {f(pt)} "
              f"{f(row['speedup_render'], '7.2f')} | {f((row['rays_per_s_median'] or 0) / 1e6, '8.2f')} "
              f"{f(row.get('mask_iou'), '7.4f')}")
        sys.stdout.flush()

    # ---- scaling -----------------------------------------------------------
    series = [r for r in result["render"] if r["scene"].startswith("union_")]
    for r in series:
        result["scaling"].append({"primitives": int(r["scene"].split("_")[1]),
                                  "rayscad_render_s": r["rayscad_render_s_median"],
                                  "povray_trace_s": r["povray_trace_s_median"]})
    if len(series) >= 2:
        s0, s1 = result["scaling"][0], result["scaling"][-1]
        if s0["rayscad_render_s"] and s1["rayscad_render_s"]:
            k = math.log(s1["rayscad_render_s"] / s0["rayscad_render_s"]) / math.log(
                s1["primitives"] / s0["primitives"])
            result["summary"]["scaling_exponent_rayscad"] = k
            print(f"scaling: render time ~ n^{k:.2f} from {s0['primitives']} to "
                  f"{s1['primitives']} primitives ({s0['rayscad_render_s']:.3f} s -> "
                  f"{s1['rayscad_render_s']:.3f} s)")

    # ---- meshing -----------------------------------------------------------
    mesh_scenes = MESH_SCENES[:1] if a.quick else MESH_SCENES
    manifold_ok = have["node"] and os.path.isdir(os.path.join(HERE, "node_modules", "manifold-3d"))
    p = subprocess.run([rayscad, "--help"], capture_output=True, text=True)
    mesh_cli = "--mesh-size" in p.stdout
    if not mesh_cli:
        print("mesh: this rayscad has no mesh output yet (--mesh-size); skipping rayscad meshing")
    print(f"mesh: {reps} alternating reps; volume error against the exact value")
    print(f"{'scene':12} {'tool':28} {'median s':>9} {'in-proc s':>9} {'triangles':>9} "
          f"{'vol err %':>9} {'deviation':>9}")
    for name, rel, exact in mesh_scenes:
        path = os.path.join(HERE, "scenes", rel)
        runs = {}
        for rep_i in range(reps):
            if mesh_cli:
                for h in MESH_SIZES:
                    out = os.path.join(work, f"{name}.rayscad-{h}.stl")
                    # binary STL, as the diary's earlier runs wrote (manifold-3d
                    # writes no file; openscad its default, text)
                    # the contour itself (--mesh-tolerance 0), as the diary's
                    # earlier runs wrote it before meshes were simplified by
                    # default
                    t, p = run([rayscad, path, "-o", out, "--export-format", "binstl",
                                "--mesh-size", str(h), "--mesh-tolerance", "0", "--threads",
                                str(a.threads)])
                    if p.returncode == 0:
                        runs.setdefault(f"rayscad --mesh-size {h}", []).append((t, None, out))
                # out of the box: the default grid and tolerance (the facets'
                # deviation at the scene's $fn = 64)
                out = os.path.join(work, f"{name}.rayscad-default.stl")
                t, p = run([rayscad, path, "-o", out, "--export-format", "binstl", "--threads",
                            str(a.threads)])
                if p.returncode == 0:
                    runs.setdefault("rayscad default", []).append((t, None, out))
                for tol in MESH_TOLERANCES:
                    out = os.path.join(work, f"{name}.rayscad-tol{tol}.stl")
                    t, p = run([rayscad, path, "-o", out, "--export-format", "binstl",
                                "--mesh-size", "0.25", "--mesh-tolerance", str(tol),
                                "--threads", str(a.threads)])
                    if p.returncode == 0:
                        runs.setdefault(f"rayscad 0.25 tolerance {tol}", []).append(
                            (t, None, out))
            if have["openscad"]:
                out = os.path.join(work, f"{name}.openscad.stl")
                t, p = run(["openscad", "-o", out, "-D", f"fn={OPENSCAD_FN}", path], timeout=600)
                if p.returncode == 0:
                    runs.setdefault(f"openscad CGAL $fn={OPENSCAD_FN}", []).append((t, None, out))
                if rep_i == 0 and not a.quick:
                    out = os.path.join(work, f"{name}.openscad-fine.stl")
                    t, p = run(["openscad", "-o", out, "-D", f"fn={OPENSCAD_FN_FINE}", path],
                               timeout=900)
                    if p.returncode == 0:
                        runs.setdefault(f"openscad CGAL $fn={OPENSCAD_FN_FINE}", []).append(
                            (t, None, out))
            if manifold_ok:
                for seg in MANIFOLD_SEGMENTS:
                    out = os.path.join(work, f"{name}.manifold-{seg}.stl")
                    t, p = run(["node", os.path.join(HERE, "manifold_mesh.mjs"), name, str(seg),
                                out])
                    if p.returncode == 0:
                        j = json.loads(p.stdout.strip().splitlines()[-1])
                        j["stl"] = out
                        runs.setdefault(f"manifold-3d {seg} segments", []).append(
                            (t, j["ms"] / 1000, j))
        for tool, rs in runs.items():
            last = rs[-1][2]
            if isinstance(last, dict):
                vol, ntri = last["volume"], last["triangles"]
                stl = last["stl"]
            else:
                vol, ntri = stl_volume(last)
                stl = last
            row = {"scene": name, "tool": tool, "exact_volume": exact,
                   "whole_s": [r[0] for r in rs], "inproc_s": [r[1] for r in rs],
                   "volume": vol, "triangles": ntri,
                   "volume_error_pct": 100 * (vol - exact) / exact,
                   "deviation": surface_deviation(name, stl_triangles(stl))
                   if ntri <= 200000 else None}
            row["whole_s_median"] = med(row["whole_s"])
            row["inproc_s_median"] = med(row["inproc_s"])
            result["mesh"].append(row)
            ip = row["inproc_s_median"]
            print(f"{name:12} {tool:28} {row['whole_s_median']:9.3f} "
                  f"{(format(ip, '9.3f') if ip is not None else '-'.rjust(9))} {ntri:9d} "
                  f"{row['volume_error_pct']:+9.3f} "
                  f"{(format(row['deviation'], '9.5f') if row['deviation'] is not None else '-'.rjust(9))}")
        sys.stdout.flush()

    # ---- animation: 60 frames, one process each side -----------------------
    # rayscad --animate 60 against povray rendering the same 60 frames from
    # rayscad's .pov export of each, driven by povray's own animation clock
    # (one scene file that includes frame_number's export).
    frames = 10 if a.quick else 60
    anim = os.path.join(ROOT, "models", "animated.scad")
    adir = os.path.join(work, "anim")
    os.makedirs(adir, exist_ok=True)
    t_export, p = run([rayscad, anim, "--animate", str(frames), "-o", os.path.join(adir, "f.pov"),
                       f"--imgsize={W},{H}"])
    driver = os.path.join(adir, "animation.pov")
    with open(driver, "w") as fh:
        fh.write('#include concat("f", str(frame_number, -5, 0), ".pov")\n')
    row = {"frames": frames, "size": [W, H], "pov_export_s": t_export, "rayscad_s": [],
           "povray_s": []}
    for _ in range(reps):
        t, p = run([rayscad, anim, "--animate", str(frames), "-o", os.path.join(adir, "r.png"),
                    f"--imgsize={W},{H}", "--threads", str(a.threads)], timeout=600)
        if p.returncode == 0:
            row["rayscad_s"].append(t)
        if have["povray"]:
            t, p = run(["povray", f"+W{W}", f"+H{H}", "-D", "-A", f"+WT{a.threads}",
                        f"+KFI0", f"+KFF{frames - 1}", f"+L{adir}", f"+I{driver}",
                        f"+O{os.path.join(adir, 'p.png')}"], timeout=1200)
            if p.returncode == 0:
                row["povray_s"].append(t)
    row["rayscad_s_median"], row["povray_s_median"] = med(row["rayscad_s"]), med(row["povray_s"])
    if row["rayscad_s_median"] and row["povray_s_median"]:
        row["speedup_whole"] = row["povray_s_median"] / row["rayscad_s_median"]
    result["animation"] = row
    print(f"animation: {frames} frames at {W}x{H}: rayscad {row['rayscad_s_median']} s, "
          f"povray {row['povray_s_median']} s")
    sys.stdout.flush()

    # ---- the viewer: a scripted session under Xvfb (bench/viewer_bench.py) ---
    if not a.quick:
        result["viewer"] = viewer_bench.run(a.build)
        sys.stdout.flush()

    # ---- evaluation: library code (BOSL2's test pass) ------------------------
    if not a.quick:
        result["evaluation"] = eval_bench.run(a.build, reps)
        sys.stdout.flush()

    # ---- hulls: a rounded box minus a revolved hull, thousands of faces each --
    # (not a render row: POV-Ray clips every plane of the exported hulls and
    # took more than ten minutes for one 640x480 frame)
    if have["openscad"]:
        path = os.path.join(HERE, "scenes", "hull.scad")
        row = {"scene": "hull", "rayscad_stl_s": [], "rayscad_png_s": [], "openscad_stl_s": []}
        for _ in range(reps):
            t, p = run([rayscad, path, "-o", os.path.join(work, "hull.stl"), "--threads",
                        str(a.threads)])
            if p.returncode == 0:
                row["rayscad_stl_s"].append(t)
            t, p = run([rayscad, path, "-o", os.path.join(work, "hull.png"), f"--imgsize={W},{H}",
                        "--threads", str(a.threads)])
            if p.returncode == 0:
                row["rayscad_png_s"].append(t)
            t, p = run(["openscad", "-o", os.path.join(work, "hull.openscad.stl"), path],
                       timeout=600)
            if p.returncode == 0:
                row["openscad_stl_s"].append(t)
        for k in ("rayscad_stl_s", "rayscad_png_s", "openscad_stl_s"):
            row[k + "_median"] = med(row[k])
        rs, os_ = row["rayscad_stl_s_median"], row["openscad_stl_s_median"]
        row["stl_speedup"] = os_ / rs if rs and os_ else None
        result["hull"] = row
        print(f"hull: rayscad stl {rs} s, png {row['rayscad_png_s_median']} s; openscad stl "
              f"{os_} s")
        sys.stdout.flush()

    # ---- --measure: exact volume and area of the mesh scenes, no grid --------
    # (the issue asks for 1e-6 of the exact volume in under 0.1 s; its ray
    # count is deterministic, its time is not)
    result["measure"] = []
    for name, rel, exact in mesh_scenes:
        path = os.path.join(HERE, "scenes", rel)
        times, m = [], None
        for _ in range(reps):
            t, p = run([rayscad, path, "--measure", "--json", "--threads", str(a.threads)])
            if p.returncode == 0:
                times.append(t)
                m = json.loads(p.stdout)
        if m:
            row = {"scene": name, "whole_s": times, "whole_s_median": med(times),
                   "rays": m.get("rays"), "volume": m["volume"], "exact_volume": exact,
                   "volume_error_rel": abs(m["volume"] - exact) / exact}
            result["measure"].append(row)
            print(f"measure: {name:12} {row['whole_s_median']:.3f} s, {row['rays']} rays, volume "
                  f"{m['volume']:.10g} ({row['volume_error_rel']:.2g} off the exact {exact})")
    sys.stdout.flush()

    # ---- summary -------------------------------------------------------------
    S = result["summary"]
    if result.get("hull", {}).get("stl_speedup"):
        S["hull_stl_whole_speedup_vs_openscad"] = result["hull"]["stl_speedup"]
    ev = result.get("evaluation")
    if ev:
        S["eval_bosl2_pass_cpu_ratio"] = ev["bosl2_pass"]["ratio"]
        S["eval_heaviest_worst_cpu_ratio"] = ev["heaviest_worst_ratio"]
        S["eval_startup_cpu_s"] = (f"rayscad {ev['startup']['rayscad_cpu_s']:.3f}, "
                                   f"openscad {ev['startup']['openscad_cpu_s']:.3f}")
    views = [r for r in result.get("viewer", []) if "moving_fps" in r]
    if views:
        S["viewer_moving_fps_min"] = min(r["moving_fps"] for r in views)
        S["viewer_rest_full_render_ms_max"] = max(r.get("rest_full_render_ms", 0) for r in views)
        S["viewer_reload_overhead_ms_max"] = max(r.get("reload_overhead_ms", 0) for r in views)
    if result.get("animation", {}).get("speedup_whole"):
        S[f"animation_{result['animation']['frames']}_frames_whole_speedup"] = \
            result["animation"]["speedup_whole"]
    S["render_whole_speedup_gmean"] = gmean([r["speedup_whole"] for r in result["render"]])
    S["render_only_speedup_gmean"] = gmean([r["speedup_render"] for r in result["render"]])
    big = [r for r in result["render"] if r["scene"] in ("union_1000", "union_10000")]
    S["render_whole_speedup_1000plus_gmean"] = gmean([r["speedup_whole"] for r in big])
    S["render_only_speedup_1000plus_gmean"] = gmean([r["speedup_render"] for r in big])
    for name, _, _ in mesh_scenes:
        rows = {r["tool"]: r for r in result["mesh"] if r["scene"] == name}
        ours = [r for t, r in rows.items() if t.startswith("rayscad")]
        for o in ours:
            for t, r in rows.items():
                if t.startswith("rayscad"):
                    continue
                S[f"mesh_{name}: {o['tool']} vs {t}"] = {
                    "speedup_whole": r["whole_s_median"] / o["whole_s_median"],
                    "volume_error_pct": [o["volume_error_pct"], r["volume_error_pct"]]}
    print("summary:")
    for k, v in S.items():
        if isinstance(v, float):
            print(f"  {k}: {v:.2f}")
        elif isinstance(v, dict):
            print(f"  {k}: {v['speedup_whole']:.2f}x faster whole-process, volume error "
                  f"{v['volume_error_pct'][0]:+.3f}% vs {v['volume_error_pct'][1]:+.3f}%")
        else:
            print(f"  {k}: {v}")
    out = a.out or os.path.join(HERE, "results",
                                datetime.datetime.now().strftime("%Y%m%d-%H%M%S") + ".json")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out + ".tmp", "w") as fh:
        json.dump(result, fh, indent=1)
    os.replace(out + ".tmp", out)
    print(f"wrote {os.path.relpath(out, ROOT)}")


if __name__ == "__main__":
    main()
