#!/usr/bin/env bash
# The rayscad command as a user meets it: exit codes, messages with
# file:line:col, and outputs that are whole or absent.
#   usage: tests/cli_test.sh [BUILD]
set -u
build=${1:-build}
rayscad=$(realpath "$build/rayscad")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
umask 022
passed=0
failed=0

check() { # name, condition (a command)
    local name=$1
    shift
    if "$@"; then
        passed=$((passed + 1))
    else
        echo "FAIL $name"
        failed=$((failed + 1))
    fi
}

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
check "unknown output format is a usage error" test "$rc" -eq 2
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

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
