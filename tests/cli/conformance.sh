#!/usr/bin/env bash
# Language conformance against the real openscad 2021.01 binary.  For every
# bundled example (/usr/share/openscad/examples/**/*.scad) and every file in
# tests/lang/, both programs write `-o x.echo` and `-o x.csg`:
#   echo: compared line for line (ECHO, WARNING, DEPRECATED lines, and an
#         error's ERROR/TRACE lines);
#   csg:  compared token by token, numbers equal within a relative 1e-9
#         (absolute 1e-12 near zero) and -0 read as 0.
# A mismatch fails unless tests/lang/known_differences.txt lists it, one
# line each: "<file>[:echo|:csg] <reason>" (file as printed below).
# Outputs of each run stay in BUILD/conformance/.
#   usage: tests/cli/conformance.sh [BUILD] [file.scad ...]
set -u
build=${1:-build}
shift || true
rayscad=$build/rayscad
out=$build/conformance
known=tests/lang/known_differences.txt
examples=/usr/share/openscad/examples
mkdir -p "$out"
py=/usr/bin/python3
[ -x "$py" ] || py=python3

if [ $# -gt 0 ]; then
    files=("$@")
else
    files=()
    if [ -d "$examples" ]; then
        while IFS= read -r f; do files+=("$f"); done < <(find "$examples" -name '*.scad' | sort)
    fi
    for f in tests/lang/*.scad; do files+=("$f"); done
fi

# Token-wise comparison of two .csg files (the rule of tests/cli/corpus.py);
# exit 0 when they agree, else prints where they differ.
csgcmp() {
    "$py" - "$1" "$2" "$top/tests/cli" <<'EOF'
import sys
sys.path.insert(0, sys.argv[3])
from corpus import csg_diff, read
why = csg_diff(read(sys.argv[1]), read(sys.argv[2]))
if why:
    print(why)
    sys.exit(1)
EOF
}

is_known() { # file kind
    [ -f "$known" ] || return 1
    grep -qE "^($(printf '%s' "$1" | sed 's/[.[\*^$]/\\&/g'))(:$2)?[[:space:]]" "$known"
}

case $rayscad in /*) ;; *) rayscad=$PWD/$rayscad ;; esac
top=$PWD
jobs=${CONFORMANCE_JOBS:-2}

# One file: writes "<status> <name> (<kind>): <why>" lines to $out/<key>.result
check_one() {
    local f=$1 name key dir base kind ref ours why
    case $f in
    "$examples"/*) name=examples/${f#"$examples"/} ;;
    *) name=$f ;;
    esac
    key=$(printf '%s' "$name" | tr '/' '_')
    dir=$(dirname "$f")
    base=$(basename "$f")
    : >"$out/$key.result"
    for kind in echo csg; do
        ref=$top/$out/$key.ref.$kind
        ours=$top/$out/$key.$kind
        rm -f "$ours"
        # both run in the file's folder: messages and file names are relative to it
        if [ ! -s "$ref" ] || [ "$f" -nt "$ref" ]; then
            rm -f "$ref"
            (cd "$dir" && timeout 120 openscad -o "$ref" "$base") >"$ref.log" 2>&1
            [ -f "$ref" ] || : >"$ref"
        fi
        (cd "$dir" && timeout 120 "$rayscad" "$base" -o "$ours") >"$ours.log" 2>&1
        [ -f "$ours" ] || : >"$ours"
        if [ "$kind" = echo ]; then
            why=$(diff <(grep -aE "^(ECHO|WARNING|DEPRECATED|ERROR|TRACE|Can't parse)" "$ref") \
                <(grep -aE "^(ECHO|WARNING|DEPRECATED|ERROR|TRACE|Can't parse)" "$ours") |
                head -n 4 | tr '\n' ' ')
        else
            why=$(csgcmp "$ref" "$ours")
        fi
        if [ -z "$why" ]; then
            echo "ok $name ($kind)" >>"$out/$key.result"
        elif is_known "$name" "$kind"; then
            echo "known $name ($kind)" >>"$out/$key.result"
        else
            echo "FAIL $name ($kind): $(printf '%s' "$why" | head -c 300)" >>"$out/$key.result"
        fi
    done
}

running=0
for f in "${files[@]}"; do
    check_one "$f" &
    running=$((running + 1))
    if [ $running -ge "$jobs" ]; then
        wait -n
        running=$((running - 1))
    fi
done
wait

passed=0
failed=0
known_hits=0
for f in "${files[@]}"; do
    case $f in
    "$examples"/*) name=examples/${f#"$examples"/} ;;
    *) name=$f ;;
    esac
    key=$(printf '%s' "$name" | tr '/' '_')
    grep -v '^ok ' "$out/$key.result"
    k=$(grep -c '^known ' "$out/$key.result")
    known_hits=$((known_hits + k))
    if grep -q '^FAIL ' "$out/$key.result" || [ "$(grep -c '' "$out/$key.result")" != 2 ]; then
        failed=$((failed + 1))
    else
        passed=$((passed + 1))
    fi
done
echo "files matching openscad (echo and csg, known differences aside): $passed of ${#files[@]}" \
    "($known_hits known differences)"
echo "conformance: $passed passed, $failed failed"
[ $failed = 0 ]
