#!/usr/bin/env bash
# The rayscad command as a user meets it: exit codes, messages with
# file:line:col, and outputs that are whole or absent.
#   usage: tests/cli/cli_test.sh [BUILD]
set -u
. "$(dirname "$(realpath "$0")")/../lib.sh" # check, summary
build=${1:-build}
rayscad=$(realpath "$build/rayscad")
meshcmp=$(realpath "$build/tools/meshcmp")
py=/usr/bin/python3
[ -x "$py" ] || py=python3
root=$PWD
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
umask 022

quiet() { "$@" >/dev/null; }

run() { # run rayscad, keep stderr in err.txt and the exit code in $rc
    "$rayscad" "$@" >out.txt 2>err.txt
    rc=$?
}

printf 'cube(2);\n' >ok.scad
printf 'cube(2);\nsphere(1\n' >syntax.scad
printf 'echo("hi", 1 + 2);\nfoo();\n' >echo.scad

run --help
check "help exits 0" test "$rc" -eq 0
check "help prints usage" grep -q "usage: rayscad" out.txt

# The man page (docs/rayscad.1) and the command agree on the flags: every
# flag --help prints, and every flag the parser names (a string literal
# that is a whole flag in src/cli/options.c: -h and -v are not in --help),
# has an entry of its own under OPTIONS (the tag line after a .TP); every
# --flag the page names anywhere is one the parser accepts, asked of the
# command itself (its "unknown option" error).  Flags are read from the
# page's source with troff's \- and font escapes undone.
flags_py=$(
    cat <<'PY'
import re, subprocess, sys
rayscad, page, source = sys.argv[1:4]
LONG = r"--[a-z][a-z0-9]*(?:-[a-z0-9]+)*(?:-\*)?"  # "--max-*" names a family, no flag
SHORT = r"(?<![A-Za-z0-9-])-[A-Za-z](?![A-Za-z0-9-])"
def flags(text):
    longs = {f for f in re.findall(LONG, text) if not f.endswith("*")}
    return longs | set(re.findall(SHORT, text))
def troff_text(src):
    src = re.sub(r"\\f(?:\(..|\[[^]]*\]|.)", "", src)  # \fB, \fI, \fR, \fP, \f(CW
    return src.replace("\\-", "-").replace("\\c", "").replace("\\&", "")
source_text = troff_text(open(page, encoding="utf-8").read())
documented = flags(source_text)
options = re.search(r"^\.SH OPTIONS\n(.*?)^\.SH ", source_text, re.M | re.S)
entries = flags("\n".join(re.findall(r"^\.TP\n(.*)", options.group(1), re.M))) if options else set()
usage = subprocess.run([rayscad, "--help"], capture_output=True, text=True).stdout
sources = "".join(open(p).read() for p in source.split(":"))
literals = re.findall(r'"(-[A-Za-z]|--[a-z][a-z0-9]*(?:-[a-z0-9]+)*)"', sources)
if sys.argv[4] == "documented":
    missing = sorted(flags(usage) - entries) + sorted(set(literals) - flags(usage) - entries)
    for f in missing:
        print(f"  {f} has no entry under OPTIONS in docs/rayscad.1", file=sys.stderr)
    sys.exit(1 if missing or not literals else 0)
bad = []
for f in sorted(f for f in documented if f.startswith("--")):
    r = subprocess.run([rayscad, f], stdin=subprocess.DEVNULL, capture_output=True, text=True)
    if "unknown option" in r.stderr:
        bad.append(f)
for f in bad:
    print(f"  {f} in docs/rayscad.1 is not a flag rayscad accepts", file=sys.stderr)
sys.exit(1 if bad or not documented else 0)
PY
)
check "the man page lists every flag of --help and of the parser" \
    "$py" -c "$flags_py" "$rayscad" "$root/docs/rayscad.1" "$root/src/cli/options.c:$root/src/cli/options_openscad.c" documented
check "every flag the man page names is accepted by the parser" \
    "$py" -c "$flags_py" "$rayscad" "$root/docs/rayscad.1" "$root/src/cli/options.c:$root/src/cli/options_openscad.c" accepted
