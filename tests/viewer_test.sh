#!/usr/bin/env bash
# The viewer (rayscad FILE.scad without -o) driven as a user drives it, in a
# real window under Xvfb: xdotool moves the mouse and presses keys, xwd
# takes the window's picture, and tests/viewer/shot.py compares it with what
# `rayscad -o x.png` draws for the same file and camera.
#   usage: tests/viewer_test.sh [BUILD]   (or run inside an X server)
set -u
. "$(dirname "$(realpath "$0")")/lib.sh" # check, summary
build=${1:-build}
rayscad=$(realpath "$build/rayscad")
shot=$(realpath "$(dirname "$0")/viewer/shot.py")
for tool in xdotool xwd xvfb-run; do
    if ! command -v $tool >/dev/null; then
        echo "viewer: $tool not found (make deps installs it)"
        exit 1
    fi
done
if [ -z "${VIEWER_TEST_IN_X:-}" ]; then
    VIEWER_TEST_IN_X=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi
tmp=$(mktemp -d)
cd "$tmp" || exit 1
SIZE=320,240
mkdir model
cat >model/part.scad <<'EOS'
include <inc.scad>
difference() {
    cube(20, center = true);
    sphere(r);
}
color("red") translate([25, 0, 0]) sphere(8);
EOS
echo 'r = 13;' >model/inc.scad

# Without a display: a clear error, exit 2.
env -u DISPLAY "$rayscad" model/part.scad >out.txt 2>err.txt
rc=$?
check "no display: exit 2 with a message" sh -c "[ $rc -eq 2 ] && grep -q 'cannot open a window' err.txt"

"$rayscad" model/part.scad --imgsize=$SIZE --stats >viewer.out 2>viewer.err &
pid=$!
win=""
for _ in $(seq 50); do
    win=$(xdotool search --name '^part.scad - rayscad' 2>/dev/null | head -1)
    [ -n "$win" ] && break
    sleep 0.2
done
check "the window opens, titled with the file's name" test -n "$win"
if [ -z "$win" ]; then
    kill "$pid" 2>/dev/null
    echo "viewer: $passed passed, $failed failed"
    exit 1
fi
settle() { sleep "${1:-2}"; }
grab() { xwd -id "$win" -out "$1"; }
camera() { # the --camera line the c key prints, the last one
    xdotool key --window "$win" c
    sleep 0.5
    grep -- '^--camera=' viewer.out | tail -1
}
settle 3
grab first.xwd
"$rayscad" model/part.scad --imgsize=$SIZE --samples 3 -o first.png
check "the first full frame is the command line's image" "$shot" same first.xwd first.png
check "--stats: the resting picture converges" grep -q '^converged after [0-9]* passes' viewer.err
"$rayscad" model/part.scad --imgsize=$SIZE --samples 8 -o fine.png
check "its passes refine past 3x3 samples a pixel, toward 8x8" "$shot" closer first.xwd first.png fine.png

# A left drag turns the view; the printed camera draws the same picture.
xdotool mousemove --window "$win" 160 120 mousedown 1 mousemove --window "$win" 200 140 \
    mousemove --window "$win" 230 150 mouseup 1
settle
grab turned.xwd
check "a drag changes the view" "$shot" differ first.xwd turned.xwd
cam=$(camera)
"$rayscad" model/part.scad --imgsize=$SIZE --samples 3 -o turned.png "$cam"
check "the printed --camera renders the same picture ($cam)" "$shot" same turned.xwd turned.png
# The wheel zooms; a right drag pans.
xdotool mousemove --window "$win" 160 120 click 4 click 4
settle
xdotool mousemove --window "$win" 160 120 mousedown 3 mousemove --window "$win" 190 120 mouseup 3
settle
grab moved.xwd
cam=$(camera)
"$rayscad" model/part.scad --imgsize=$SIZE --samples 3 -o moved.png "$cam"
check "wheel and right drag: the printed camera agrees" "$shot" same moved.xwd moved.png
check "wheel and right drag change the view" "$shot" differ turned.xwd moved.xwd

# Editing the file, and the file it includes, redraws within a second.
sed -i 's/cube(20/cube(24/' model/part.scad
sleep 1.5
grab edited.xwd
"$rayscad" model/part.scad --imgsize=$SIZE --samples 3 -o edited.png "$cam"
check "an edit of the file redraws it" "$shot" same edited.xwd edited.png
echo 'r = 15;' >inc.tmp && mv inc.tmp model/inc.scad # as editors save: a new file renamed over
sleep 1.5
grab included.xwd
"$rayscad" model/part.scad --imgsize=$SIZE --samples 3 -o included.png "$cam"
check "an edit of an included file redraws it" "$shot" same included.xwd included.png

# A syntax error keeps the last model and says so: title and a red frame.
echo 'cube(;' >>model/part.scad
sleep 1.5
grab broken.xwd
xdotool getwindowname "$win" >title.txt
check "a syntax error is in the title with its file:line:col" \
    grep -q 'part.scad:[0-9]*:[0-9]*: error' title.txt
check "a syntax error frames the picture in red" "$shot" red-frame broken.xwd
check "a syntax error keeps the last model (and says so at the bottom)" \
    "$shot" same broken.xwd included.png --border 5 --top 0.6
check "the error's text is drawn in the window" "$shot" differ broken.xwd included.xwd
check "the error is printed on the terminal too" grep -q 'error' viewer.err

# ? shows the keys over the picture, and hides them again.
xdotool key --window "$win" question
sleep 0.5
grab keys.xwd
xdotool key --window "$win" question
sleep 0.5
grab nokeys.xwd
check "? shows the keys in the window" "$shot" differ broken.xwd keys.xwd
check "? again hides them" "$shot" same nokeys.xwd included.png --border 5 --top 0.6

# Keys: axes on (Ctrl+2) as --view=axes draws them.
sed -i '$d' model/part.scad
sleep 1.5
xdotool key --window "$win" ctrl+2
settle
grab axes.xwd
"$rayscad" model/part.scad --imgsize=$SIZE --samples 3 -o axes.png "$cam" --view=axes
check "Ctrl+2 shows the axes as --view=axes" "$shot" same axes.xwd axes.png
xdotool key --window "$win" s
sleep 1
check "s saves a screenshot" test -s model/part-1.png -o -s part-1.png

# The section plane (v) through the view centre shows the inside of the
# hollow part; the printed --camera and --section draw the same picture.
xdotool key --window "$win" v
settle
grab section.xwd
cut=$(camera)
"$rayscad" model/part.scad --imgsize=$SIZE --samples 3 -o section.png $cut --view=axes
check "v cuts the model open ($cut)" "$shot" same section.xwd section.png
check "the section changes the picture" "$shot" differ axes.xwd section.xwd
xdotool key --window "$win" bracketright
settle
grab section2.xwd
check "] moves the section plane" "$shot" differ section.xwd section2.xwd
xdotool key --window "$win" v

# Deleting the watched file, then its folder, does not stop the viewer.
rm model/part.scad
sleep 1
rm -rf model
sleep 1
check "deleting the watched file and folder: still running" kill -0 "$pid"
xdotool key --window "$win" q
for _ in $(seq 50); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
wait "$pid"
rc=$?
check "q closes the window with exit 0" test "$rc" -eq 0
check "--stats: a line per frame" grep -q '^frame [0-9]*x[0-9]* samples' viewer.err

summary viewer
