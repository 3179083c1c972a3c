#!/usr/bin/env bash
# Every option of `openscad --help` (2021.01), run on the same files by the
# real openscad and by rayscad: the outputs, messages and exit statuses that
# openscad's users rely on must agree (README.md has the table).  Where the
# two differ on purpose the check says so.  Meshes are compared by volume
# (build/tools/meshcmp), images by silhouette (build/tools/maskcmp; openscad
# under xvfb-run).
#   usage: tests/cli/openscad_flags.sh [BUILD]
set -u
. "$(dirname "$(realpath "$0")")/../lib.sh" # check, summary
build=${1:-build}
rayscad=$(realpath "$build/rayscad")
meshcmp=$(realpath "$build/tools/meshcmp")
maskcmp=$(realpath "$build/tools/maskcmp")
root=$PWD
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
umask 022

if ! command -v openscad >/dev/null; then
    echo "openscad_flags: openscad not found (make deps installs it)"
    exit 1
fi

# Both programs on the same arguments, in folders of their own with the same
# files: o/ for openscad, r/ for rayscad; stdout, stderr and status kept.
both() {
    rm -rf o r
    mkdir o r
    cp -- *.scad *.stl *.dat *.json o/ 2>/dev/null
    cp -- *.scad *.stl *.dat *.json r/ 2>/dev/null
    (cd o && openscad "$@" >out.txt 2>err.txt)
    orc=$?
    (cd r && "$rayscad" "$@" >out.txt 2>err.txt)
    rrc=$?
}
same_status() { [ "$orc" -eq 0 ] && [ "$rrc" -eq 0 ] || { [ "$orc" -ne 0 ] && [ "$rrc" -ne 0 ]; }; }
same_file() { cmp -s "o/$1" "r/$1"; }
same_volume() { "$meshcmp" "r/$1" "o/$1" --volume-only >/dev/null; }
# The ECHO and WARNING lines a run printed on stderr (openscad adds its own
# progress lines, rayscad its own notes).
said() { grep -E '^(ECHO|WARNING|DEPRECATED|TRACE):' "$1/err.txt"; }
same_said() { diff <(said o) <(said r) >/dev/null; }

cat >p.scad <<'EOF'
echo(preview = $preview, t = $t);
if ($preview) cube(2); else sphere(1, $fn = 16);
EOF
cat >w.scad <<'EOF'
echo("a");
cube(a = 1);
echo("b");
EOF
cat >params.scad <<'EOF'
module m(a = 1) echo(a = a);
m(b = 2);
cylinder(r = -1, h = 1);
cube([1, -1, 1]);
sphere(d = -4);
square(0);
circle(r = 0);
cube(2);
EOF
printf 'include <inc.scad>\nimport("ring.stl");\nsurface("s.dat");\necho(v);\n' >dep.scad
printf 'v = 5;\n' >inc.scad
printf '1 2\n3 4\n' >s.dat
printf 'solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n' >ring.stl # a tetrahedron, outward

# -o, repeatable: every output of one run.  openscad 2021.01 crashes on
# some pairs (-o x.echo -o y.csg), so its reference is one run per output.
# (It also writes a .csg beside the input file, not in the working folder:
# the input is copied in.)
rm -rf o r && mkdir o r && cp p.scad o/ && cp p.scad r/
(cd o && openscad -o a.echo p.scad && openscad -o b.csg p.scad && openscad -o a.stl p.scad) \
    >/dev/null 2>&1
(cd r && "$rayscad" -o a.echo -o b.csg -o a.stl -o b.off p.scad >/dev/null 2>err.txt)
rrc=$?
check "-o four times: one run writes them all" \
    sh -c "[ $rrc -eq 0 ] && [ -s r/a.echo ] && [ -s r/b.csg ] && [ -s r/a.stl ] && [ -s r/b.off ]"
check "-o four times: the .echo openscad writes alone" same_file a.echo
check "-o four times: the .csg openscad writes alone" same_file b.csg
check "-o four times: the STL's volume as openscad's (render: the sphere)" same_volume a.stl
check "-o four times: the OFF holds the same mesh" \
    sh -c "'$meshcmp' r/b.off o/a.stl --volume-only >/dev/null"

