#!/usr/bin/env python3
"""The viewer's speed from a scripted session (make bench; issue 21's targets).

  viewer_bench.py BUILD            runs itself under xvfb-run, prints a table
                                   and the JSON of the results on its last line

For each scene, the viewer (rayscad FILE --stats) opens an 800x600 window
under Xvfb.  xdotool then drags the mouse across it for about 1.5 s (a step
every 16 ms), lets the view rest, and appends a comment to the file.  The
--stats lines (one per picture shown, with its size, samples, render time,
time since the last input and wall-clock time; "loaded in" per evaluation)
give:
  moving fps    pictures shown per second while the mouse moved, and the
                reduced size they were drawn at (the median)
  rest          the full-resolution picture after the drag: its render time
                (target: within 100 ms) and when it showed after the last
                input (the viewer waits 150 ms to call the view rested)
  reload        from the file's save to the new model on screen, less the
                evaluation's own time (target: within 200 ms)
No timing is asserted here; the figures go to bench/results with the rest.
"""
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SCENES = ["bench/scenes/few.scad", "bench/scenes/csg_deep.scad", "bench/scenes/glass.scad",
          "models/demo.scad", "models/gear.scad", "models/order_independence.scad"]
FRAME = re.compile(r"^frame (\d+)x(\d+) samples (\d+) pass \d+: ([\d.]+) ms, (\d+) ms after the "
                   r"last input, at ([\d.]+)$")
LOADED = re.compile(r"^loaded in ([\d.]+) ms")


def frames(path):
    out, loads = [], []
    for line in open(path, errors="replace"):
        m = FRAME.match(line.strip())
        if m:
            w, h, s, ms, since, at = m.groups()
            out.append({"w": int(w), "h": int(h), "samples": int(s), "ms": float(ms),
                        "since": int(since), "at": float(at)})
        m = LOADED.match(line.strip())
        if m:
            loads.append(float(m.group(1)))
    return out, loads


def window(name):
    for _ in range(100):
        r = subprocess.run(["xdotool", "search", "--name", "^" + re.escape(name) + " - rayscad"],
                           capture_output=True, text=True)
        if r.stdout.strip():
            return r.stdout.split()[0]
        time.sleep(0.1)
    return None


def wait_for(path, pred, timeout=30):
    t0 = time.time()
    while time.time() - t0 < timeout:
        fr, loads = frames(path)
        if pred(fr, loads):
            return True
        time.sleep(0.05)
    return False


def scene(rayscad, src, tmp):
    name = os.path.basename(src)
    model = os.path.join(tmp, name)
    text = open(os.path.join(ROOT, src)).read()
    open(model, "w").write(text)
    err = os.path.join(tmp, name + ".stats")
    proc = subprocess.Popen([rayscad, model, "--imgsize=800,600", "--stats"],
                            stdout=subprocess.DEVNULL, stderr=open(err, "w"), cwd=tmp)
    row = {"scene": src}
    try:
        win = window(name)
        if not win or not wait_for(err, lambda f, l: any(x["w"] == 800 and x["samples"] == 9
                                                           for x in f)):
            row["error"] = "no window or no full picture"
            return row
        # the drag: 90 steps of 4 px, one each 16 ms
        cmd = ["xdotool", "mousemove", "--window", win, "200", "300", "mousedown", "1"]
        for k in range(90):
            cmd += ["mousemove", "--window", win, str(200 + 4 * k), str(300 + (k % 20)),
                    "sleep", "0.016"]
        cmd += ["mouseup", "1"]
        t0 = time.time()
        subprocess.run(cmd, check=True)
        t1 = time.time()
        wait_for(err, lambda f, l: any(x["at"] > t1 and x["w"] == 800 and x["samples"] == 1
                                       for x in f), 10)
        fr, _ = frames(err)
        moving = [x for x in fr if t0 <= x["at"] <= t1 + 0.05]
        row["moving_fps"] = len(moving) / (t1 - t0)
        row["moving_size"] = "%dx%d" % (statistics.median(x["w"] for x in moving),
                                         statistics.median(x["h"] for x in moving)) \
            if moving else None
        row["moving_render_ms_median"] = statistics.median(x["ms"] for x in moving) \
            if moving else None
        full = [x for x in fr if x["at"] > t1 and x["w"] == 800 and x["samples"] == 1]
        if full:
            row["rest_full_render_ms"] = full[0]["ms"]
            row["rest_full_after_input_ms"] = full[0]["since"]
        # the reload: a comment appended, as an editor saves
        time.sleep(1)
        _, loads0 = frames(err)
        ts = time.time()
        with open(model, "a") as fh:
            fh.write("\n// saved again\n")
        wait_for(err, lambda f, l: len(l) > len(loads0) and any(x["at"] > ts for x in f), 30)
        fr, loads = frames(err)
        after = [x for x in fr if x["at"] > ts]
        if after and len(loads) > len(loads0):
            row["reload_total_ms"] = 1000 * (after[0]["at"] - ts)
            row["reload_eval_ms"] = loads[-1]
            row["reload_overhead_ms"] = row["reload_total_ms"] - loads[-1]
    finally:
        subprocess.run(["xdotool", "search", "--name", "^" + re.escape(name) + " - rayscad",
                        "key", "q"], capture_output=True)
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
    return row


def inner(build):
    rayscad = os.path.abspath(os.path.join(ROOT, build, "rayscad"))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for src in SCENES:
            rows.append(scene(rayscad, src, tmp))
    print(json.dumps(rows))


def fmt(v, f="%.1f"):
    return f % v if isinstance(v, (int, float)) else "-"


def run(build):
    """The rows, printed as a table; [] when there is no X to run under."""
    if not all(subprocess.run(["sh", "-c", "command -v " + t], capture_output=True).returncode == 0
               for t in ("xvfb-run", "xdotool")):
        print("viewer: xvfb-run or xdotool missing; skipped")
        return []
    r = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", sys.executable,
                        os.path.abspath(__file__), "--inner", build],
                       capture_output=True, text=True, cwd=ROOT, timeout=900)
    try:
        rows = json.loads(r.stdout.strip().splitlines()[-1])
    except (IndexError, ValueError):
        print("viewer: the session failed:", r.stderr[-500:])
        return []
    print("viewer (800x600 window, 2 cores): moving fps at the reduced size, the full picture "
          "after the view rests, reload beyond evaluation")
    for x in rows:
        print("  %-36s %5s fps at %-8s  rest: %6s ms render, shown %5s ms after input  "
              "reload: +%6s ms (eval %s ms)"
              % (x["scene"], fmt(x.get("moving_fps")), x.get("moving_size") or "-",
                 fmt(x.get("rest_full_render_ms")), fmt(x.get("rest_full_after_input_ms"), "%d"),
                 fmt(x.get("reload_overhead_ms")), fmt(x.get("reload_eval_ms")))
              + ("  (%s)" % x["error"] if x.get("error") else ""))
    return rows


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--inner":
        inner(sys.argv[2])
    else:
        run(sys.argv[1] if len(sys.argv) > 1 else "build")
