#!/usr/bin/env bash
# Writes the data files the geo_import and geo_surface models read: meshes
# exported by openscad itself (so the OFF has OpenSCAD's one-line header,
# "OFF nv nf 0"), a text heightmap and a small RGB PNG heightmap.
#   usage: tests/models/data/make_data.sh   (from anywhere; needs openscad)
set -eu
cd "$(dirname "$0")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# a cube with a spherical bite and a hole through it: not convex, with a tunnel
cat >"$tmp/part.scad" <<'SCAD'
difference() {
    cube([16, 12, 10], center = true);
    translate([8, 6, 5]) sphere(6, $fn = 16);
    rotate([90, 0, 0]) cylinder(r = 3, h = 20, center = true, $fn = 12);
}
SCAD
openscad -o part.stl "$tmp/part.scad" >/dev/null 2>&1
# a twisted hexagonal prism, as OFF
echo 'linear_extrude(height = 12, twist = 60, slices = 4) circle(6, $fn = 6);' >"$tmp/hex.scad"
openscad -o hex.off "$tmp/hex.scad" >/dev/null 2>&1
head -c 4 hex.off | grep -q OFF
# heightmap: a comment, a blank line, ragged rows (missing values read as 0)
cat >surface.dat <<'DAT'
# a 7 x 5 heightmap
0 1 2 3 2 1 0
1 3 5 6 5 3 1

2 5 8 9 8 5 2
1 3 5 6 5 3
0 1 2 3 2 1 0
DAT
# an 8 x 6 RGB PNG whose luminance makes a ridge and a pit
/usr/bin/python3 - <<'PY'
import struct, zlib
w, h = 8, 6
rows = []
for y in range(h):
    row = bytearray([0])                                   # filter: none
    for x in range(w):
        r = min(255, 30 * x + 10 * y)
        g = 255 - 35 * abs(x - 4) if y != 2 else 20
        b = (40 * y) % 256
        row += bytes([r, max(0, g), b])
    rows.append(bytes(row))
def chunk(t, d):
    c = struct.pack('>I', len(d)) + t + d
    return c + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
png += chunk(b'IDAT', zlib.compress(b''.join(rows))) + chunk(b'IEND', b'')
open('surface.png', 'wb').write(png)
PY
