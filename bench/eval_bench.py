"""make bench's evaluation part: rayscad and openscad on real library code.

The BOSL2 test pass (every [[test]] script of ../shared/corpora/BOSL2/tests,
written into a scratch copy as tests/cli/corpus.py does), each script run by
both programs one after the other (-o x.echo, from its folder, OPENSCADPATH at
the corpora), two scripts at a time; CPU time (user + system, of the process
and its children) summed over the pass.  Then its 10 heaviest scripts (by
openscad's CPU time in that pass) again, alternately, REPS times, medians.
And start-up: an empty file to .echo, both programs, alternately.
"""
import os
import statistics
import sys
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "cli"))
import corpus  # noqa: E402  (tests/cli/corpus.py: the scratch copy of BOSL2)


def cpu_of(argv, cwd, out):
    """Run argv as make corpus runs it; its CPU seconds (user + system,
    children included).  Its output and log are not kept."""
    cpu = corpus.run(argv, cwd, out)[1]
    for f in (out, out + ".log"):
        if os.path.exists(f):
            os.unlink(f)
    return cpu


def both(rayscad, path, scratch, tag):
    cwd, base = os.path.dirname(path), os.path.basename(path)
    out = os.path.join(scratch, "bench-%s.echo" % tag)
    o = cpu_of(["openscad", "-o", out, base], cwd, out)
    r = cpu_of([rayscad, base, "-o", out], cwd, out)
    return o, r


def run(build, reps):
    """The evaluation result (a dict), or None where the corpora are absent."""
    if not os.path.isdir(corpus.CORPORA):
        print("evaluation: skipped: no corpora at %s" % corpus.CORPORA)
        return None
    rayscad = os.path.abspath(os.path.join(build, "rayscad"))
    scratch = os.path.abspath(os.path.join(build, "corpus", "scratch"))
    os.makedirs(scratch, exist_ok=True)
    tests = corpus.bosl2_tests(scratch)
    print("evaluation: the BOSL2 test pass, %d scripts, both programs, 2 at a time" % len(tests))
    with ThreadPoolExecutor(max_workers=2) as pool:
        times = list(pool.map(lambda kt: both(rayscad, kt[1], scratch, kt[0].replace("/", "_")),
                              tests))
    pass_o = sum(t[0] for t in times)
    pass_r = sum(t[1] for t in times)
    print("  whole pass CPU: openscad %.1f s, rayscad %.1f s, ratio %.2f" %
          (pass_o, pass_r, pass_r / pass_o))
    heavy = sorted(zip(tests, times), key=lambda x: -x[1][0])[:10]
    rows = []
    print("  %-52s %9s %9s %6s" % ("heaviest (median of %d)" % reps, "openscad", "rayscad", "ratio"))
    for (key, path), _ in heavy:
        os_, rs = [], []
        for _ in range(reps):
            o, r = both(rayscad, path, scratch, "heavy")
            os_.append(o)
            rs.append(r)
        o, r = statistics.median(os_), statistics.median(rs)
        rows.append({"script": key, "openscad_cpu_s": o, "rayscad_cpu_s": r, "ratio": r / o})
        print("  %-52s %9.2f %9.2f %6.2f" % (key[len("BOSL2/tests/"):][:52], o, r, r / o))
    empty = os.path.join(scratch, "empty.scad")
    with open(empty, "w") as fh:
        fh.write("")
    starts_o, starts_r = [], []
    for _ in range(max(5, reps)):
        o, r = both(rayscad, empty, scratch, "empty")
        starts_o.append(o)
        starts_r.append(r)
    so, sr = statistics.median(starts_o), statistics.median(starts_r)
    print("  start-up (an empty file to .echo) CPU: openscad %.3f s, rayscad %.3f s" % (so, sr))
    return {"bosl2_pass": {"scripts": len(tests), "openscad_cpu_s": pass_o,
                           "rayscad_cpu_s": pass_r, "ratio": pass_r / pass_o},
            "heaviest": rows,
            "heaviest_worst_ratio": max(r["ratio"] for r in rows),
            "startup": {"openscad_cpu_s": so, "rayscad_cpu_s": sr}}
