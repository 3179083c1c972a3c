#!/bin/bash
# valgrind.sh — runs the demos (models/*.scad, at 32×24 pixels, with their own
# `// args:` flags) under valgrind memcheck, and fails on any invalid read or
# write, use of uninitialised memory, or definite leak.  Not part of `make test`
# (it takes minutes); run it by hand on a build without sanitizers:
#
#   tests/cli/valgrind.sh [BUILD] [FILE.scad ...]    (default build, models/*.scad)
#
# Leaks of the libraries rayscad loads (fontconfig, OpenImageIO's plugin caches)
# are "still reachable" or "possibly lost" and are not counted: only
# "definitely lost" and "indirectly lost" blocks fail a run.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
shift || true
bin="$root/$build/rayscad"
[ -x "$bin" ] || { echo "valgrind.sh: no $bin (make BUILD=$build first)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "valgrind.sh: valgrind is not installed" >&2; exit 1; }
if [ $# -gt 0 ]; then files=("$@"); else files=("$root"/models/*.scad); fi

work=$(mktemp -d "${TMPDIR:-/tmp}/rayscad-valgrind.XXXXXX")
trap 'rm -rf "$work"' EXIT
failed=0
for f in "${files[@]}"; do
    name=$(basename "$f" .scad)
    args=$(sed -n 's|^// args: *||p' "$f" | head -n 1)
    log="$work/$name.log"
    # shellcheck disable=SC2086
    valgrind --error-exitcode=99 --suppressions="$root/tests/cli/valgrind.supp" --leak-check=full \
        --errors-for-leak-kinds=definite,indirect \
        --show-leak-kinds=definite,indirect --log-file="$log" \
        "$bin" "$f" -o "$work/$name.png" $args --imgsize=32,24 --threads=2 >/dev/null 2>"$work/$name.err"
    rc=$?
    summary=$(grep -m1 'ERROR SUMMARY' "$log" | sed 's/^==[0-9]*== //')
    if [ $rc -ne 0 ]; then
        echo "FAIL $f: exit $rc, $summary"
        grep -E -A12 'Invalid|uninitialised|definitely lost in|indirectly lost in' "$log" | head -n 60
        head -c 400 "$work/$name.err"
        failed=$((failed + 1))
    else
        echo "ok   $f: $summary"
    fi
done
echo "valgrind.sh: ${#files[@]} files, $failed failed"
[ $failed -eq 0 ]