# --export-format and -o -.
both --export-format echo -o - p.scad
check "-o - --export-format echo: the same stdout" cmp -s o/out.txt r/out.txt
both -o - p.scad
check "-o - without a format fails in both" sh -c "[ $orc -ne 0 ] && [ $rrc -ne 0 ]"
check "-o - without a format: openscad's words" grep -q "Either add a valid suffix" r/err.txt
both --export-format binstl -o x.foo p.scad
check "--export-format binstl: binary STL whatever the name" \
    sh -c "! head -c 5 r/x.foo | grep -q solid && ! head -c 5 o/x.foo | grep -q solid"
both --export-format asciistl -o x.stl p.scad
check "--export-format asciistl: text STL" sh -c "head -c 5 r/x.stl | grep -q solid"
check "--export-format asciistl: volume as openscad's" same_volume x.stl
both -o x.stl p.scad
check "STL is text by default in both" \
    sh -c "head -c 5 r/x.stl | grep -q solid && head -c 5 o/x.stl | grep -q solid"
both --export-format foo -o x.stl p.scad
check "--export-format foo fails in both" sh -c "[ $orc -ne 0 ] && [ $rrc -ne 0 ] && [ ! -e r/x.stl ]"
check "--export-format foo: openscad's words" grep -q "Unknown --export-format option 'foo'" r/err.txt

# - as the input: the model from stdin, named <stdin>.
rm -rf o r && mkdir o r && cp w.scad o/ && cp w.scad r/
(cd o && openscad -o x.echo - <w.scad >/dev/null 2>&1)
(cd r && "$rayscad" -o x.echo - <w.scad >/dev/null 2>&1)
check "- reads stdin: the same .echo" same_file x.echo

# .ast (the parse printed back, with the customizer's annotations) and
# .term (the CSG term text, which 2021.01 builds without geometry: empty).
cat >ast.scad <<'EOF'
/* [Size] */
// The width
width = 10; // [1:50]
shape = "box"; // [box, ball]
flag = true;
include <inc.scad>
module part(w) { if (w > 5) cube(w); else { sphere(w); } }
function half(x) = x / 2;
!part(width);
*sphere(1);
v2 = [for (i = [0:2]) if (i % 2) i * v];
EOF
printf '{"parameterSets": {"big": {"width": "30", "shape": "ball", "flag": "false"}}, "fileFormatVersion": "1"}\n' >ast.json
printf 'cube(\n' >bad.scad
both -o x.ast ast.scad
check ".ast: the file openscad writes" same_file x.ast
both -D width=20 -D 'extra="x"' -o x.ast ast.scad
check ".ast with -D: the values where openscad puts them" same_file x.ast
both -p ast.json -P big -o x.ast ast.scad
check ".ast with -p/-P: the parameter set's values" same_file x.ast
both -o x.term ast.scad
check ".term: the file openscad writes" same_file x.term
both --export-format ast -o - ast.scad
check "--export-format ast -o -: the same stdout" cmp -s o/out.txt r/out.txt
both --export-format term -o - ast.scad
check "--export-format term -o -: the same stdout" cmp -s o/out.txt r/out.txt
both --animate 2 -o f.ast ast.scad
check "--animate 2 -o f.ast: each frame as openscad's (\$t is no -D line)" \
    sh -c "cmp -s o/f00000.ast r/f00000.ast && cmp -s o/f00001.ast r/f00001.ast"
for ext in ast term; do
    both -o "x.$ext" bad.scad
    check ".$ext of a syntax error: fails in both, no file" \
        sh -c "[ $orc -ne 0 ] && [ $rrc -ne 0 ] && [ ! -e o/x.$ext ] && [ ! -e r/x.$ext ]"
done

