#!/usr/bin/env python3
"""Every output of every model, for checking that a change of structure
changes nothing (issue 17's "byte-identical before and after").

  snapshot.py run BIN DIR [--only GLOB] [--kinds echo,csg,png,stl]
      run BIN on every file below and keep each output, its exit status and
      its stderr under DIR (DIR/manifest.json indexes them)
  snapshot.py diff DIR_A DIR_B [--rerun BIN_A]
      list every file whose outputs, exit status or stderr differ; with
      --rerun, a difference that BIN_A itself does not reproduce on a second
      run (rands() without a seed, time) is reported as unstable, not as a
      change

The files: tests/**.scad, models/, bench/scenes/ (and union_1000 from
gen_union.py), OpenSCAD's bundled examples, and ../shared/corpora: the
regression corpus's scad/ and BOSL2's examples and the scripts of its
tests/*.scadtest (written into a scratch copy of BOSL2, as its README asks).
Each runs in its own folder with OPENSCADPATH at the corpora.  Outputs: .echo,
.csg, a 320x240 PNG, an STL.  Not a test: the expected outputs are our own.
"""
import fnmatch
import hashlib
import json
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import corpus  # noqa: E402  (tests/cli/corpus.py: the BOSL2 test scripts)

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CORPORA = corpus.CORPORA
EXAMPLES = "/usr/share/openscad/examples"
SCRATCH = os.path.join(tempfile.gettempdir(), "rayscad-snapshot-corpora")
KINDS = ["echo", "csg", "png", "stl"]
TIMEOUT = 60
STDERR_KEEP = 1 << 16  # characters of stderr kept in the manifest


def bosl2_scratch():
    """A scratch copy of BOSL2 whose tests/ holds one .scad per [[test]]
    (written as make corpus writes them)."""
    if not os.path.isdir(os.path.join(CORPORA, "BOSL2")):
        return []
    return [path for _, path in corpus.bosl2_tests(SCRATCH)]


def all_files():
    files = []
    for base in ("tests", "models", "bench/scenes"):
        for d, _, names in os.walk(os.path.join(ROOT, base)):
            files += [os.path.join(d, n) for n in names if n.endswith(".scad")]
    union = os.path.join(SCRATCH, "union_1000.scad")
    if not os.path.exists(union):
        os.makedirs(SCRATCH, exist_ok=True)
        subprocess.run([sys.executable, os.path.join(ROOT, "bench/scenes/gen_union.py"),
                        "1000", union], check=True)
    files.append(union)
    for base in (EXAMPLES, os.path.join(CORPORA, "openscad-tests/data/scad"),
                 os.path.join(CORPORA, "BOSL2/examples")):
        for d, _, names in os.walk(base):
            files += [os.path.join(d, n) for n in names if n.endswith(".scad")]
    files += bosl2_scratch()
    return sorted(set(files))


def key_of(path):
    for prefix, tag in ((ROOT + "/", ""), (SCRATCH + "/", "scratch/"),
                        (CORPORA + "/", "corpora/"), (EXAMPLES + "/", "examples/")):
        if path.startswith(prefix):
            return tag + path[len(prefix):]
    return path