check "bash completion offers every flag of --help" "$py" -c '
import re, subprocess, sys
usage = subprocess.run([sys.argv[1], "--help"], capture_output=True, text=True).stdout
flags = set(re.findall(r"(?<![A-Za-z0-9-])(--?[A-Za-z][a-z0-9-]*)", usage))
flags = {f for f in flags if re.match(r"^(-[A-Za-z]|--[a-z][a-z0-9-]*[a-z0-9])$", f)}
text = open(sys.argv[2]).read()
m = re.search(r"flags=\"([^\"]*)\"", text)
offered = set(m.group(1).split()) if m else set()
missing = sorted(flags - offered)
for f in missing: print("  " + f + " is not in docs/rayscad.bash-completion", file=sys.stderr)
sys.exit(1 if missing or not offered else 0)
' "$rayscad" "$root/docs/rayscad.bash-completion"
run --version
check "version exits 0" test "$rc" -eq 0
run ok.scad
check "no -o is a usage error" test "$rc" -eq 2
run ok.scad -o x.png --imgsize=0,5
check "bad imgsize is a usage error" test "$rc" -eq 2
run ok.scad -o x.png --samples nan
check "NaN samples is a usage error" test "$rc" -eq 2
run ok.scad -o x.png --camera=1,2,3
check "3-number camera is a usage error" test "$rc" -eq 2
run ok.scad -o x.png --bogus
check "unknown flag is a usage error" test "$rc" -eq 2
run ok.scad -o x.unknownext
check "unknown output format exits 1, as openscad" test "$rc" -eq 1
check "unknown output format is named" grep -q "x.unknownext" err.txt
check "no file for an unknown output format" test ! -e x.unknownext
run missing.scad -o x.png
check "missing input exits 1" test "$rc" -eq 1
check "missing input names the file" grep -q "missing.scad" err.txt
check "missing input leaves no output" test ! -e x.png

run syntax.scad -o x.png
check "syntax error exits 1" test "$rc" -eq 1
check "syntax error has file:line:col" grep -Eq "^syntax\.scad:[23]:[0-9]+: error: " err.txt

echo "precious" >keep.png
run syntax.scad -o keep.png
check "failed render keeps the existing file" grep -q precious keep.png
check "no temporary file left behind" test -z "$(ls -A | grep -v -e '\.scad$' -e '\.txt$' -e '^keep\.png$')"

run ok.scad -o good.png --imgsize=64,48
check "render exits 0" test "$rc" -eq 0
check "output gets the umask's permissions" test "$(stat -c %a good.png)" = 644
check "render writes a PNG" sh -c "head -c 8 good.png | od -c | grep -q 'P   N   G'"

run echo.scad -o e.echo
check "echo output exits 0" test "$rc" -eq 0
openscad -o ref.echo echo.scad >/dev/null 2>&1
check "echo output matches openscad's" cmp -s e.echo ref.echo

# ---- meshes and --measure ----
printf 'cube([10, 20, 30]);\n' >box.scad
printf 'sphere(r = 10, $fn = 100);\n' >ball.scad
printf 'cube([10, 10, 0.2]);\n' >lone_plate.scad
printf 'difference() { cube([10, 10, 0.2]); translate([5, 5, -1]) cylinder(r = 1, h = 3); }\n' >plate.scad
printf 'cube(1);\ncube(2, center = true);\n' >two.scad
printf 'echo("nothing");\n' >empty.scad

for ext in stl off obj ply; do
    run box.scad -o "box.$ext" --mesh-size 0.5
    check "mesh .$ext exits 0" test "$rc" -eq 0
done
check "mesh output gets the umask's permissions" test "$(stat -c %a box.stl)" = 644
check "ASCII STL by default, as openscad 2021.01" sh -c "head -c 5 box.stl | grep -q solid"
run box.scad -o boxb.stl --mesh-size 0.5 --export-format binstl
check "binstl writes binary STL" sh -c "! head -c 5 boxb.stl | grep -q solid"
# Each format read back through OpenMesh: closed, the same volume and shape.
for ext in off obj ply; do
    check "mesh .$ext reads back as the STL" quiet "$meshcmp" "box.$ext" box.stl --h 0.5 --name "$ext" \
        --vol-tol 1e-6 --hausdorff-cells 1e-4
done
run box.scad -o boxa.stl --ascii --mesh-size 0.5
check "--ascii writes text STL" sh -c "head -c 5 boxa.stl | grep -q solid"
check "--ascii STL reads back" quiet "$meshcmp" boxa.stl box.stl --h 0.5 --vol-tol 1e-6 --hausdorff-cells 1e-4
run box.scad -o boxa.ply --ascii --mesh-size 0.5
check "--ascii writes text PLY" grep -q "format ascii" boxa.ply
run box.scad -o bin.ply --mesh-size 0.5
check "PLY is binary by default" grep -aq "format binary" bin.ply