# $preview: true for images and .echo, false for meshes and --render images.
both -o x.stl p.scad
check "\$preview false for a mesh, as openscad" same_said
if command -v xvfb-run >/dev/null; then
    rm -rf o r && mkdir o r
    (cd o && xvfb-run -a openscad --render -o x.png --imgsize=200,200 ../p.scad >out.txt 2>err.txt)
    (cd r && "$rayscad" --render -o x.png --imgsize=200,200 ../p.scad >out.txt 2>err.txt)
    check "--render: \$preview false for the image" same_said
    check "--render: the same silhouette (the sphere)" \
        sh -c "'$maskcmp' r/x.png o/x.png --min-iou 0.99 >/dev/null"
    rm -rf o r && mkdir o r
    (cd o && xvfb-run -a openscad --preview -o x.png --imgsize=200,200 ../p.scad >out.txt 2>err.txt)
    (cd r && "$rayscad" --preview -o x.png --imgsize=200,200 ../p.scad >out.txt 2>err.txt)
    check "--preview: \$preview true for the image" same_said
    check "--preview: the same silhouette (the cube)" \
        sh -c "'$maskcmp' r/x.png o/x.png --min-iou 0.99 >/dev/null"
    # --animate 10 of the bundled animation (its camera follows $t too):
    # frames named as openscad names them, each openscad's silhouette.
    # openscad 2021.01 stops after two PNG frames under Xvfb (an X error),
    # so each reference frame is its own run at that $t.
    "$rayscad" --animate 10 -o f.png --imgsize=160,120 "$root/models/animated.scad" >/dev/null 2>&1
    ok=1
    for i in 0 1 2 3 4 5 6 7 8 9; do
        xvfb-run -a openscad -o "ref$i.png" --imgsize=160,120 -D "\$t=$i/10" \
            "$root/models/animated.scad" >/dev/null 2>&1
        "$maskcmp" "f0000$i.png" "ref$i.png" --min-iou 0.99 >/dev/null || ok=0
    done
    check "--animate 10: ten frames, each openscad's silhouette at its \$t" test "$ok" -eq 1
fi
both --animate 3 -o f.stl p.scad
check "--animate 3: frames f00000.stl .. f00002.stl in both" \
    sh -c "ls o/f0000?.stl | sed 's|o/||' >o.txt; ls r/f0000?.stl | sed 's|r/||' >r.txt; cmp -s o.txt r.txt && [ \$(wc -l <r.txt) -eq 3 ]"
check "--animate 3: \$t = 0, 1/3, 2/3 as openscad" same_said

# Every mesh format we write, imported by openscad: the same volume as ours
# (its STL export of import("ours.EXT") against our STL of the model).
printf 'difference() { cube(10, center = true); sphere(6); }\n' >solid.scad
"$rayscad" -o ours.stl solid.scad --mesh-size 0.5 >/dev/null 2>&1
for ext in stl off amf 3mf; do
    "$rayscad" -o "ours.$ext" solid.scad --mesh-size 0.5 >/dev/null 2>&1
    printf 'import("ours.%s");\n' "$ext" >reimport.scad
    rm -f back.stl
    openscad -o back.stl reimport.scad >/dev/null 2>&1
    check "openscad imports our .$ext with our volume" \
        sh -c "'$meshcmp' back.stl ours.stl --volume-only --vol-tol 0.5 >/dev/null"
done

# 2D exports: SVG and DXF as openscad writes them (byte for byte where the
# region is the same), and a 3D model refused with its words.
printf 'difference() { square(10); translate([5, 5]) circle(3); }\nsquare([4, 20]);\n' >flat.scad
for ext in svg dxf; do
    both -o "x.$ext" flat.scad
    check "2D .$ext: the file openscad writes" same_file "x.$ext"
done
both -o x.svg p.scad
check "2D export of a 3D model fails in both, in openscad's words" \
    sh -c "[ $orc -ne 0 ] && [ $rrc -ne 0 ] && grep -q 'Current top level object is not a 2D object.' r/err.txt && [ ! -e r/x.svg ]"

# PDF: openscad's A4 page (rulers, scale note, the outlines stroked, not
# filled), both rasterised by pdftoppm at 300 dpi in grey.  The page size
# pdfinfo reads; the outlines, the only ink darker than 128 (the rulers and
# type are 40 % grey), within IoU 0.99 outside a one-pixel band (maskcmp
# --ink); and where the region is openscad's to the bit, every pixel of the
# page.  hole and poly sit at the page's corner, circle and mixed at its
# centre; the text's glyphs differ from openscad's by about 0.01 mm, so its
# page is compared by the outlines only.
printf 'difference() { square(20); translate([5, 5]) square(10); }\n' >hole.scad
printf 'translate([-20, 10]) circle(r = 25, $fn = 48);\n' >circle.scad
printf 'polygon([[0, 0], [60, 0], [60, 40], [0, 40], [10, 10], [25, 10], [25, 30], [10, 30],
         [35, 10], [50, 10], [42, 30]], paths = [[0, 1, 2, 3], [4, 5, 6, 7], [8, 9, 10]]);\n' >poly.scad
