#!/usr/bin/env python3
"""Screenshots of the viewer's window against command-line renders.

  shot.py same XWD PNG [--border N] [--tol T] [--max-frac F] [--top R]
      the window's picture (xwd -id WINDOW) and an image rayscad -o wrote
      agree: at most a fraction F (default 0.01) of the pixels differ by
      more than T (default 24) in a channel, the N-pixel border (default 0)
      and all but the top R of the rows (default 1: all) left out.  Prints
      the fraction; exits 1 when over.
  shot.py closer XWD COARSE FINE  the window's mean error per channel to the
      finely sampled image FINE is under 0.8 of the coarse image's: the
      viewer's passes refine past COARSE.
  shot.py differ XWD XWD  the two pictures differ in over 1 % of the pixels.
  shot.py red-frame XWD   the outermost pixels are the viewer's error red.

XWD (X's window dump) is read here: a 24/32-bit TrueColor ZPixmap, as
xwd writes a window of Xvfb's default visual.  PNGs go through oiiotool.
"""
import struct
import subprocess
import sys
import tempfile


def read_xwd(path):
    d = open(path, "rb").read()
    (hsize, version, fmt, depth, w, h, _xoff, byte_order, _unit, _bit_order, _pad, bpp, bpl,
     _cls, rmask, gmask, bmask, _bits, _cmap, ncolors) = struct.unpack(">20I", d[:80])
    assert version == 7 and fmt == 2 and bpp in (24, 32), (version, fmt, bpp)
    off = hsize + 12 * ncolors
    endian = "<" if byte_order == 0 else ">"
    shifts = [(m, (m & -m).bit_length() - 1) for m in (rmask, gmask, bmask)]
    px = []
    for y in range(h):
        row = d[off + y * bpl: off + (y + 1) * bpl]
        for x in range(w):
            if bpp == 32:
                (v,) = struct.unpack_from(endian + "I", row, 4 * x)
            else:
                b = row[3 * x:3 * x + 3]
                v = int.from_bytes(b, "little" if byte_order == 0 else "big")
            px.append(tuple((v & m) >> s for m, s in shifts))
    return w, h, px


def read_png(path):
    with tempfile.NamedTemporaryFile(suffix=".ppm") as t:
        subprocess.run(["oiiotool", path, "--ch", "R,G,B", "-d", "uint8", "-o", t.name], check=True)
        d = open(t.name, "rb").read()
    magic, w, h, _, data = d.split(maxsplit=4)
    w, h = int(w), int(h)
    return w, h, [tuple(data[3 * i:3 * i + 3]) for i in range(w * h)]


def differing(a, b, w, h, border, tol, top=1.0):
    n = bad = 0
    for y in range(border, min(h - border, int(round(h * top)))):
        for x in range(border, w - border):
            i = y * w + x
            n += 1
            bad += max(abs(p - q) for p, q in zip(a[i], b[i])) > tol
    return bad / max(1, n)


def main(argv):
    opts = {"--border": 0, "--tol": 24, "--max-frac": 0.01, "--top": 1.0}
    args, i = [], 0
    while i < len(argv):
        if argv[i] in opts:
            opts[argv[i]] = float(argv[i + 1])
            i += 2
        else:
            args.append(argv[i])
            i += 1
    what = args[0]
    if what == "same":
        w, h, a = read_xwd(args[1])
        w2, h2, b = read_png(args[2])
        if (w, h) != (w2, h2):
            print("sizes differ: window %dx%d, image %dx%d" % (w, h, w2, h2))
            return 1
        f = differing(a, b, w, h, int(opts["--border"]), opts["--tol"], opts["--top"])
        print("%.4f of the pixels differ" % f)
        return 0 if f <= opts["--max-frac"] else 1
    if what == "closer":
        # the window nearer to a finely sampled image than a coarse one is
        w, h, a = read_xwd(args[1])
        _, _, coarse = read_png(args[2])
        _, _, fine = read_png(args[3])
        def mean_error(x, y):
            return sum(abs(p - q) for i in range(w * h) for p, q in zip(x[i], y[i])) / (3 * w * h)
        ew, ec = mean_error(a, fine), mean_error(coarse, fine)
        print("mean error to the fine image: window %.4f, coarse %.4f (of 255)" % (ew, ec))
        return 0 if ew < 0.8 * ec else 1
    if what == "differ":
        w, h, a = read_xwd(args[1])
        _, _, b = read_xwd(args[2])
        f = differing(a, b, w, h, 0, opts["--tol"])
        print("%.4f of the pixels differ" % f)
        return 0 if f > 0.01 else 1
    if what == "red-frame":
        w, h, a = read_xwd(args[1])
        edge = [a[x] for x in range(w)] + [a[(h - 1) * w + x] for x in range(w)]
        red = sum(1 for p in edge if p[0] > 180 and p[1] < 80 and p[2] < 80)
        print("%d of %d edge pixels red" % (red, len(edge)))
        return 0 if red == len(edge) else 1
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