# --measure against closed forms.  Exact (rays, no grid): a box to rounding,
# its bounds and centre included.
run box.scad --measure --json
check "--measure alone exits 0" test "$rc" -eq 0
check "--json: box volume, area, bounds, centroid exact" "$py" - out.txt <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
ok = abs(m["volume"] - 6000) <= 1e-9 * 6000 and abs(m["area"] - 2200) <= 1e-9 * 2200
ok = ok and all(abs(a - b) <= 1e-9 for a, b in zip(m["bounds"]["min"], [0, 0, 0]))
ok = ok and all(abs(a - b) <= 1e-9 for a, b in zip(m["bounds"]["max"], [10, 20, 30]))
ok = ok and all(abs(a - b) <= 1e-9 for a, b in zip(m["centroid"], [5, 10, 15]))
ok = ok and m["method"] == "exact" and m["tolerance"] == 1e-6 and m["rays"] > 0
sys.exit(0 if ok and not m["empty"] and "mesh" not in m else 1)
PY
run box.scad -o mb.stl --json
check "--measure with a mesh output: exact where it is cheap, and the mesh" "$py" - out.txt <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
ok = m["method"] == "exact" and abs(m["volume"] - 6000) <= 1e-9 * 6000
sys.exit(0 if ok and m["mesh"]["triangles"] == 12 and m["grid_spacing"] > 0 else 1)
PY
run ball.scad --measure --measure-tolerance 1e-8 --json
check "--measure-tolerance: sphere volume and area within 1e-8" "$py" - out.txt <<'PY'
import json, math, sys
m = json.load(open(sys.argv[1]))
v, a = 4 / 3 * math.pi * 1000, 4 * math.pi * 100
ok = abs(m["volume"] - v) <= 1e-8 * v and abs(m["area"] - a) <= 1e-8 * a
sys.exit(0 if ok and m["tolerance"] == 1e-8 else 1)
PY
run box.scad --measure-tolerance 1e-3 -o x.stl
check "--measure-tolerance without --measure is a usage error" sh -c "test $rc -eq 2 && grep -q 'measure-tolerance applies to --measure' err.txt"
run box.scad --measure --measure-tolerance 2
check "--measure-tolerance 2 is a usage error" test "$rc" -eq 2
# --mesh-size alone measures on that grid: the midpoint rule over the rays
# is exact along each ray and converges across them.
run ball.scad --json --mesh-size 0.25
check "--json: sphere volume and area within 0.1 % / 0.5 %" "$py" - out.txt <<'PY'
import json, math, sys
m = json.load(open(sys.argv[1]))
v, a = 4 / 3 * math.pi * 1000, 4 * math.pi * 100
ok = abs(m["volume"] - v) <= 1e-3 * v and abs(m["area"] - a) <= 5e-3 * a
ok = ok and m["grid_spacing"] == 0.25 and all(abs(c) < 1e-6 for c in m["centroid"])
ok = ok and all(abs(x + 10) < 0.01 for x in m["bounds"]["min"])
sys.exit(0 if ok else 1)
PY
run ball.scad -o ball.stl --measure --json --mesh-size 0.3
check "--measure with a mesh reports it, close to the measured volume" "$py" - out.txt <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
sys.exit(0 if m["mesh"]["triangles"] > 1000 and abs(m["mesh"]["volume"] / m["volume"] - 1) < 1e-3 else 1)
PY
run two.scad --measure
check "--measure prints text" grep -q "^volume: *8$" out.txt
check "--measure unions the top-level objects" grep -q "bounding box: *\[-1, -1, -1\] to \[1, 1, 1\]" out.txt
run box.scad -o m.png --imgsize=32,32 --measure
check "--measure with an image output" sh -c "test $rc -eq 0 && test -s m.png && grep -q volume out.txt"

run ball.scad -o dec.stl --decimate 0.05 --mesh-size 0.3
check "--decimate exits 0" test "$rc" -eq 0
check "--decimate makes a smaller mesh" test "$(stat -c %s dec.stl)" -lt "$(stat -c %s ball.stl)"
check "decimated mesh stays closed, close to the sphere" quiet "$meshcmp" dec.stl ball.stl --h 0.1 \
    --vol-tol 0.01
run ball.scad -o tol5.stl --mesh-tolerance 0.05 --mesh-size 0.3
check "--decimate is --mesh-tolerance's older name" cmp -s dec.stl tol5.stl

# --mesh-tolerance: a box is its 12 triangles, as openscad writes it.
run box.scad -o tol.stl --mesh-tolerance 0.01
openscad -o tol_ref.stl box.scad >/dev/null 2>&1
check "--mesh-tolerance: a box is as many triangles as openscad's" \
    test "$(grep -c 'facet normal' tol.stl)" -eq "$(grep -c 'facet normal' tol_ref.stl)"