printf 'difference() { offset(r = 3, $fn = 24) square([40, 20], center = true); circle(5, $fn = 30); }
translate([0, 40]) rotate(17) square([15, 8]);\n' >mixed.scad
printf 'text("Hello", size = 10, font = "Liberation Sans");\n' >hello.scad
printf 'translate([-150, -20]) square([400, 30]);\n' >wide.scad
if command -v pdftoppm >/dev/null && command -v pdfinfo >/dev/null; then
    for m in hole circle poly mixed hello wide; do
        both -o x.pdf "$m.scad"
        check "2D .pdf ($m): written by both" \
            sh -c "[ $orc -eq 0 ] && [ $rrc -eq 0 ] && [ -s o/x.pdf ] && [ -s r/x.pdf ]"
        check "2D .pdf ($m): openscad's page size" \
            sh -c "pdfinfo o/x.pdf | grep '^Page size' >o.txt && pdfinfo r/x.pdf | grep '^Page size' >r.txt && grep -q '595 x 842' r.txt && cmp -s o.txt r.txt"
        pdftoppm -r 300 -gray -png o/x.pdf o/page >/dev/null 2>&1
        pdftoppm -r 300 -gray -png r/x.pdf r/page >/dev/null 2>&1
        check "2D .pdf ($m): openscad's outlines (IoU >= 0.99)" \
            sh -c "'$maskcmp' r/page-1.png o/page-1.png --ink 128 --min-iou 0.99 >/dev/null"
        [ "$m" = hello ] ||
            check "2D .pdf ($m): every pixel of openscad's page" cmp -s o/page-1.png r/page-1.png
    done
    check "2D .pdf (wide): openscad's warning that it passes the page" \
        sh -c "grep -q '^EXPORT-WARNING: Geometry is too large to fit into A4 size.' o/err.txt && grep -q '^EXPORT-WARNING: Geometry is too large to fit into A4 size.' r/err.txt"
    both -o x.pdf hole.scad
    check "2D .pdf: no warning for a page it fits" sh -c "! grep -q EXPORT-WARNING r/err.txt"
    both --export-format pdf -o - circle.scad
    check "--export-format pdf -o -: a PDF on stdout, pixels as openscad's" \
        sh -c "head -c 5 r/out.txt | grep -q '%PDF-' && pdftoppm -r 72 -gray o/out.txt o/s && pdftoppm -r 72 -gray r/out.txt r/s && cmp -s o/s-1.pgm r/s-1.pgm"
else
    check "pdftoppm and pdfinfo installed (poppler-utils; make deps)" false
fi
both -o x.pdf p.scad
check "2D .pdf of a 3D model fails in both, in openscad's words, no file" \
    sh -c "[ $orc -ne 0 ] && [ $rrc -ne 0 ] && grep -q 'Current top level object is not a 2D object.' r/err.txt && [ ! -e r/x.pdf ]"
printf 'not a pdf\n' >r/kept.pdf
(cd r && "$rayscad" -o kept.pdf p.scad >/dev/null 2>&1)
check "2D .pdf of a 3D model leaves an existing file as it was" grep -qx 'not a pdf' r/kept.pdf
(cd r && "$rayscad" -o no/such/dir/x.pdf hole.scad >/dev/null 2>err.txt)
rrc=$?
check "2D .pdf into a missing folder: exit 1, the path named, nothing left" \
    sh -c "[ $rrc -eq 1 ] && grep -q 'error: no/such/dir/x.pdf: ' r/err.txt && [ -z \"\$(find r -name '*.pdf*' ! -name kept.pdf)\" ]"

# Messages: -q, --hardwarnings, --check-parameters, --check-parameter-ranges.
both -q -o x.stl w.scad
check "-q: nothing on stderr but errors" test ! -s r/err.txt
both --hardwarnings -o x.echo w.scad
check "--hardwarnings: the .echo stops at the warning, as openscad's" same_file x.echo
both --hardwarnings -o x.stl w.scad
check "--hardwarnings: a mesh export fails in both" sh -c "[ $orc -ne 0 ] && [ $rrc -ne 0 ]"
both -o x.echo params.scad
check "default checks: the same .echo" same_file x.echo
both --check-parameters=false -o x.echo params.scad
check "--check-parameters=false: the same .echo" same_file x.echo
both --check-parameter-ranges=true -o x.echo params.scad
check "--check-parameter-ranges=true: the same .echo" same_file x.echo
check "--check-parameter-ranges=true: warns of cylinder(r1=-1, r2=-1, ...)" \
    grep -q "cylinder(r1=-1, r2=-1, ...)" r/x.echo

