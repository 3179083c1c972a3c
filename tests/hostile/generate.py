#!/usr/bin/env python3
"""Writes the generated members of the hostile corpus (gen_*.scad, data/*):
deep nesting, very long tokens and deterministic binary garbage.  The output
is committed; run this again only to change it (the seed is fixed, so the
bytes are the same every time)."""
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
DEEP = 50000


def put(name, data):
    path = os.path.join(HERE, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def main():
    rng = random.Random(20261122)
    # nesting the parser and evaluator must refuse or survive, not overflow
    put("gen_deep_parens.scad", "x = " + "(" * DEEP + "1" + ")" * DEEP + ";\necho(x);\n")
    put("gen_deep_parens_open.scad", "x = " + "(" * DEEP + "1;\n")
    put("gen_deep_brackets.scad", "x = " + "[" * DEEP + "1" + "]" * DEEP + ";\necho(len(x));\n")
    put("gen_deep_brackets_open.scad", "[" * DEEP)
    put("gen_deep_braces.scad", "{" * DEEP + "cube();" + "}" * DEEP + "\n")
    put("gen_deep_braces_open.scad", "{" * DEEP + "cube();\n")
    put("gen_deep_unary.scad", "x = " + "-" * DEEP + "1;\necho(x);\ny = " + "!" * DEEP + "true;\n")
    put("gen_deep_ternary.scad", "x = " + "true ? " * (DEEP // 4) + "1" + " : 0" * (DEEP // 4) + ";\necho(x);\n")
    put("gen_deep_transforms.scad", "translate([1, 0, 0]) " * (DEEP // 5) + "cube();\n")
    put("gen_deep_modifiers.scad", "#%" * (DEEP // 2) + "cube();\n")
    put("gen_deep_if.scad", "if (true) " * (DEEP // 4) + "cube();\n")
    put("gen_deep_let.scad", "x = " + "let (a = 1) " * (DEEP // 4) + "a;\necho(x);\n")
    put("gen_deep_index.scad", "x = [1];\necho(x" + "[0]" * DEEP + ");\n")
    put("gen_deep_calls.scad", "function f(x) = x;\necho(" + "f(" * (DEEP // 2) + "1" + ")" * (DEEP // 2) + ");\n")
    put("gen_deep_comprehension.scad",
        "x = " + "[for (i = [0:1]) " * 2000 + "i" + "]" * 2000 + ";\necho(len(x));\n")
    put("gen_deep_functions.scad",
        "".join("function f%d(x) = f%d(x) + 1;\n" % (i, i + 1) for i in range(5000))
        + "function f5000(x) = x;\necho(f0(0));\n")
    put("gen_deep_modules.scad",
        "".join("module m%d() m%d() children();\n" % (i, i + 1) for i in range(5000))
        + "module m5000() children();\nm0() cube();\n")
    put("gen_long_binary.scad", "x = 1" + " + 1" * DEEP + ";\necho(x);\ny = 1" + " ^ 1" * 1000 + ";\n")
    put("gen_many_args.scad", "cube(" + "1, " * DEEP + "1);\necho(" + "a = 1, " * 1000 + "1);\n")
    put("gen_many_statements.scad", "cube();\n" * (DEEP // 5))
    put("gen_many_assignments.scad", "".join("v%d = %d;\n" % (i, i) for i in range(DEEP // 5)) + "echo(v9999);\n")
    # very long tokens
    put("gen_long_identifier.scad", "a" * 100000 + " = 1;\necho(" + "a" * 100000 + ");\n")
    put("gen_long_string.scad", 'echo(len("' + "x" * 200000 + '"));\n')
    put("gen_long_number.scad", "echo(" + "9" * 20000 + ", 0." + "0" * 20000 + "1, 1e" + "9" * 1000 + ");\n")
    put("gen_long_comment.scad", "/*" + "*" * 100000 + "/\ncube();\n//" + "/" * 100000 + "\n")
    # binary garbage: random bytes, random printable soup, NULs in the middle
    for i in range(1, 5):
        put("gen_garbage_%d.scad" % i, bytes(rng.randrange(256) for _ in range(4096 * i)))
    soup = "(){}[]<>;,.=+-*/%!?:#$\"\\ \n\tabcxyz0123456789e"
    for i in range(1, 4):
        put("gen_soup_%d.scad" % i, "".join(rng.choice(soup) for _ in range(8192)))
    put("gen_nul_bytes.scad", b"cube();\n\0\0\0sphere();\n\0echo(\"a\0b\");\n")
    put("gen_utf16.scad", "cube(5);\n".encode("utf-16"))
    # files the hostile imports read (not .scad: the script does not run them)
    put("data/garbage.stl", bytes(rng.randrange(256) for _ in range(2000)))
    put("data/garbage.off", "OFF\n3 1 0\n0 0 nan\ninf 1 0\n0 1\n3 0 1 7\n")
    put("data/huge_counts.off", "OFF\n2000000000 2000000000 0\n0 0 0\n")
    put("data/empty.obj", "")
    put("data/garbage.dat", "1 2 x\n# c\nnan inf -inf\n1e999 3 4\n")
    put("data/ragged.dat", "1 2 3\n4\n5 6 7 8 9\n\n")
    put("data/garbage.png", b"\x89PNG\r\n\x1a\n" + bytes(rng.randrange(256) for _ in range(500)))


if __name__ == "__main__":
    main()