check "--mesh-tolerance: the box's volume, closed" quiet "$meshcmp" tol.stl tol_ref.stl --h 0.01 \
    --vol-tol 1e-6
for bad in -1 nan abc; do
    run box.scad -o x.stl --mesh-tolerance "$bad"
    check "--mesh-tolerance $bad is a usage error" test "$rc" -eq 2
done

# Without --mesh-tolerance a mesh is simplified to the deviation OpenSCAD's
# facets would give the model (a flat one: 1e-4 of its size); 0 keeps the
# contour as it is.
run box.scad -o def.stl
check "by default a box is as many triangles as openscad's" \
    test "$(grep -c 'facet normal' def.stl)" -eq "$(grep -c 'facet normal' tol_ref.stl)"
run box.scad -o raw.stl --mesh-tolerance 0
check "--mesh-tolerance 0: the contour, unsimplified" \
    test "$(grep -c 'facet normal' raw.stl)" -gt 1000
run ball.scad -o ball0.stl --mesh-tolerance 0 --mesh-size 0.3
check "by default a sphere is simplified (to its facets' 0.0049)" \
    test "$(stat -c %s ball.stl)" -lt "$(stat -c %s ball0.stl)"
check "the default-simplified sphere stays closed, close to the contour" quiet "$meshcmp" \
    ball.stl ball0.stl --h 0.1 --vol-tol 0.001

for bad in 0 -1 nan inf abc; do
    run box.scad -o x.stl --mesh-size "$bad"
    check "--mesh-size $bad is a usage error" test "$rc" -eq 2
done
run box.scad -o x.stl --decimate -1
check "negative --decimate is a usage error" test "$rc" -eq 2
run box.scad -o x.png --ascii
check "--ascii with an image is a usage error" test "$rc" -eq 2
run box.scad -o x.echo --measure
check "--measure with .echo writes both" sh -c "test $rc -eq 0 && test -e x.echo && grep -q volume: out.txt"
run box.scad
check "neither -o nor --measure is a usage error" test "$rc" -eq 2
check "no mesh file from usage errors" test ! -e x.stl

# Thin walls are reported, not silently lost.
run plate.scad -o plate.stl --mesh-size 0.5
check "a plate thinner than h warns" grep -q "warning: walls thinner than the grid spacing 0.5" err.txt
check "a plate lost entirely is an error" test "$rc" -eq 1
check "a lost plate leaves no file" test ! -e plate.stl
run plate.scad -o plate.stl --mesh-size 0.3
check "a plate thinner than h warns on any grid" grep -q "walls thinner than the grid spacing 0.3" err.txt
run plate.scad -o plate.stl
check "a plate 2.5 cells thick does not warn" sh -c "test $rc -eq 0 && test ! -s err.txt"
# A box alone is written as its own faces, however thin.
run lone_plate.scad -o plate.stl --mesh-size 0.5
check "a lone plate is its twelve triangles" \
    sh -c "test $rc -eq 0 && test ! -s err.txt && test \$(grep -c 'facet normal' plate.stl) -eq 12"

# Failed mesh outputs never leave a file behind.
echo "precious" >keep.stl
run syntax.scad -o keep.stl
check "failed mesh keeps the existing file" grep -q precious keep.stl
run empty.scad -o empty.stl
check "empty model is an error for a mesh" test "$rc" -eq 1
check "empty model leaves no file" test ! -e empty.stl
run box.scad -o no/such/dir/x.stl
check "unwritable mesh path exits 1" test "$rc" -eq 1
check "no temporary mesh file left behind" test -z "$(ls -A | grep -e '^\.')"

# A file's top-level $rs_ settings are the flags' equivalents (and flags win).
printf 'color("teal") sphere(8);\ntranslate([14, 0, 0]) cube(6, center = true);\n' >plain.scad
printf '$rs_shadows = true;\n$rs_aperture = 3;\n$rs_focus = 60;\n$rs_samples = 2;\n' >set.scad
cat plain.scad >>set.scad
run plain.scad -o flags.png --imgsize=96,72 --shadows --aperture 3 --focus 60 --samples 2
run set.scad -o file.png --imgsize=96,72
check "\$rs_ settings render as their flags" cmp -s flags.png file.png
run plain.scad -o none.png --imgsize=96,72
check "\$rs_ settings change the image" sh -c "! cmp -s none.png file.png"
run set.scad -o flag_wins.png --imgsize=96,72 --aperture 0.5
run plain.scad -o flag_only.png --imgsize=96,72 --shadows --aperture 0.5 --focus 60 --samples 2
check "a flag wins over the file's setting" cmp -s flag_wins.png flag_only.png
printf '$rs_bounces = 1000;\ncube(1);\n' >bad_setting.scad
run bad_setting.scad -o bad_setting.png --imgsize=32,32
check "an out-of-range setting warns and is ignored" sh -c "test $rc -eq 0 && grep -q 'rs_bounces = 1000 is outside 1..64' err.txt"

