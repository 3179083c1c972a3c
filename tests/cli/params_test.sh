#!/usr/bin/env bash
# Customizer parameter files, -p FILE.json -P SET, against openscad 2021.01:
# the same .scad and .json through both, `-o x.echo`, and the .echo files
# compared byte for byte; where openscad's output cannot be matched (bad
# JSON worded by json-c, openscad aborting) the exit status class (0 or
# not) and our message.  src/cli/params.c lists the rules measured.
#   usage: tests/cli/params_test.sh [BUILD | path/to/rayscad]
set -u
. "$(dirname "$(realpath "$0")")/../lib.sh" # check, summary
arg=${1:-build}
if [ -d "$arg" ]; then rayscad=$(realpath "$arg/rayscad"); else rayscad=$(realpath "$arg"); fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
ulimit -c 0 # openscad aborts on some files

# Both programs on the same arguments (-o x.echo added): o.echo and orc
# openscad's, r.echo, rrc and r.err ours.
both() {
    rm -f o.echo r.echo
    { timeout 60 openscad -o o.echo "$@" >/dev/null 2>o.err; } 2>/dev/null # "Aborted"
    orc=$?
    timeout 60 "$rayscad" -o r.echo "$@" >/dev/null 2>r.err
    rrc=$?
}

same() { # name, arguments: exit 0 from both and identical .echo files
    local name=$1
    shift
    both "$@"
    check "$name: openscad exits 0" test "$orc" -eq 0
    check "$name: exits 0" test "$rrc" -eq 0
    check "$name: .echo as openscad's" cmp -s o.echo r.echo
}

# ---- the files ----

cat >a.scad <<'EOF'
n = 5;
s = "hello";
b = true;
v = [1, 2, 3];
r = [0:2:10];
u = undef;
echo(n=n, s=s, b=b, v=v, r=r, u=u);
EOF
cat >a.json <<'EOF'
{
    "parameterSets": {
        "good": {"n": "7", "s": "world", "b": "false", "v": "[4, 5, 6]", "r": "[1:1:3]",
                 "u": "undef"},
        "unquoted": {"n": 8, "s": 9, "b": true, "v": [7, 8]},
        "mismatch": {"n": "\"str\"", "s": "[1,2]", "v": "3", "r": "[1,2]", "u": "4"},
        "extra": {"zz": "3", "n": "9"},
        "strings": {"s": "a\"b\\c\nd\te\u00e9\ud83d\ude00"},
        "numbers": {"n": "-1.5e3", "v": "[1, abc 1.23456789, 2:x, \"q r\"]", "r": "[-1 : 0.5 : 1]"},
        "bools": {"b": "+false"},
        "badbool": {"n": "7", "b": "True", "v": "[9]"}
    },
    "fileFormatVersion": "1"
}
EOF

# ---- sets that apply ----

for set in good unquoted mismatch extra strings numbers bools badbool; do
    same "set $set" -p a.json -P "$set" a.scad
done
# an unknown set: no message; the sets themselves are read as the set
same "unknown set" -p a.json -P nosuch a.scad
printf 'good = "str";\nother = 5;\necho(good=good, other=other);\n' >q.scad
printf '{"parameterSets":{"good":{"other":"6"},"other":{"other":"7"}}}\n' >q.json
same "unknown set named like a variable" -p q.json -P nosuch q.scad
# a set overrides -D
same "set after -D" -D n=1 -D 's="dd"' -p a.json -P good a.scad
# a bad boolean stops the rest, in file order
printf 'v = [0];\nb = false;\nn = 1;\necho(n=n, v=v, b=b);\n' >order.scad
same "bad boolean stops in file order" -p a.json -P badbool order.scad
# defaults evaluated with no variables and no builtins, warnings and all
cat >ctx.scad <<'EOF'
k = 2;
a = sin(30);
b = k + 1;
c = 2 * 3;
e = [1, k];
i = "x";
echo(a=a, b=b, c=c, e=e, i=i);
EOF
printf '{"parameterSets": {"s": {"a": "5", "b": "6", "c": "7", "e": "[9]", "i": "[1,2]"}}}\n' >ctx.json
same "defaults in an empty context" -p ctx.json -P s ctx.scad
# -p or -P alone: openscad does nothing
same "-p without -P" -p a.json a.scad
same "-P without -p" -P good a.scad

# ---- files that are no parameter set ----

same "missing file" -p none.json -P good a.scad
printf '{}\n' >empty_object.json
same "root without members" -p empty_object.json -P good a.scad

printf '{ "parameterSets": { "x": \n' >bad.json
both -p bad.json -P good a.scad
check "malformed file: openscad exits 0" test "$orc" -eq 0
check "malformed file: exits 0" test "$rrc" -eq 0
check "malformed file: an ERROR naming the file and line" \
    grep -q "^ERROR: Cannot open Parameter Set 'bad.json': bad.json(2): " r.echo
check "malformed file: the rest as openscad's" \
    cmp -s <(sed 1d o.echo) <(sed 1d r.echo)
printf '{"parameterSets":{"x":{"s":"a",}}}' >comma.json
same "trailing comma" -p comma.json -P x a.scad

printf '{"foo": {"good": {"n": "3"}}}\n' >nosets.json
both -p nosets.json -P good a.scad
check "no parameterSets: openscad aborts" test "$orc" -ne 0
check "no parameterSets: fails without a signal" test "$rrc" -ne 0 -a "$rrc" -lt 128
check "no parameterSets: says so" grep -q "parameterSets" r.err

mkdir folder.json
both -p folder.json -P good a.scad
check "a folder: openscad aborts" test "$orc" -ne 0
check "a folder: fails without a signal" test "$rrc" -ne 0 -a "$rrc" -lt 128
check "a folder: names it" grep -q "folder.json" r.err

summary params