# --colorscheme: a wrong name lists the schemes, in openscad's order.
both --colorscheme=Foo -o x.png p.scad
check "--colorscheme=Foo fails in both" sh -c "[ $orc -ne 0 ] && [ $rrc -ne 0 ]"
check "--colorscheme=Foo: the same schemes listed" \
    sh -c "grep -v 'rayscad:' r/err.txt | diff - o/err.txt >/dev/null"

# -d and -m.
both -d x.d -o x.stl dep.scad
check "-d: the same files (fonts aside), files absolute, the input as given" \
    sh -c "tr -d '\\\\' <o/x.d | tr -s ' \t' '\n' | sed 's|$tmp/o/||' | sort >o.deps;
           tr -d '\\\\' <r/x.d | tr -s ' \t' '\n' | sed 's|$tmp/r/||' | sort >r.deps; cmp -s o.deps r.deps"
printf 'import("made.stl");\n' >mk.scad
printf '#!/bin/sh\ncp "$(dirname "$1")/ring.stl" "$1"\necho "$1" >made.txt\n' >mk.sh
chmod +x mk.sh
rm -rf o r && mkdir o r && cp mk.scad mk.sh ring.stl o/ && cp mk.scad mk.sh ring.stl r/
(cd o && openscad -m ./mk.sh -o x.stl mk.scad >/dev/null 2>&1)
(cd r && "$rayscad" -m ./mk.sh -o x.stl mk.scad >/dev/null 2>&1)
check "-m: make ran for the missing import with the path openscad gives" \
    sh -c "sed 's|/o/|/|' o/made.txt >a.txt; sed 's|/r/|/|' r/made.txt >b.txt; cmp -s a.txt b.txt"
check "-m: the made file is imported" same_volume x.stl

# --view: the lines each part adds, against openscad's (within a pixel,
# both ways).  Edges on a polyhedral model only: openscad outlines every
# facet of its tessellation, rayscad the creases of the exact surface.
if command -v xvfb-run >/dev/null; then
    cat >v.scad <<'EOV'
cube(10);
translate([14, 0, 0]) rotate([0, 0, 30]) cube([6, 8, 4]);
translate([-8, -8, 0]) cube([5, 5, 12]);
EOV
    view() { # program, flags...: o/ or r/ gets <flags>.png
        local who=$1
        shift
        if [ "$who" = o ]; then
            (cd o && xvfb-run -a openscad ../v.scad -o "x$*.png" --imgsize=400,300 "$@" >/dev/null 2>&1)
        else
            (cd r && "$rayscad" ../v.scad -o "x$*.png" --imgsize=400,300 "$@" >/dev/null 2>&1)
        fi
    }
    rm -rf o r
    mkdir o r
    view o
    view r
    for v in axes axes,scales edges; do
        view o "--view=$v"
        view r "--view=$v"
        check "--view=$v: openscad's lines" \
            "$root/tests/cli/viewcmp.py" o/x.png "o/x--view=$v.png" r/x.png "r/x--view=$v.png"
    done
    view o --view=wireframe
    view r --view=wireframe
    check "--view=wireframe: the image unchanged, as openscad's" \
        sh -c "cmp -s r/x.png r/x--view=wireframe.png && oiiotool --diff o/x.png o/x--view=wireframe.png >/dev/null"
fi

# Accepted flags: --csglimit, --debug, --preview=throwntogether,
# -s, --info, -h, -v.
both --csglimit=5 -o x.stl p.scad
check "--csglimit: accepted, the same mesh" same_volume x.stl
both --debug=all -o x.stl p.scad
check "--debug: accepted by both" same_status
both -s s.stl p.scad
check "-s: writes the file, as -o" same_volume s.stl
check "-s: openscad's DEPRECATED line" \
    sh -c "grep DEPRECATED o/err.txt >a.txt; grep DEPRECATED r/err.txt | cmp -s a.txt -"
both --info # openscad 2021.01 exits 1 after printing it
check "--info: exits 0" test "$rrc" -eq 0
for lib in lib3mf freetype harfbuzz fontconfig cairo; do
    check "--info: the $lib version openscad reports" \
        sh -c "v=\$(grep -i '^$lib version' o/out.txt | grep -o '[0-9][0-9.]*[0-9]' | head -1); [ -n \"\$v\" ] && grep -i '^$lib' r/out.txt | grep -q \"\$v\""
done
both --help
check "--help: exits 0 in both" same_status
both --version
check "--version: exits 0 in both" same_status

summary openscad_flags