# OpenSCAD reads our .csg back: what it writes from it is what it writes
# from the .scad itself, byte for byte.
for m in nested_booleans colors_modifiers geo_linear_extrude geo_polyhedron; do
    src=$root/tests/models/$m.scad
    run "$src" -o "ours_$m.csg"
    openscad -o "again_$m.csg" "ours_$m.csg" >/dev/null 2>&1
    (cd "$(dirname "$src")" && openscad -o "$tmp/ref_$m.csg" "$m.scad" >/dev/null 2>&1)
    check "openscad reads our $m.csg back unchanged" cmp -s "again_$m.csg" "ref_$m.csg"
done

# Evaluation limits from the command line: each a named error at file:line:col.
printf 'function f(n) = n == 0 ? 0 : 1 + f(n - 1);\necho(f(50));\n' >deep.scad
run deep.scad -o deep.echo --max-recursion 20
check "--max-recursion is a named error" sh -c "test $rc -eq 1 && grep -q 'deep.scad:1:.*recursion deeper than 20 calls' err.txt"
run deep.scad -o deep.echo
check "within the default recursion limit" test "$rc" -eq 0
printf 'x = [for (i = [0:999]) for (j = [0:999]) i + j];\necho(len(x));\n' >steps.scad
run steps.scad -o steps.echo --max-steps 5000
check "--max-steps is a named error" sh -c "test $rc -eq 1 && grep -q 'steps.scad:1:.*more than 5000 steps' err.txt"
run steps.scad -o steps.echo --max-list 100
check "--max-list is a named error" sh -c "test $rc -eq 1 && grep -q 'list longer than 100 elements' err.txt"
printf 'echo(len(str("abc", "defgh")));\n' >str.scad
run str.scad -o str.echo --max-string 4
check "--max-string is a named error" sh -c "test $rc -eq 1 && grep -q 'string longer than 4 bytes' err.txt"
run str.scad -o str.echo --max-steps 0
check "a limit of 0 is a usage error" test "$rc" -eq 2

# The error that stops an evaluation is the last thing it says: the
# unwinding (an undef for len(), the next echo) adds no WARNING nor ECHO.
printf 'function d(l, n) = n == 0 ? l : d(concat(l, l), n - 1);\necho(len(d([1], 40)));\necho("after");\n' >stop_steps.scad
run stop_steps.scad -o stop_steps.echo --max-steps 100000
check "a step limit is the only line on stderr" sh -c "test $rc -eq 1 && test \"\$(cat err.txt)\" = 'stop_steps.scad:1:35: error: evaluation took more than 100000 steps (concat)'"
check "a step limit ends the .echo with its trace" sh -c "tail -n 1 stop_steps.echo | grep -qx \"TRACE: called by 'echo' in file stop_steps.scad, line 2\" && ! grep -Eq 'WARNING|ECHO' stop_steps.echo"
printf 'function s(x, n) = n == 0 ? x : s(str(x, x), n - 1);\necho(len(s("ab", 40)));\n' >stop_str.scad
run stop_str.scad -o stop_str.png --max-string 1000
check "a string limit is the only line on stderr" sh -c "test $rc -eq 1 && test \"\$(cat err.txt)\" = 'stop_str.scad:1:35: error: string longer than 1000 bytes (str)'"
printf 'function f(n) = [f(n + 1)];\necho(len(f(0)[0]), undefined_var);\ncube(1);\n' >stop_rec.scad
run stop_rec.scad -o stop_rec.png --max-recursion 50
check "a recursion limit is the only line on stderr" sh -c "test $rc -eq 1 && test \"\$(cat err.txt)\" = \"stop_rec.scad:1:18: error: recursion deeper than 50 calls (calling function 'f')\""