def run_one(binary, path, kind, outdir):
    key = key_of(path)
    stem = os.path.join(outdir, "files", key.replace("/", "__"))
    out = "%s.%s" % (stem, kind)
    args = [binary, os.path.basename(path), "-o", out]
    if kind == "png":
        args.append("--imgsize=320,240")
    env = dict(os.environ, OPENSCADPATH=CORPORA)
    # stderr goes to a file: a run may print gigabytes of warnings in its
    # time, which must not all be held here
    with tempfile.TemporaryFile() as ef:
        try:
            rc = subprocess.run(["timeout", "-k", "5", str(TIMEOUT)] + args,
                                cwd=os.path.dirname(path), env=env, stdout=subprocess.DEVNULL,
                                stderr=ef).returncode
        except OSError as e:
            rc = -1
            ef.write(str(e).encode())
        size = ef.tell()
        ef.seek(0)
        err = ef.read(STDERR_KEEP + 1024)
        rest = hashlib.sha256(err)
        for block in iter(lambda: ef.read(1 << 20), b""):
            rest.update(block)
    # the output's own name appears in some messages; make it DIR-independent
    err = err.replace(out.encode(), b"OUT").replace(outdir.encode(), b"DIR")
    text = err.decode("utf-8", "replace")
    if size > STDERR_KEEP:
        text = "%s…[%d bytes, sha256 %s]" % (text[:STDERR_KEEP], size, rest.hexdigest())
    digest = None
    if os.path.exists(out):
        h = hashlib.sha256()
        with open(out, "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
        digest = h.hexdigest()
    return key, kind, {"rc": rc, "stderr": text, "sha": digest}


def same(x, y):
    """Whether two results agree: exit status, output and stderr (a stderr
    over STDERR_KEEP compared by its first STDERR_KEEP characters, which is
    all a snapshot keeps of it)."""
    return (x["rc"], x["sha"], x["stderr"][:STDERR_KEEP]) == (
        y["rc"], y["sha"], y["stderr"][:STDERR_KEEP])


def cmd_run(binary, outdir, only, kinds):
    binary = os.path.abspath(binary)
    outdir = os.path.abspath(outdir)
    os.makedirs(os.path.join(outdir, "files"), exist_ok=True)
    files = [f for f in all_files() if not only or fnmatch.fnmatch(key_of(f), only)]
    manifest_path = os.path.join(outdir, "manifest.json")
    manifest = {}
    if os.path.exists(manifest_path):
        with open(manifest_path) as f:
            manifest = json.load(f)
    jobs = [(f, k) for f in files for k in kinds]
    done = 0
    with ThreadPoolExecutor(max_workers=int(os.environ.get("SNAPSHOT_JOBS", "2"))) as pool:
        for key, kind, res in pool.map(lambda j: run_one(binary, j[0], j[1], outdir), jobs):
            manifest.setdefault(key, {})[kind] = res
            done += 1
            if done % 200 == 0:
                print("%d of %d" % (done, len(jobs)), flush=True)
    with open(manifest_path, "w") as f:
        json.dump(manifest, f, indent=1, sort_keys=True)
    print("%d files, %d outputs -> %s" % (len(files), len(jobs), manifest_path))


def cmd_diff(a_dir, b_dir, rerun):
    with open(os.path.join(a_dir, "manifest.json")) as f:
        a = json.load(f)
    with open(os.path.join(b_dir, "manifest.json")) as f:
        b = json.load(f)
    by_key = {key_of(p): p for p in all_files()} if rerun else {}
    changed = unstable = 0
    for key in sorted(set(a) & set(b)):
        for kind in sorted(set(a[key]) & set(b[key])):
            x, y = a[key][kind], b[key][kind]
            if same(x, y):
                continue
            if rerun and key in by_key:
                with tempfile.TemporaryDirectory() as t:
                    os.makedirs(os.path.join(t, "files"))
                    _, _, again = run_one(os.path.abspath(rerun), by_key[key], kind, t)
                again["stderr"] = again["stderr"].replace(t, a_dir)
                if not same(again, x):
                    unstable += 1
                    print("unstable %s (%s)" % (key, kind))
                    continue
            changed += 1
            what = [f for f in ("rc", "sha", "stderr") if x[f] != y[f]]
            print("CHANGED %s (%s): %s" % (key, kind, ", ".join(what)))
            if "rc" in what:
                print("    rc %s -> %s" % (x["rc"], y["rc"]))
            if "stderr" in what:
                print("    stderr before: %s" % x["stderr"][:300].replace("\n", "\n      "))
                print("    stderr after:  %s" % y["stderr"][:300].replace("\n", "\n      "))
    missing = sorted(set(a) ^ set(b))
    for key in missing:
        print("ONLY IN %s: %s" % ("first" if key in a else "second", key))
    print("%d changed, %d unstable, %d in one snapshot only" % (changed, unstable, len(missing)))
    return 1 if changed or missing else 0


def main(argv):
    if len(argv) >= 3 and argv[0] == "run":
        only, kinds = None, KINDS
        rest = argv[3:]
        while rest:
            if rest[0] == "--only":
                only, rest = rest[1], rest[2:]
            elif rest[0] == "--kinds":
                kinds, rest = rest[1].split(","), rest[2:]
            else:
                break
        cmd_run(argv[1], argv[2], only, kinds)
        return 0
    if len(argv) >= 3 and argv[0] == "diff":
        rerun = argv[4] if len(argv) >= 5 and argv[3] == "--rerun" else None
        return cmd_diff(argv[1], argv[2], rerun)
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
