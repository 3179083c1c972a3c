#!/bin/bash
# hostile.sh — runs rayscad on every file of the hostile corpus (tests/hostile/*.scad)
# and on every .scad under /usr/share/openscad/examples, rendering a 64×48 PNG with a
# per-file timeout, and checks that each run either succeeds or fails cleanly:
#
#   - exit status 0 or 1: never a signal, never 124 (the timeout), never 2;
#   - a failure says why on stderr: a "file:line:col: error:" line, or rayscad's own
#     "rayscad: error:" line for I/O;
#   - no sanitizer report ("ERROR: AddressSanitizer", "ERROR: LeakSanitizer",
#     "runtime error:") — under the asan build these come with a non-zero exit;
#   - a failed run leaves no output file behind (each run gets a fresh path), and
#     for every third file an existing output is pre-created and must be
#     byte-identical after a failed run;
#   - the files in MUST_FAIL do fail (so the checks above are exercised), and
#     those in MUST_PASS render.
# Each run has --max-steps 1e7: the default (1e9) is set for real library code,
# and runaway input would take minutes to reach it.
#
# Usage: tests/cli/hostile.sh [BUILD [PATTERN]]   (default build; the asan build is detected
# and runs with a longer per-file timeout; PATTERN, a shell glob such as 'fuzz_*', runs
# only the corpus files whose name matches it).  Runs as many files at once as there are
# cores.  Exit status 0 when every file passes.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-build}
pattern=${2:-}
bin="$root/$build/rayscad"
[ -x "$bin" ] || { echo "hostile.sh: no $bin (make BUILD=$build first)" >&2; exit 1; }

limit=20
asan=0
if ldd "$bin" 2>/dev/null | grep -q 'libasan'; then asan=1; limit=60; fi
# lib3mf's own leaks are not ours (tests/lsan.supp)
[ $asan -eq 1 ] && export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/lsan.supp:print_suppressions=0}

# Files that must fail (each with a located error), and files that must render
# (a file including itself draws, as in openscad: the inner include is refused).
MUST_FAIL="rec_module rec_function rec_mutual rec_let rec_list_comp rec_module_children
rec_default_arg lex_unterminated_string lex_unterminated_comment
parse_errors assert_fail gen_deep_parens_open gen_deep_brackets_open
gen_garbage_1 str_doubling rec_module_geometry children_deep_chain
list_doubling size_fn_extrude_slices fuzz_concat_doubling fuzz_str_doubling"
MUST_PASS="num_cube_1e300 num_nan_translate num_scale_zero size_zero size_negative
poly_empty poly_open inc_missing inc_cycle_a inc_self loop_1e7 loop_list_1e7 lex_empty mix_union
mix_hull_many import_amf_3mf
mix_minkowski_fine fuzz_minkowski_sphere_fn fuzz_extrude_twist_slices
fuzz_extrude_twist_circle_fn"

work=$(mktemp -d "${TMPDIR:-/tmp}/rayscad-hostile.XXXXXX")
trap 'rm -rf "$work"' EXIT

check_one() { # index file
    local i=$1 f=$2 name out err rc keep=0
    name=$(basename "$f" .scad)
    out="$work/out_$i.png"
    err="$work/err_$i.txt"
    if [ $((i % 3)) -eq 0 ]; then
        keep=1
        printf 'existing output %s\n' "$i" > "$out"
    fi
    local t0=$SECONDS
    (cd "$(dirname "$f")" && ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:intercept_tls_get_addr=0} \
        timeout -k 5 "$limit" "$bin" "$f" -o "$out" --imgsize=64,48 --threads=1 --max-steps 1e7 \
        </dev/null >/dev/null 2>"$err")
    rc=$?
    local dt=$((SECONDS - t0)) why=""
    if grep -qE 'ERROR: (Address|Leak)Sanitizer|runtime error:' "$err"; then
        why="sanitizer report: $(grep -m1 -E 'ERROR: |runtime error:' "$err")"
    elif [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
        why="timed out after ${limit} s"
    elif [ $rc -ge 128 ]; then
        why="killed by signal $((rc - 128))"
    elif [ $rc -ne 0 ] && [ $rc -ne 1 ]; then
        why="exit status $rc: $(head -c 300 "$err")"
    elif [ $rc -eq 1 ]; then
        if ! grep -qE '^[^ :]+:[0-9]+:[0-9]+: error: |^rayscad: error: ' "$err"; then
            why="failed without a located error: $(head -c 300 "$err" | tr '\n' '|')"
        elif [ $keep -eq 1 ]; then
            [ "$(cat "$out" 2>/dev/null)" = "existing output $i" ] ||
                why="a failed run changed the existing output"
        elif [ -e "$out" ]; then
            why="a failed run left an output file"
        fi
    elif [ ! -s "$out" ]; then
        why="exit 0 but no output"
    fi
    if [ -z "$why" ]; then
        case " $(echo $MUST_FAIL) " in *" $name "*) [ $rc -eq 1 ] || why="should fail, exit $rc" ;; esac
        case " $(echo $MUST_PASS) " in *" $name "*) [ $rc -eq 0 ] || why="should render, exit $rc: $(head -c 300 "$err")" ;; esac
    fi
    rm -f "$out"
    if [ -n "$why" ]; then
        echo "FAIL $f: $why"
    else
        echo "ok   $f ($rc, ${dt}s)"
    fi
}
export -f check_one
export work bin limit MUST_FAIL MUST_PASS

if [ -n "$pattern" ]; then
    files=$(ls "$root"/tests/hostile/$pattern.scad 2>/dev/null)
    [ -n "$files" ] || { echo "hostile.sh: no tests/hostile/$pattern.scad" >&2; exit 1; }
    n=$(echo "$files" | wc -l)
else
    files=$( (ls "$root"/tests/hostile/*.scad; find /usr/share/openscad/examples -name '*.scad' 2>/dev/null | sort) )
    n=$(echo "$files" | wc -l)
    [ "$n" -ge 100 ] || { echo "hostile.sh: only $n files found" >&2; exit 1; }
fi
jobs=$(nproc 2>/dev/null || echo 2)

start=$SECONDS
echo "$files" | awk '{print NR " " $0}' |
    xargs -P "$jobs" -L 1 bash -c 'check_one "$0" "$1"' > "$work/results.txt"
failed=$(grep -c '^FAIL' "$work/results.txt")
grep '^FAIL' "$work/results.txt"
slow=$(sed -n 's/^ok .*, \([0-9]*\)s)$/\1/p' "$work/results.txt" | sort -n | tail -1)
echo "hostile.sh: $n files in $((SECONDS - start)) s (slowest ${slow:-0} s), $failed failed"
[ "$failed" -eq 0 ]