# The output does not depend on the number of threads: the same bytes with
# 1, 2 and 5 workers for an image with every random choice in play
# (antialiasing samples, an area light's soft shadows, a thin lens's depth
# of field, a path-traced image) and for a mesh.  The options must matter,
# or the comparison proves nothing: each image differs from a plain render.
demo=$root/models/demo.scad
look=(--imgsize=96,72 --samples 2 --light=40,-30,60,8 --light-samples 2 --aperture 3 --seed 7)
for t in 1 2 5; do
    run "$demo" -o "det_$t.png" "${look[@]}" --threads=$t
    check "threads=$t: the antialiased, soft-shadowed, defocused image renders" sh -c "test $rc -eq 0 && test -s det_$t.png"
    run "$demo" -o "det_pt_$t.png" --imgsize=48,36 --path-trace=4 --seed 7 --threads=$t
    check "threads=$t: the path-traced image renders" sh -c "test $rc -eq 0 && test -s det_pt_$t.png"
    run "$root/models/gear.scad" -o "det_$t.stl" --threads=$t
    check "threads=$t: the mesh is written" sh -c "test $rc -eq 0 && test -s det_$t.stl"
done
run "$demo" -o det_plain.png --imgsize=96,72 --threads=2
run "$demo" -o det_sharp.png --imgsize=96,72 --samples 2 --light=40,-30,60,8 --light-samples 2 --seed 7 --threads=2
check "the sampled image differs from a plain one" quiet sh -c "! cmp -s det_1.png det_plain.png"
check "--aperture changes the image" quiet sh -c "! cmp -s det_1.png det_sharp.png"
for t in 2 5; do
    check "threads=$t: the image is byte-identical to threads=1" cmp -s det_1.png "det_$t.png"
    check "threads=$t: the path-traced image is byte-identical to threads=1" cmp -s det_pt_1.png "det_pt_$t.png"
    check "threads=$t: the STL is byte-identical to threads=1" cmp -s det_1.stl "det_$t.stl"
done

# Output and memory limits: each a named error that names its flag, exit 1,
# nothing written and an existing output left as it was.
absent_or_kept() { # file: absent, or still holding "precious"
    test ! -e "$1" || grep -qx precious "$1"
}
echo "precious" >kept.png
run ok.scad -o huge.png --imgsize=100000,100000
check "--max-pixels: a huge image is refused by name" sh -c "test $rc -eq 1 && grep -qx 'rayscad: error: image 100000x100000 is 10000000000 pixels, more than --max-pixels 268435456' err.txt"
check "--max-pixels: nothing written" test ! -e huge.png
run ok.scad -o kept.png --imgsize=64,48 --max-pixels 3071
check "--max-pixels N is a named error" sh -c "test $rc -eq 1 && grep -qx 'rayscad: error: image 64x48 is 3072 pixels, more than --max-pixels 3071' err.txt"
check "--max-pixels: the existing file is kept" absent_or_kept kept.png
run ok.scad -o px.png --imgsize=64,48 --max-pixels 3072
check "--max-pixels: an image of exactly N pixels renders" sh -c "test $rc -eq 0 && test -s px.png"
run ok.scad -o wide.png --imgsize=70000,1
check "a side above 65536 pixels is refused" sh -c "test $rc -eq 1 && grep -q 'a side may have at most 65536 pixels' err.txt && test ! -e wide.png"
run ok.scad -o x.png --max-pixels 0
check "--max-pixels 0 is a usage error" test "$rc" -eq 2

# A bar cut by 1500 slots: a ray along it crosses 1500 intervals.
printf 'difference() {\n  cube([15, 4, 4]);\n  for (i = [0:1499]) translate([i * 0.01, -1, -1]) cube([0.005, 6, 6]);\n}\n' >slots.scad
along_x=(--camera=-10,2,2,40,2,2 --imgsize=48,48)
echo "precious" >kept.png
run slots.scad -o kept.png "${along_x[@]}" --max-intervals 1000
check "--max-intervals: a render past it is a named error" sh -c "test $rc -eq 1 && grep -qx 'rayscad: error: render: a ray.s interval list holds more than 1000 intervals (--max-intervals)' err.txt"
check "--max-intervals: the existing image is kept" absent_or_kept kept.png
run slots.scad -o slots.png "${along_x[@]}" --max-intervals 1000 --path-trace=1
check "--max-intervals: so is a path-traced one" sh -c "test $rc -eq 1 && grep -q 'more than 1000 intervals (--max-intervals)' err.txt && test ! -e slots.png"
run slots.scad -o slots.png "${along_x[@]}" --max-intervals 2000
check "--max-intervals: within it the render succeeds" sh -c "test $rc -eq 0 && test -s slots.png"
run slots.scad -o slots.stl --max-intervals 1000
check "--max-intervals: a mesh past it is a named error" sh -c "test $rc -eq 1 && grep -qx 'rayscad: error: a ray.s interval list holds more than 1000 intervals (--max-intervals)' err.txt && test ! -e slots.stl"
run slots.scad --measure --max-intervals 1000
check "--max-intervals: so is --measure" sh -c "test $rc -eq 1 && grep -q '(--max-intervals)' err.txt && test ! -s out.txt"
run slots.scad -o x.png --max-intervals 1.5
check "--max-intervals 1.5 is a usage error" test "$rc" -eq 2

