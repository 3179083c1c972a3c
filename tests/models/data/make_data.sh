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
# AMF and 3MF for geo_import_amf_3mf: the part and the prism as openscad
# exports them, and two files written here with what openscad does not
# export: a zipped AMF of two overlapping objects, the second with a vertex
# per triangle corner (as Cura writes them), and a 3MF of two mesh objects
# whose build items carry transforms (2021.01 ignores them)
openscad -o part.amf "$tmp/part.scad" >/dev/null 2>&1
openscad -o hex.3mf "$tmp/hex.scad" >/dev/null 2>&1
/usr/bin/python3 - <<'PY'
import zipfile
def box(o, s):
    v = [(o[0] + s[0] * (i & 1), o[1] + s[1] * (i >> 1 & 1), o[2] + s[2] * (i >> 2 & 1))
         for i in range(8)]
    # counter-clockwise seen from outside
    t = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
         (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
    return v, t
def amf_object(i, v, t):
    s = ' <object id="%d">\n  <color><r>1</r><g>0</g><b>0</b></color>\n  <mesh>\n   <vertices>\n' % i
    for p in v:
        s += '    <vertex><coordinates><x>%g</x><y>%g</y><z>%g</z></coordinates></vertex>\n' % p
    s += '   </vertices>\n   <volume materialid="1">\n'
    for f in t:
        s += '    <triangle><v1>%d</v1><v2>%d</v2><v3>%d</v3></triangle>\n' % f
    return s + '   </volume>\n  </mesh>\n </object>\n'
a = box((0, 0, 0), (10, 8, 6))
v, t = box((6, 4, 3), (8, 8, 8))
soup = [v[i] for f in t for i in f]  # every corner a vertex of its own
b = (soup, [(3 * k, 3 * k + 1, 3 * k + 2) for k in range(len(t))])
amf = ('<?xml version="1.0" encoding="utf-8"?>\n<amf unit="millimeter">\n'
       ' <material id="1"><metadata type="name">red</metadata></material>\n'
       + amf_object(0, *a) + amf_object(1, *b) + '</amf>\n')
with zipfile.ZipFile('two_boxes.amf', 'w', zipfile.ZIP_DEFLATED) as z:
    z.writestr(zipfile.ZipInfo('two_boxes.amf', (2024, 1, 1, 0, 0, 0)), amf)
def model_object(i, v, t):
    s = '  <object id="%d" type="model"><mesh><vertices>\n' % i
    for p in v:
        s += '   <vertex x="%g" y="%g" z="%g"/>\n' % p
    s += '  </vertices><triangles>\n'
    for f in t:
        s += '   <triangle v1="%d" v2="%d" v3="%d"/>\n' % f
    return s + '  </triangles></mesh></object>\n'
c = box((-4, -4, 0), (8, 8, 3))
d = box((-1, -1, 0), (2, 2, 12))
model = ('<?xml version="1.0" encoding="UTF-8"?>\n'
         '<model unit="millimeter" xml:lang="en-US" '
         'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">\n <resources>\n'
         + model_object(1, *c) + model_object(2, *d) + ' </resources>\n <build>\n'
         '  <item objectid="1" transform="1 0 0 0 1 0 0 0 1 50 0 0"/>\n'
         '  <item objectid="2"/>\n </build>\n</model>\n')
types = ('<?xml version="1.0" encoding="UTF-8"?>\n'
         '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
         '<Default Extension="rels" '
         'ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
         '<Default Extension="model" '
         'ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>\n')
rels = ('<?xml version="1.0" encoding="UTF-8"?>\n'
        '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
        '<Relationship Target="/3D/3dmodel.model" Id="rel0" '
        'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>\n')
with zipfile.ZipFile('post.3mf', 'w', zipfile.ZIP_DEFLATED) as z:
    for name, text in (('[Content_Types].xml', types), ('_rels/.rels', rels),
                       ('3D/3dmodel.model', model)):
        z.writestr(zipfile.ZipInfo(name, (2024, 1, 1, 0, 0, 0)), text)
PY
