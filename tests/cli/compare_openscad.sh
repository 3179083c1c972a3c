#!/usr/bin/env bash
# Render every model under tests/models and models/ with rayscad and with the
# real openscad binary (its preview PNG, under xvfb), same flags, and compare
# the object masks: IoU >= 0.99 outside a one-pixel band at the silhouette.
# The flags come from the model's "// args:" line (none: OpenSCAD's defaults
# at 512x512).  Images and mask diffs of each run stay in BUILD/compare/.
#   usage: tests/cli/compare_openscad.sh [BUILD] [model.scad ...]
set -u
build=${1:-build}
shift || true
rayscad=$build/rayscad
maskcmp=$build/tools/maskcmp
out=$build/compare
mkdir -p "$out"
if [ $# -gt 0 ]; then models=("$@"); else models=(tests/models/*.scad models/*.scad); fi

passed=0
failed=0
# Judge $out/NAME.png against $out/NAME.ref.png: mask IoU >= 0.99.
judge() {
    local res
    if res=$("$maskcmp" "$out/$1.png" "$out/$1.ref.png" --min-iou 0.99 --diff "$out/$1.diff.png"); then
        echo "ok   $1: $res"
        passed=$((passed + 1))
    else
        echo "FAIL $1: $res"
        failed=$((failed + 1))
    fi
}
for m in "${models[@]}"; do
    name=$(basename "$m" .scad)
    args=$(sed -n 's|^// args: *||p' "$m" | head -n 1)
    [ -n "$args" ] || args="--imgsize=512,512"
    # shellcheck disable=SC2086
    if ! timeout 300 xvfb-run -a openscad -o "$out/$name.ref.png" $args "$m" \
            >"$out/$name.openscad.log" 2>&1; then
        echo "FAIL $name: openscad failed (see $out/$name.openscad.log)"
        failed=$((failed + 1))
        continue
    fi
    # shellcheck disable=SC2086
    if ! timeout 300 "$rayscad" "$m" -o "$out/$name.png" $args >"$out/$name.rayscad.log" 2>&1; then
        echo "FAIL $name: rayscad failed: $(tail -n 3 "$out/$name.rayscad.log")"
        failed=$((failed + 1))
        continue
    fi
    judge "$name"
done
# Framing: a model clipped by a huge box (a common idiom) must be framed as
# what is drawn.  openscad frames the box and draws a speck or nothing, so
# the truth is openscad's picture of the drawn part alone.
if [ $# -eq 0 ]; then
    while IFS='|' read -r name clipped alone; do
        printf '%s\n' "$clipped" >"$out/$name.scad"
        printf '%s\n' "$alone" >"$out/$name.alone.scad"
        if ! timeout 300 xvfb-run -a openscad -o "$out/$name.ref.png" --imgsize=320,240 \
                "$out/$name.alone.scad" >"$out/$name.openscad.log" 2>&1 ||
            ! "$rayscad" "$out/$name.scad" -o "$out/$name.png" --imgsize=320,240 \
                >"$out/$name.rayscad.log" 2>&1; then
            echo "FAIL $name: a run failed (see $out/$name.*.log)"
            failed=$((failed + 1))
        else
            judge "$name"
        fi
    done <<'CASES'
frame_clip_3d|intersection() { sphere(5, $fn = 24); cube(1e10, center = true); }|sphere(5, $fn = 24);
frame_clip_half|intersection() { union() { cylinder(r = 10, h = 5); translate([30, 0, 0]) cube(8); } translate([-1e6, -1e6, 0]) cube([2e6, 2e6, 2]); }|cylinder(r = 10, h = 2); translate([30, 0, 0]) cube([8, 8, 2]);
frame_clip_2d|linear_extrude(3) intersection() { circle(4, $fn = 30); square(1e9, center = true); }|linear_extrude(3) circle(4, $fn = 30);
CASES
fi
echo "compare: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
