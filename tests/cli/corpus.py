#!/usr/bin/env python3
"""Real OpenSCAD code against the real openscad 2021.01 (`make corpus`).

  corpus.py BUILD [--only GLOB] [--kind echo|csg|png|stl|ast|term] [--jobs N] [--update]

The two corpora of ../shared/corpora (see its README):
  openscad-tests/data/scad/**.scad  .echo, .csg, .png, .stl, .ast and .term
  BOSL2 tests/*.scadtest             .echo of every [[test]] script, written
                                     into a scratch copy of BOSL2 so that its
                                     include <../std.scad> resolves
Each file runs in its own folder with OPENSCADPATH at the corpora root, under
both programs, 2 jobs at a time.  .echo, .ast (the parsed file printed back)
and .term (the CSG term text) are compared byte for byte, .csg token by token
as tests/cli/conformance.sh does (numbers within 1e-9 relative).
.png is openscad's preview at 320x240 with its default camera (under one Xvfb
for the whole run) against ours with --facets=openscad: the silhouettes must
agree to IoU >= 0.99 outside a one-pixel band (BUILD/tools/maskcmp), and where
openscad draws nothing we must draw nothing.
.stl is openscad's export (CGAL) against ours with --facets=openscad: where
openscad exports a closed 2-manifold, ours must be one too, its volume within
0.5 % of openscad's (BUILD/tools/meshcmp --volume-only); where openscad
exports nothing (a 2D or empty model) or a mesh that is not closed (an open
polyhedron written as given), there is no rule.
openscad's outputs are kept in BUILD/corpus/ref and reused while newer than
their input.

A mismatch fails when tests/lang/known_differences.txt does not list it
(openscad broken, or rayscad deliberately different) and
tests/corpus/passing.txt does: that list is every file that matched when it
was last written (--update rewrites it from this run), so the count can only
rise.  A file that matches and is not on the list is reported as new.  rayscad
taking over 10 s or 2 GB where openscad takes under is a failure too.

Counts, each mismatch and each new match are printed; every result (with both
programs' CPU time and peak memory) is in BUILD/corpus/results.json.
"""
import fnmatch
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tomllib
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CORPORA = os.path.abspath(os.environ.get("RAYSCAD_CORPORA",
                                         os.path.join(ROOT, "..", "shared", "corpora")))
KNOWN = os.path.join(ROOT, "tests", "lang", "known_differences.txt")
PASSING = os.path.join(ROOT, "tests", "corpus", "passing.txt")
TIMEOUT = 120           # seconds a run may take before it is stopped
SLOW = 10.0             # seconds of CPU ...
HEAVY = 2 << 30         # ... or bytes of memory beyond which rayscad must not go alone
MEMORY_CAP = 6 << 30    # address space either program may map


def bosl2_tests(scratch):
    """(key, path) of every BOSL2 [[test]] script, written into scratch/BOSL2."""
    src = os.path.join(CORPORA, "BOSL2")
    dst = os.path.join(scratch, "BOSL2")
    if not os.path.isdir(dst):
        shutil.copytree(src, dst, ignore=shutil.ignore_patterns("*.scadtest"))
    out = []
    for t in sorted(os.listdir(os.path.join(src, "tests"))):
        if not t.endswith(".scadtest"):
            continue
        with open(os.path.join(src, "tests", t), "rb") as f:
            doc = tomllib.load(f)
        for i, test in enumerate(doc.get("test", [])):
            name = "%s__%03d_%s.scad" % (t[:-len(".scadtest")], i, test.get("name", "x"))
            path = os.path.join(dst, "tests", name)
            text = test["script"]
            old = None
            if os.path.exists(path):
                with open(path) as f:
                    old = f.read()
            if old != text:
                with open(path, "w") as f:
                    f.write(text)
            out.append(("BOSL2/tests/" + name, path))
    return out


def openscad_tests():
    base = os.path.join(CORPORA, "openscad-tests", "data", "scad")
    out = []
    for d, _, names in os.walk(base):
        for n in names:
            if n.endswith(".scad"):
                p = os.path.join(d, n)
                out.append(("openscad-tests/" + os.path.relpath(p, base), p))
    return sorted(out)


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))


def run(argv, cwd, out, display=None):
    """Run argv in cwd writing out; (exit status, CPU seconds, peak bytes)."""
    env = dict(os.environ, OPENSCADPATH=CORPORA)
    env.pop("DISPLAY", None)
    if display:
        env["DISPLAY"] = display
    if os.path.exists(out):  # a failed run writes nothing: no stale output
        os.unlink(out)
    with open(out + ".log", "wb") as log:
        p = subprocess.Popen(["timeout", "-k", "5", str(TIMEOUT)] + argv, cwd=cwd, env=env,
                             stdin=subprocess.DEVNULL, stdout=log, stderr=log,
                             preexec_fn=limit_memory)
        _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if not os.path.exists(out):
        open(out, "wb").close()
    # timeout's own usage is negligible; its child's is folded into ru
    return p.returncode, ru.ru_utime + ru.ru_stime, ru.ru_maxrss * 1024


