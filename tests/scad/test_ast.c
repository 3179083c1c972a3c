/*
 * test_ast.c — the .ast output (src/scad/ast_print.c, annotations.c)
 * against what `openscad -o x.ast` (2021.01) wrote for the same sources,
 * byte for byte: the layout of scopes and child lists, expressions, the
 * customizer annotations of the top-level assignments, the -D overrides
 * where openscad parses them (lines after the file's end), and a syntax
 * error, which writes nothing.  tests/cli/openscad_flags.sh runs openscad
 * itself on more; the corpus (tests/cli/corpus.py --kind ast) on 526 files.
 */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/scad/scad.h"
#include "../services.h"

/* The .ast of src as t.scad (defines may be NULL), or NULL after a parse
 * error; the caller frees it. */
static char *ast_of(const char *src, const char *const *defines, int ndefines)
{
    scad_options o;
    memset(&o, 0, sizeof o);
    o.services = test_services();
    o.defines = defines;
    o.define_count = ndefines;
    char *text = NULL;
    size_t len = 0;
    int rc = scad_dump_ast_string("t.scad", src, &o, &text, &len);
    if (rc != 0) {
        cr_expect_null(text);
        return NULL;
    }
    cr_expect_eq(len, strlen(text));
    return text;
}

static void expect_ast(const char *src, const char *want)
{
    char *got = ast_of(src, NULL, 0);
    cr_assert_not_null(got);
    cr_expect_str_eq(got, want);
    free(got);
}

/* Functions, modules, assignments, then instantiations; one child on the
 * line, a lone assignment braced, "*" dropped, modifiers not shown, an
 * empty else written as "else;" with no line break. */
Test(scad_ast, scopes_are_laid_out_as_openscad)
{
    expect_ast(
        "function f(a, b=2) = a + b;\n"
        "translate([1,0,0]) { x = 1; }\n"
        "translate([1,0,0]) { }\n"
        "union() { *cube(); sphere(); }\n"
        "!#%cube(1);\n"
        "if (1) cube(); else ;\n"
        "if (1) ; else cube();\n"
        "if (1) { cube(); sphere(); } else { sphere(); cube(); }\n"
        "if (2) if (3) cube(); else sphere();\n"
        "module m() { x = 2; module n() cube(); function g() = 1; n(); if (x) { cube(); } }\n"
        "module e();\n"
        "for (i=[1,2], j=[3]) cube(i);\n"
        "{ cube(7); }\n",
        "function f(a, b = 2) = (a + b);\n"
        "module m() {\n"
        "\tfunction g() = 1;\n"
        "\tmodule n() {\n"
        "\t\tcube();\n"
        "\t}\n"
        "\tx = 2;\n"
        "\tn();\n"
        "\tif(x) cube();\n"
        "}\n"
        "module e() {\n"
        "}\n"
        "translate([1, 0, 0]) {\n"
        "\tx = 1;\n"
        "}\n"
        "translate([1, 0, 0]);\n"
        "union() sphere();\n"
        "cube(1);\n"
        "if(1) cube();\n"
        "else;if(1);\n"
        "else cube();\n"
        "if(1) {\n"
        "\tcube();\n"
        "\tsphere();\n"
        "}\n"
        "else {\n"
        "\tsphere();\n"
        "\tcube();\n"
        "}\n"
        "if(2) if(3) cube();\n"
        "else sphere();\n"
        "for(i = [1, 2], j = [3]) cube(i);\n"
        "cube(7);\n");
}

/* Parentheses around every operation, a unary plus dropped, strings
 * escaped, numbers as echo prints them, comprehensions' bodies in
 * parentheses (a let's only when its body is a comprehension). */