echo "precious" >kept.stl
run box.scad -o kept.stl --mesh-size 0.001
check "--max-mesh-cells: a tiny --mesh-size is a named error" sh -c "test $rc -eq 1 && grep -qx 'rayscad: error: a grid of 10003 x 20003 x 30003 cells (spacing 0.001) is 6003300540027 cells, more than 4294967296 (--max-mesh-cells; a larger --mesh-size needs fewer)' err.txt"
check "--max-mesh-cells: the existing mesh is kept" absent_or_kept kept.stl
run box.scad -o cells.stl --mesh-size 0.5 --max-mesh-cells 62306
check "--max-mesh-cells N is a named error" sh -c "test $rc -eq 1 && grep -qx 'rayscad: error: a grid of 23 x 43 x 63 cells (spacing 0.5) is 62307 cells, more than 62306 (--max-mesh-cells; a larger --mesh-size needs fewer)' err.txt && test ! -e cells.stl"
run box.scad --measure --mesh-size 0.5 --max-mesh-cells 62306
check "--max-mesh-cells: so is --measure" sh -c "test $rc -eq 1 && grep -q '(--max-mesh-cells' err.txt"
run box.scad -o cells.stl --mesh-size 0.5 --max-mesh-cells 62307
check "--max-mesh-cells: a grid of exactly N cells meshes" sh -c "test $rc -eq 0 && test -s cells.stl"

# --max-memory caps the process's data (not enforced under AddressSanitizer,
# which says so).  A list that doubles 24 times (16 M numbers) is within
# --max-list but not within 300M; a 8000x8000 image's buffer alone is 1 GB.
for bad in 0 100K 1X 2G2 -1G nan; do
    run ok.scad -o x.png --max-memory "$bad"
    check "--max-memory $bad is a usage error" test "$rc" -eq 2
done
run ok.scad -o mem_probe.echo --max-memory 1.5G
if grep -q "not enforced" err.txt; then
    echo "skip --max-memory checks: $(head -n 1 err.txt)"