NUM = re.compile(r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?(?:inf|nan)')
TOK = re.compile(r'"(?:[^"\\\n]|\\.)*"|' + NUM.pattern + r'|\w+|\S')


def csg_diff(a, b):
    """Why two .csg texts differ, or None (the rule of conformance.sh)."""
    x, y = TOK.findall(a), TOK.findall(b)
    for i, (s, t) in enumerate(zip(x, y)):
        if s == t:
            continue
        if NUM.fullmatch(s) and NUM.fullmatch(t):
            fs, ft = float(s), float(t)
            if fs == ft or (fs != fs and ft != ft):
                continue
            if abs(fs - ft) <= max(1e-12, 1e-9 * max(abs(fs), abs(ft))):
                continue
        return "token %d: %r != %r" % (i, s, t)
    if len(x) != len(y):
        return "token count %d != %d" % (len(x), len(y))
    return None


def echo_diff(a, b):
    """The first differing line of two texts (.echo, .ast, .term), or None."""
    if a == b:
        return None
    x, y = a.split("\n"), b.split("\n")
    for i, (s, t) in enumerate(zip(x, y)):
        if s != t:
            return "line %d: openscad %r, rayscad %r" % (i + 1, s[:160], t[:160])
    i = min(len(x), len(y))
    more = x[i] if len(x) > len(y) else y[i]
    who = "openscad" if len(x) > len(y) else "rayscad"
    return "line %d: only %s has %r" % (i + 1, who, more[:160])


IMG = ["--imgsize=320,240"]
MIN_IOU = 0.99


def mask_pixels(maskcmp, img):
    """Pixels off the background in img (0 where there is no image: a run
    that stops with an error draws nothing, as openscad's empty preview)."""
    if os.path.getsize(img) == 0:
        return 0
    p = subprocess.run([maskcmp, img, img], capture_output=True, text=True)
    m = re.search(r"mask_px=(\d+) band_px=(\d+)", p.stdout)
    return int(m.group(1)) + int(m.group(2)) if m else -1


def png_diff(maskcmp, ref, ours):
    """Why two previews' silhouettes differ, or None; also the IoU (None
    where openscad draws nothing)."""
    theirs = mask_pixels(maskcmp, ref)
    if theirs == 0 or os.path.getsize(ours) == 0:
        mine = mask_pixels(maskcmp, ours)
        if theirs == 0 and mine == 0:
            return None, None
        if theirs == 0:
            return "openscad draws nothing, rayscad %d pixels" % mine, None
        return "rayscad draws nothing, openscad %d pixels" % theirs, 0.0
    p = subprocess.run([maskcmp, ours, ref, "--min-iou", str(MIN_IOU),
                        "--diff", ours + ".diff.png"], capture_output=True, text=True)
    m = re.search(r"iou=([0-9.]+) mask_px=(\d+)", p.stdout)
    if not m:
        return "maskcmp failed: %s" % (p.stderr.strip() or p.stdout.strip()), None
    iou = float(m.group(1))
    return (None if iou >= MIN_IOU else "silhouette IoU %.4f" % iou), iou


MAX_DVOL = 0.005


def stl_volume(meshcmp, ours, ref):
    """(closed, our volume, openscad's) of two STL files, or None."""
    p = subprocess.run([meshcmp, ours, ref, "--volume-only"], capture_output=True, text=True)
    m = re.search(r"closed=(\d) volume=(\S+) ref_volume=(\S+)", p.stdout)
    return (m.group(1) == "1", float(m.group(2)), float(m.group(3))) if m else None


def stl_diff(meshcmp, ref, ours):
    """Why our STL falls short of openscad's, or None; also the relative
    volume difference (None where there is no rule: openscad exported
    nothing, or a mesh that is not closed)."""
    if os.path.getsize(ref) == 0:
        return None, None
    theirs = stl_volume(meshcmp, ref, ref)
    if theirs is None or not theirs[0] or theirs[1] == 0:
        return None, None
    if os.path.getsize(ours) == 0:
        return "rayscad exports nothing, openscad volume %.6g" % theirs[1], 1.0
    mine = stl_volume(meshcmp, ours, ref)
    if mine is None:
        return "meshcmp could not read our STL", 1.0
    dv = abs(mine[1] - mine[2]) / abs(mine[2])
    if not mine[0]:
        return "our mesh is not closed and 2-manifold", dv
    if dv > MAX_DVOL:
        return "volume %.6g vs openscad's %.6g (%+.2f %%)" % (
            mine[1], mine[2], 100 * (mine[1] - mine[2]) / abs(mine[2])), dv
    return None, dv


def read(path):
    with open(path, "rb") as f:
        return f.read().decode("utf-8", "replace")


def compare(kind, ref, ours, maskcmp):
    if kind == "png":
        return png_diff(maskcmp, ref, ours)
    if kind == "stl":
        return stl_diff(os.path.join(os.path.dirname(maskcmp), "meshcmp"), ref, ours)
    a, b = read(ref), read(ours)
    return (csg_diff(a, b) if kind == "csg" else echo_diff(a, b)), None


def check(rayscad, outdir, key, path, kind, display=None):
    stem = key.replace("/", "__")
    ref = os.path.join(outdir, "ref", stem + "." + kind)
    ours = os.path.join(outdir, "ours", stem + "." + kind)
    cwd, base = os.path.dirname(path), os.path.basename(path)
    meta = ref + ".json"
    fresh = (os.path.exists(meta) and os.path.getmtime(meta) >= os.path.getmtime(path))
    if fresh:
        with open(meta) as f:
            theirs = json.load(f)
    img = IMG if kind == "png" else []
    if not fresh:
        rc, cpu, mem = run(["openscad", "-o", ref] + img + [base], cwd, ref, display)
        theirs = {"rc": rc, "cpu": cpu, "mem": mem}
        with open(meta, "w") as f:
            json.dump(theirs, f)
    facets = ["--facets=openscad"] if kind in ("png", "stl") else []
    rc, cpu, mem = run([rayscad, base, "-o", ours] + img + facets, cwd, ours)
    maskcmp = os.path.join(os.path.dirname(rayscad), "tools", "maskcmp")
    why, iou = compare(kind, ref, ours, maskcmp)
    if why is not None and kind in ("echo", "csg"):
        # openscad once more before calling it a difference: one of its runs
        # has been seen to differ from the next (misc/include-recursive-test)
        orc, ocpu, omem = run(["openscad", "-o", ref, base], cwd, ref)
        theirs = {"rc": orc, "cpu": ocpu, "mem": omem}
        with open(meta, "w") as f:
            json.dump(theirs, f)
        why, iou = compare(kind, ref, ours, maskcmp)
    if why is None and rc in (124, 137) + tuple(range(-64, 0)):
        why = "rayscad stopped (exit %d)" % rc
    slow = (cpu > SLOW and theirs["cpu"] <= SLOW) or (mem > HEAVY and theirs["mem"] <= HEAVY)
    return {"key": key, "kind": kind, "why": why, "slow": slow, "iou": iou if kind == "png" else None,
            "dvol": iou if kind == "stl" else None,
            "openscad": theirs, "rayscad": {"rc": rc, "cpu": cpu, "mem": mem}}


def start_xvfb():
    """One X server for every openscad preview of the run: (process, DISPLAY)."""
    r, w = os.pipe()
    p = subprocess.Popen(["Xvfb", "-displayfd", str(w), "-screen", "0", "1024x768x24",
                          "-nolisten", "tcp"], pass_fds=(w,), stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL)
    os.close(w)
    with os.fdopen(r) as f:
        number = f.readline().strip()
    if not number:
        raise SystemExit("corpus: Xvfb did not start (make deps installs it)")
    return p, ":" + number


def read_known():
    known = {}
    if os.path.exists(KNOWN):
        for line in open(KNOWN, encoding="utf-8"):
            line = line.strip()
            if line and not line.startswith("#"):
                name, _, reason = line.partition(" ")
                known[name] = reason.strip()
    return known


def read_passing():
    if not os.path.exists(PASSING):
        return set()
    return {l.strip() for l in open(PASSING, encoding="utf-8")
            if l.strip() and not l.startswith("#")}


def main(argv):
    if not argv or argv[0].startswith("-"):
        print(__doc__)
        return 2
    build, only, kind, jobs, update = argv[0], None, None, 2, False
    i = 1
    while i < len(argv):
        if argv[i] == "--only":
            only, i = argv[i + 1], i + 2
        elif argv[i] == "--kind":
            kind, i = argv[i + 1], i + 2
        elif argv[i] == "--jobs":
            jobs, i = int(argv[i + 1]), i + 2
        elif argv[i] == "--update":
            update, i = True, i + 1
        else:
            print("corpus.py: unknown argument %s" % argv[i], file=sys.stderr)
            return 2
    if not os.path.isdir(CORPORA):
        print("corpus: skipped: no corpora at %s (see the README's Tests section)" % CORPORA)
        return 0
    if shutil.which("openscad") is None:
        print("corpus: openscad is not installed (make deps)", file=sys.stderr)
        return 2
    rayscad = os.path.abspath(os.path.join(build, "rayscad"))
    outdir = os.path.abspath(os.path.join(build, "corpus"))
    for d in ("ref", "ours", "scratch"):
        os.makedirs(os.path.join(outdir, d), exist_ok=True)

    jobs_list = [(k, p, kind) for k, p in openscad_tests()
                 for kind in ("echo", "csg", "png", "stl", "ast", "term")]
    jobs_list += [(k, p, "echo") for k, p in bosl2_tests(os.path.join(outdir, "scratch"))]
    if only:
        jobs_list = [j for j in jobs_list if fnmatch.fnmatch(j[0], only)]
    if kind:
        jobs_list = [j for j in jobs_list if j[2] == kind]

    results = []
    xvfb, display = start_xvfb() if any(j[2] == "png" for j in jobs_list) else (None, None)
    try:
        with ThreadPoolExecutor(max_workers=jobs) as pool:
            for n, r in enumerate(pool.map(lambda j: check(rayscad, outdir, *j, display=display),
                                           jobs_list), 1):
                results.append(r)
                if n % 100 == 0:
                    print("corpus: %d of %d" % (n, len(jobs_list)), flush=True)
    finally:
        if xvfb:
            xvfb.terminate()
            xvfb.wait()
    with open(os.path.join(outdir, "results.json"), "w") as f:
        json.dump(results, f, indent=1)

    known, passing = read_known(), read_passing()
    failed, new, counts = [], [], {}
    for r in results:
        name = "%s:%s" % (r["key"], r["kind"])
        corpus = r["key"].split("/")[0] + " ." + r["kind"]
        c = counts.setdefault(corpus, [0, 0, 0])
        c[1] += 1
        if r["why"] is None:
            c[0] += 1
            if name not in passing:
                new.append(name)
        elif name in known or r["key"] in known:
            c[2] += 1
        else:
            print("DIFF %s: %s" % (name, r["why"]))
            if name in passing:
                failed.append("%s no longer matches openscad" % name)
        if r["slow"]:
            print("SLOW %s: rayscad %.1f s %.0f MB, openscad %.1f s %.0f MB" % (
                name, r["rayscad"]["cpu"], r["rayscad"]["mem"] / 2**20,
                r["openscad"]["cpu"], r["openscad"]["mem"] / 2**20))
            failed.append("%s takes over %g s or %d GB where openscad does not" % (
                name, SLOW, HEAVY >> 30))
    for name in new:
        print("NEW %s matches openscad (not yet in tests/corpus/passing.txt)" % name)
    for corpus in sorted(counts):
        ok, total, k = counts[corpus]
        print("corpus: %s: %d of %d %s openscad's, %d known differences" % (
            corpus, ok, total,
            "identical to" if corpus.endswith(("echo", "csg", "ast", "term")) else "agree with",
            k))
    ious = [r["iou"] for r in results if r["kind"] == "png" and r["iou"] is not None]
    if ious:
        print("corpus: .png where openscad draws: %d files, IoU >= 0.99: %d, 0.95-0.99: %d, "
              "below: %d" % (len(ious), sum(i >= 0.99 for i in ious),
                             sum(0.95 <= i < 0.99 for i in ious), sum(i < 0.95 for i in ious)))
    dvols = [r["dvol"] for r in results if r["kind"] == "stl" and r["dvol"] is not None]
    if dvols:
        closed = sum(1 for r in results if r["kind"] == "stl" and r["dvol"] is not None
                     and (r["why"] is None or "volume" in r["why"]))
        print("corpus: .stl where openscad exports a closed mesh: %d files, ours closed: %d, "
              "volume within 0.5 %%: %d" % (len(dvols), closed,
                                             sum(1 for d in dvols if d <= MAX_DVOL)))
    for f in failed:
        print("FAIL %s" % f)
    if update:
        keep = {n for n in passing
                if (only and not fnmatch.fnmatch(n.split(":")[0], only))
                or (kind and n.rsplit(":", 1)[1] != kind)}
        now = keep | {"%s:%s" % (r["key"], r["kind"]) for r in results if r["why"] is None}
        os.makedirs(os.path.dirname(PASSING), exist_ok=True)
        with open(PASSING, "w", encoding="utf-8") as f:
            f.write("# Corpus files whose output matches openscad 2021.01's byte for byte\n"
                    "# (.csg token by token); tests/cli/corpus.py --update writes it.\n")
            for n in sorted(now):
                f.write(n + "\n")
        print("corpus: %s: %d files" % (os.path.relpath(PASSING, ROOT), len(now)))
    print("corpus: %s" % ("%d failures" % len(failed) if failed else "passed"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