Test(scad_ast, expressions_are_printed_as_openscad)
{
    expect_ast(
        "a = +x;\n"
        "c = \"t\\tq\\\\z\\\"\";\n"
        "d = [for (i=[1:2], j=[3:4]) let(k=1) for (m=[0]) [i,j]];\n"
        "e = [let(k=1) k, each [1], if (a) 1 else 2, for (i=0; i<2; i=i+1) i];\n"
        "f = f(1)(2)[0].x;\n"
        "m = function(a, b=1) function() a;\n"
        "o = -2^3^4 % 1 - !true || false && 1 < 2 == 2 >= 3;\n"
        "p = echo(\"x\") assert(true) undef;\n"
        "q = [1e10, 1e-5, 1e-6, 123456789, 0.1, []];\n",
        "a = x;\n"
        "//Parameter(\"\")\n"
        "c = \"t\\tq\\\\z\\\"\";\n"
        "d = [for(i = [1 : 2]) (for(j = [3 : 4]) (let(k = 1) (for(m = [0]) ([i, j]))))];\n"
        "e = [let(k = 1) k, each ([1]), if(a) (1) else (2), for(i = 0;(i < 2);i = (i + 1)) i];\n"
        "f = (f(1))(2)[0].x;\n"
        "m = function(a, b = 1) function() a;\n"
        "o = (((-(2 ^ (3 ^ 4)) % 1) - !true) || (false && ((1 < 2) == (2 >= 3))));\n"
        "p = echo(\"x\") assert(true) undef;\n"
        "//Parameter(\"\")\n"
        "q = [1e+10, 0.00001, 1e-6, 1.23457e+8, 0.1, []];\n");
}

/* Groups from one-line block comments, descriptions from the line above,
 * parameters from the end of the line through comment_parser.y's grammar
 * (a range, labelled pairs, words joined, quoted words, "" where it does
 * not parse or a second ';' comes first); none for a value that is not a
 * literal or an assignment after the first '{'. */
Test(scad_ast, customizer_annotations_are_openscads)
{
    expect_ast("/* not a group */\n"
               "a = 1;\n"
               "/* [First] [Second] */\n"
               "// A width\twith // slashes\n"
               "c = 3; // -0\n"
               "d = 4; // [1:2:3]\n"
               "e = 5; // [a:b, 1:2, x y 3, 4 5 z]\n"
               "f = 6; // 1 2\n"
               "g = 7; // 1e10 mm\n"
               "h = 8; // [0.5:10]\n"
               "j = \"x\"; // [\"a,b\", \"c\\\"d\" e, \"open\n"
               "k = 10; // 12abc (dropped) \"q\"\n"
               "n = 12; ; // [5]\n"
               "o = -1; // [-5:5]\n"
               "p = a; // [1:2]\n"
               "q = [1, \"s\"]; //[new,second]\n"
               "module brace() {}\n"
               "r = 1; // [3:4]\n",
               "module brace() {\n"
               "}\n"
               "//Group(\"\")\n"
               "//Parameter(\"\")\n"
               "a = 1;\n"
               "//Group(\"First-Second\")\n"
               "//Description(\"A width\\twith   slashes\")\n"
               "//Parameter(0)\n"
               "c = 3;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter([1 : 2 : 3])\n"
               "d = 4;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter([[\"a\", \"b\"], [1, 2], \"x y 3\", \"4 5 z\"])\n"
               "e = 5;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter(\"\")\n"
               "f = 6;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter(\"1e+10 mm\")\n"
               "g = 7;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter([0.5 : 10])\n"
               "h = 8;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter(\"\")\n"
               "j = \"x\";\n"
               "//Group(\"First-Second\")\n"
               "//Parameter(\"12abc dropped q\")\n"
               "k = 10;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter(\"\")\n"
               "n = 12;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter([-5 : 5])\n"
               "o = -1;\n"
               "p = a;\n"
               "//Group(\"First-Second\")\n"
               "//Parameter([\"new\", \"second\"])\n"
               "q = [1, \"s\"];\n"
               "r = 1;\n");
}

/* openscad parses "-D a=5" as a line after the file's end: the value
 * replaces the file's in its place, a new name comes last, and both are
 * annotated from their own (comment-less) lines. */
Test(scad_ast, defines_are_placed_as_openscad)
{
    const char *defs[] = {"a=5", "n=\"x\"", "b=[1,2]"};
    char *got = ast_of("// The width\na = 1; // [0:10]\nb = 2;\n", defs, 3);
    cr_assert_not_null(got);
    cr_expect_str_eq(got, "//Parameter(\"\")\n"
                          "a = 5;\n"
                          "//Parameter(\"\")\n"
                          "b = [1, 2];\n"
                          "//Parameter(\"\")\n"
                          "n = \"x\";\n");
    free(got);
}

/* A line break inside a string literal is dropped (2021.01's lexer), a
 * carriage return kept. */
Test(scad_ast, line_breaks_in_strings_are_dropped)
{
    expect_ast("x = \"a\nb\r\nc\";\n", "//Parameter(\"\")\nx = \"ab\\rc\";\n");
}

Test(scad_ast, a_syntax_error_writes_nothing)
{
    cr_expect_null(ast_of("cube(", NULL, 0));
}