else
    check "--max-memory 1.5G is accepted" sh -c "test $rc -eq 0 && test ! -s err.txt"
    printf 'function d(l, n) = n == 0 ? l : d(concat(l, l), n - 1);\necho(len(d([1], 24)));\n' >biglist.scad
    echo "precious" >kept.png
    run biglist.scad -o kept.png --max-memory 300M --max-steps 1000000000
    check "--max-memory: the evaluator's failure names the node and the limit" sh -c "test $rc -eq 1 && grep -qx 'biglist.scad:1:35: error: out of memory building a vector (more than --max-memory 300M)' err.txt"
    check "--max-memory: the existing file is kept after an evaluation" absent_or_kept kept.png
    run ok.scad -o kept.png --imgsize=8000,8000 --max-memory 300M
    check "--max-memory: an image buffer past it is a named error" sh -c "test $rc -eq 1 && grep -qx 'rayscad: error: out of memory for a 8000x8000 image (more than --max-memory 300M)' err.txt"
    check "--max-memory: the existing file is kept after a render" absent_or_kept kept.png
    run ok.scad -o small.png --imgsize=64,64 --max-memory 300M
    check "--max-memory: a small render fits in 300M" sh -c "test $rc -eq 0 && test -s small.png"
    run ball.scad -o fine.stl --mesh-size 0.05 --max-memory 100M
    check "--max-memory: a mesh past it is a named error" sh -c "test $rc -eq 1 && grep -q '^rayscad: error: .*out of memory.* (more than --max-memory 100M)$' err.txt && test ! -e fine.stl"
    # Nearly a million cubes (a loop over a million is refused, as openscad
    # refuses it) run out of memory in the evaluator wherever the limit
    # falls (a leaf, a node's children, the csg tree, the .csg text): each
    # failure is at the statement being evaluated (the for at 1:1, translate
    # at 1:22, cube at 1:43), never at "?".  A limit that lets the model
    # through fails later, in the renderer or mesher, as rayscad's own error.
    printf 'for (i = [0:999998]) translate([i, 0, 0]) cube();\n' >cubes.scad
    located=0
    for m in 60M 80M 100M 150M 200M; do
        for out in cubes.png cubes.csg cubes.stl; do
            run cubes.scad -o "$out" --imgsize=16,16 --max-memory $m
            if grep -qE "^cubes\.scad:1:(1|22|43): error: out of memory( [a-z ]+)? \(more than --max-memory $m\)$" err.txt; then
                located=$((located + 1))
            else
                check "--max-memory $m: $out fails with a located or named error" sh -c "test $rc -eq 1 && test \$(wc -l <err.txt) -eq 1 && grep -qE '^rayscad: error: .*out of memory.* \(more than --max-memory $m\)$' err.txt"
            fi
        done
    done
    check "--max-memory: the evaluator's out-of-memory errors carry file:line:col" test "$located" -ge 5
    # surface() reads a PNG through OpenImageIO while the limit applies (whose
    # initialisation used to crash below about 100M): it renders, or fails
    # with an error at the surface() call or rayscad's own, never a signal.
    run ok.scad -o height.png --imgsize=8,6
    printf 'surface(file = "height.png");\n' >surface.scad
    for m in 20M 60M 80M 100M 150M 300M; do
        run surface.scad -o surface.png --imgsize=16,16 --max-memory $m
        check "--max-memory $m: surface() of a PNG renders or fails cleanly" sh -c "test $rc -eq 0 -o $rc -eq 1 && { test $rc -eq 0 || grep -qE '^(surface\.scad:1:1|rayscad): error: .*out of memory' err.txt; }"
    done
    run surface.scad -o surface.png --imgsize=16,16 --max-memory 20M
    check "--max-memory: surface() of a PNG past it is an error at the call" sh -c "test $rc -eq 1 && grep -qx 'surface.scad:1:1: error: surface(): height.png: out of memory for a 8x6 image (more than --max-memory 20M)' err.txt"
    run surface.scad -o surface.png --imgsize=16,16 --max-memory 300M
    check "--max-memory 300M: surface() of a PNG renders" sh -c "test $rc -eq 0 && test -s surface.png && ! grep -q WARNING err.txt"
    # children() doubling 30 times stops at a step limit of 10^7 holding about
    # 2 million cube leaves and as many unions: 256 and 48 bytes each since
    # operation nodes leave out the leaf's members (1.07 GB before, 0.66 GB).
    if [ -x /usr/bin/time ]; then
        /usr/bin/time -f %M -o peak.txt "$rayscad" "$root/tests/hostile/children_deep_chain.scad" -o chain.png --imgsize=16,16 --threads=1 --max-steps 1e7 >/dev/null 2>err.txt
        rc=$?
        check "children() doubling stops at the step limit within 800 MB" sh -c "test $rc -eq 1 && grep -q 'more than 10000000 steps' err.txt && test \$(tail -n 1 peak.txt) -lt 800000"
    fi
fi

# A font that cannot be had: OpenSCAD 2021.01 draws nothing for that text()
# and goes on, so it is a warning, not an error.
printf 'text("a", font = ":charset=xxx");\ncube(1);\n' >nofont.scad
run nofont.scad -o nofont.stl
check "text() without a font warns, draws the rest and exits 0" sh -c "test $rc -eq 0 && test -s nofont.stl && grep -q \"WARNING: text(): no font found for ':charset=xxx'; nothing is drawn\" err.txt && ! grep -q 'error:' err.txt"

# Progress of a long evaluation: on a terminal (script(1) gives one) a bar
# with the time spent shows once a second has passed, erased for each ECHO
# line; not with -q, and not when stderr is no terminal.
if command -v script >/dev/null; then
    cat >slow.scad <<'EOF'
function f(n) = n <= 0 ? 0 : 1 + f(n - 1);
for (i = [0:40]) { echo(i, f(5000) + len([for (j = [0:500000]) j])); translate([i, 0, 0]) cube(1); }
EOF
    script -q -c "'$rayscad' slow.scad -o slow.png --imgsize=32,32" /dev/null >tty.txt 2>&1
    check "a long evaluation shows its progress on a terminal" \
        sh -c "grep -q 'evaluating \\[' tty.txt && grep -q '(1 s)' tty.txt && grep -q 'ECHO: 40, 505001' tty.txt"
    script -q -c "'$rayscad' -q slow.scad -o slow.png --imgsize=32,32" /dev/null >tty.txt 2>&1
    check "-q: no progress on a terminal" sh -c "! grep -q 'evaluating' tty.txt"
    "$rayscad" slow.scad -o slow.png --imgsize=32,32 >out.txt 2>err.txt
    check "no progress when stderr is no terminal" sh -c "! grep -q 'evaluating' err.txt"
fi

summary cli
