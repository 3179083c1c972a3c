#!/usr/bin/env bash
# install_test.sh — rayscad installed as a stranger gets it: `make install`
# into a scratch DESTDIR with PREFIX=/usr/local, the build tree's image
# adapter moved out of reach, and then
#   - the installed files: every one the issue lists, and none that names the
#     build tree;
#   - examples/render.c built with `pkg-config --cflags --libs rayscad`
#     against the installed copy, run, and its PNG the same as the installed
#     command's for the same model (so the library found its adapter in
#     lib/rayscad/ by itself);
#   - the installed command rendering with the adapter beside the library;
#   - `man -l` showing the page;
#   - `make uninstall` leaving no file behind.
#   usage: tests/rayscad/install_test.sh [BUILD]
set -u
build=${1:-build}
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root" || exit 1
work=$(mktemp -d "${TMPDIR:-/tmp}/rayscad-install.XXXXXX")
dest=$work/dest
adapter=$build/rayscad-image.so
restore() {
    [ -e "$work/adapter.away" ] && mv "$work/adapter.away" "$adapter"
    rm -rf "$work"
}
trap restore EXIT
passed=0
failed=0
check() { # name, then a command that must succeed
    local name=$1
    shift
    if "$@" >"$work/out.txt" 2>&1; then
        echo "ok   $name"
        passed=$((passed + 1))
    else
        echo "FAIL $name: $(tail -c 600 "$work/out.txt")"
        failed=$((failed + 1))
    fi
}

check "make install" make -s install BUILD="$build" PREFIX=/usr/local DESTDIR="$dest"
mv "$adapter" "$work/adapter.away"
p=$dest/usr/local
check "installed files" test -x "$p/bin/rayscad" -a -f "$p/lib/librayscad.a" \
    -a -f "$p/lib/librayscad.so" -a -f "$p/include/rayscad.h" \
    -a -f "$p/lib/pkgconfig/rayscad.pc" -a -f "$p/lib/rayscad/rayscad-image.so" \
    -a -f "$p/share/man/man1/rayscad.1" -a -f "$p/share/bash-completion/completions/rayscad"
check "no build path in any installed file" bash -c "! grep -rl '$root' '$dest'"

export PKG_CONFIG_PATH=$p/lib/pkgconfig
flags=$(pkg-config --define-prefix --cflags --libs rayscad 2>"$work/pc.err")
check "pkg-config knows rayscad" test -n "$flags"
# shellcheck disable=SC2086
check "examples/render.c builds against the installed library" \
    cc -std=c11 -Wall -Wextra -Werror examples/render.c $flags -o "$work/render"
src='difference() { cube(10, center = true); sphere(6.5); }'
check "the example renders" env LD_LIBRARY_PATH="$p/lib" "$work/render" "$work/example.png" "$src"
printf '%s\n' "$src" > "$work/model.scad"
check "the installed command renders" "$p/bin/rayscad" "$work/model.scad" -o "$work/command.png"
check "the example's PNG is the command's" cmp "$work/example.png" "$work/command.png"
check "man -l shows the page" bash -c "MANWIDTH=80 man -l '$p/share/man/man1/rayscad.1' | grep -q -- '--max-memory'"
# bash's completion, sourced as bash-completion would, offers the flags.
check "bash completes --hardw to --hardwarnings" bash -c "
    source '$p/share/bash-completion/completions/rayscad'
    COMP_WORDS=(rayscad --hardw); COMP_CWORD=1; _rayscad
    [ \"\${COMPREPLY[*]}\" = --hardwarnings ]"
check "make uninstall" make -s uninstall BUILD="$build" PREFIX=/usr/local DESTDIR="$dest"
check "nothing left installed" bash -c "[ -z \"\$(find '$dest' -type f -o -type l)\" ]"

echo "install: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
