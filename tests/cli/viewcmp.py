#!/usr/bin/env python3
"""What a --view flag adds to an image, in openscad's image and in ours.

  viewcmp.py PLAIN_O VIEW_O PLAIN_R VIEW_R [--within PX] [--min F]

The lines are the pixels VIEW differs from PLAIN in (the same program, the
same file and camera without the flag).  Each program's lines must lie
within PX pixels (default 1) of the other's, for at least a fraction F
(default 0.98) of them, both ways, and neither may be empty.  Prints the
two counts and fractions; exits 1 when they fall short.
"""
import subprocess
import sys
import tempfile


def load(path, tmp):
    out = tmp + "/x.ppm"
    subprocess.run(["oiiotool", path, "--ch", "R,G,B", "-d", "uint8", "-o", out], check=True)
    data = open(out, "rb").read()
    magic, w, h, _, px = data.split(maxsplit=4)
    assert magic == b"P6"
    return int(w), int(h), px


def added(plain, view, w, h):
    return {(i % w, i // w) for i in range(w * h) if plain[3 * i:3 * i + 3] != view[3 * i:3 * i + 3]}


def near(a, b, r):
    return sum(1 for (x, y) in a
               if any((x + dx, y + dy) in b for dx in range(-r, r + 1) for dy in range(-r, r + 1)))


def main(argv):
    within, least = 1, 0.98
    args = []
    i = 0
    while i < len(argv):
        if argv[i] == "--within":
            within, i = int(argv[i + 1]), i + 2
        elif argv[i] == "--min":
            least, i = float(argv[i + 1]), i + 2
        else:
            args.append(argv[i])
            i += 1
    with tempfile.TemporaryDirectory() as tmp:
        imgs = [load(p, tmp) for p in args]
    (w, h, po), (_, _, vo), (w2, h2, pr), (_, _, vr) = imgs
    if (w, h) != (w2, h2):
        print("sizes differ: %dx%d and %dx%d" % (w, h, w2, h2))
        return 1
    lo, lr = added(po, vo, w, h), added(pr, vr, w, h)
    a = near(lr, lo, within) / max(1, len(lr))
    b = near(lo, lr, within) / max(1, len(lo))
    print("openscad %d px, ours %d px; ours near theirs %.3f, theirs near ours %.3f"
          % (len(lo), len(lr), a, b))
    return 0 if lo and lr and a >= least and b >= least else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
