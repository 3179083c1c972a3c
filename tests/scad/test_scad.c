/*
 * test_scad.c — the OpenSCAD language module against independent truth:
 * every .scad file in tests/lang is run through the real openscad binary and its
 * ECHO / WARNING / DEPRECATED lines are compared, line by line, with ours;
 * trees are checked through the csg API (scene bounds, materials, roots);
 * errors by their exact "file:line:col: error:" text; limits and garbage
 * input must give a named error or a result, never a crash.
 */
#include <criterion/criterion.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/scad/ast.h"
#include "../../src/scad/scad.h"
#include "../services.h"
#include "../support.h"

/* ---- collecting messages ------------------------------------------------- */

typedef struct lines {
    char **v;
    int n;
} lines;

static void lines_add(lines *l, const char *s, size_t n)
{
    l->v = realloc(l->v, sizeof *l->v * (size_t)(l->n + 1));
    l->v[l->n] = strndup(s, n);
    l->n++;
}

static void lines_free(lines *l)
{
    for (int i = 0; i < l->n; i++)
        free(l->v[i]);
    free(l->v);
    l->v = NULL;
    l->n = 0;
}

/* Messages are split at newlines, as they appear in an .echo file. */
static void collect(void *ud, scad_msg_kind kind, const char *line)
{
    if (kind == RAYSCAD_MSG_NOTE) return; /* rayscad's own, never in openscad's .echo */
    lines *l = ud;
    const char *p = line;
    for (;;) {
        const char *nl = strchr(p, '\n');
        if (!nl) {
            lines_add(l, p, strlen(p));
            return;
        }
        lines_add(l, p, (size_t)(nl - p));
        p = nl + 1;
    }
}

static int compared_line(const char *s)
{
    return !strncmp(s, "ECHO:", 5) || !strncmp(s, "WARNING:", 8) ||
           !strncmp(s, "DEPRECATED:", 11) || !strncmp(s, "Please see", 10) ||
           !strncmp(s, "ERROR:", 6) || !strncmp(s, "TRACE:", 6) ||
           !strncmp(s, "Can't parse file", 16);
}

static void filter(lines *l)
{
    int k = 0;
    for (int i = 0; i < l->n; i++) {
        if (compared_line(l->v[i]))
            l->v[k++] = l->v[i];
        else
            free(l->v[i]);
    }
    l->n = k;
}

static int eval_src(const char *src, lines *msgs, scad_result *r, int max_rec)
{
    scad_options o;
    memset(&o, 0, sizeof o);
    o.services = test_services();
    o.message = collect;
    o.ud = msgs;
    o.max_recursion = max_rec;
    return scad_eval_string("t.scad", src, &o, r);
}

static int has_line(const lines *l, const char *s)
{
    for (int i = 0; i < l->n; i++)
        if (strcmp(l->v[i], s) == 0) return 1;
    return 0;
}

static int has_prefix(const lines *l, const char *s)
{
    for (int i = 0; i < l->n; i++)
        if (strncmp(l->v[i], s, strlen(s)) == 0) return 1;
    return 0;
}

/* ---- against the openscad binary ----------------------------------------- */

static int run_openscad(const char *scad, lines *out)
{
    char dir[] = "/tmp/rayscad_lang_XXXXXX";
    if (!mkdtemp(dir)) return -1;
    char echo_path[256], cmd[1024];
    snprintf(echo_path, sizeof echo_path, "%s/out.echo", dir);
    snprintf(cmd, sizeof cmd, "openscad -o '%s' '%s' >/dev/null 2>&1", echo_path, scad);
    int rc = system(cmd);
    FILE *f = fopen(echo_path, "r");
    if (f) {
        char buf[8192];
        while (fgets(buf, sizeof buf, f)) {
            size_t n = strlen(buf);
            if (n && buf[n - 1] == '\n') buf[--n] = 0;
            lines_add(out, buf, n);
        }
        fclose(f);
    }
    unlink(echo_path);
    rmdir(dir);
    return f ? 0 : (rc ? -1 : 0);
}

Test(scad_lang, matches_openscad_echo_files, .timeout = 600)
{
    if (system("command -v openscad >/dev/null 2>&1") != 0) cr_skip_test("openscad not installed");
    DIR *d = opendir("tests/lang");
    cr_assert_not_null(d, "run from the repository root");
    struct dirent *e;
    int files = 0;
    while ((e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 6 || strcmp(e->d_name + n - 5, ".scad")) continue;
        char path[512];
        snprintf(path, sizeof path, "tests/lang/%s", e->d_name);
        lines want = {0}, got = {0};
        cr_assert_eq(run_openscad(path, &want), 0, "openscad failed on %s", path);
        scad_options o;
        memset(&o, 0, sizeof o);
        o.services = test_services();
        o.message = collect;
        o.ud = &got;
        /* the evaluation that writes .echo: the tree, no geometry */
        char *text = NULL;
        int rc = scad_dump_csg_file(path, &o, &text, NULL);
        int want_error = 0; /* openscad's account of an error: ours must fail too */
        for (int i = 0; i < want.n; i++)
            if (!strncmp(want.v[i], "ERROR:", 6)) want_error = 1;
        cr_expect_eq(rc, want_error ? -1 : 0, "%s: evaluation %s", path,
                     rc ? "failed" : "succeeded");
        free(text);
        filter(&want);
        filter(&got);
        int n_min = want.n < got.n ? want.n : got.n;
        for (int i = 0; i < n_min; i++)
            cr_expect_str_eq(got.v[i], want.v[i], "%s, message %d", path, i + 1);
        cr_expect_eq(got.n, want.n, "%s: %d messages, openscad %d", path, got.n, want.n);
        lines_free(&want);
        lines_free(&got);
        files++;
    }
    closedir(d);
    cr_expect_geq(files, 15, "only %d files in tests/lang", files);
}

/* ---- trees ---------------------------------------------------------------- */

static csg_scene *scene_of(csg_node *n)
{
    char err[128];
    csg_node *roots[1] = {n};
    csg_scene *s = csg_scene_new(roots, 1, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

static void expect_bounds(const char *src, double x0, double y0, double z0, double x1, double y1,
                          double z1)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src(src, &m, &r, 0), 0, "%s", src);
    csg_node_free(r.highlight);
    csg_node_free(r.background);
    cr_assert_not_null(r.model, "%s: empty model", src);
    csg_scene *s = scene_of(r.model);
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0, "%s", src);
    double want_lo[3] = {x0, y0, z0}, want_hi[3] = {x1, y1, z1};
    /* csg may pad bounds by a few ulps for robust slab tests: 1e-6 */
    for (int i = 0; i < 3; i++) {
        cr_expect(fabs(lo[i] - want_lo[i]) < 1e-6, "%s: lo[%d] = %.17g, want %g", src, i, lo[i],
                  want_lo[i]);
        cr_expect(fabs(hi[i] - want_hi[i]) < 1e-6, "%s: hi[%d] = %.17g, want %g", src, i, hi[i],
                  want_hi[i]);
    }
    csg_scene_free(s);
    lines_free(&m);
}

/* ---- numerals --------------------------------------------------------------- */

/* n random digits at p, the first nonzero when `lead` is 0; returns n. */
static int digits(char *p, int n, int lead)
{
    for (int i = 0; i < n; i++)
        p[i] = (char)('0' + (i == 0 && !lead ? 1 + rng_int(9) : rng_int(10)));
    return n;
}

/* Numerals of every shape the lexer reads — 1 to 25 digits and some of 100
 * to 400 (past any fixed buffer), fractions with and without an integer
 * part, leading and trailing zeros, exponents e/E with and without a sign
 * up to ±400 — each read bit for bit as glibc's strtod reads its text. */
Test(scad_lex, numerals_read_as_strtod)
{
    enum { N = 60000 };
    rng_seed(0x7e57);
    size_t cap = (size_t)N * 64 + 4 * 100000, len = 0;
    char *src = malloc(cap);
    size_t *at = malloc(N * sizeof *at);
    cr_assert(src && at);
    for (int i = 0; i < N; i++) {
        char *p = src + len;
        int n = 0, form = rng_int(8);
        int whole = form == 0 ? 0 : rng_int(50) == 0 ? 100 + rng_int(300) : 1 + rng_int(25);
        if (whole) n += digits(p + n, whole, rng_int(4) == 0);
        if (form < 4) {
            p[n++] = '.';
            int frac = rng_int(50) == 0 ? 100 + rng_int(300) : rng_int(20);
            if (!whole && frac == 0) frac = 1;
            n += digits(p + n, frac, 1);
            if (rng_int(3) == 0) n += sprintf(p + n, "000");
        }
        if (rng_int(3) == 0) {
            p[n++] = rng_int(2) ? 'e' : 'E';
            int sign = rng_int(3);
            if (sign) p[n++] = sign == 1 ? '-' : '+';
            n += sprintf(p + n, "%d", rng_int(5) == 0 ? rng_int(400) : rng_int(30));
        }
        p[n++] = ' ';
        at[i] = len;
        len += (size_t)n;
        cr_assert(len + 2000 < cap);
    }
    src[len] = 0;
    scad_arena *a = scad_arena_new();
    scad_diag d = {0};
    scad_token *t;
    int n = scad_lex(a, &d, scad_names_new(a), "numerals", src, &t);
    cr_assert_eq(d.errors, 0);
    /* each numeral is one token with strtod's value, except those past
     * the largest double, which make none (as openscad 2021.01's lexer) */
    long fast = 0, dropped = 0;
    int k = 0;
    for (int i = 0; i < N; i++) {
        char *end;
        double want = strtod(src + at[i], &end);
        cr_assert_eq(*end, ' ', "numeral %d: strtod stopped early", i);
        if (isinf(want)) {
            dropped++;
            continue;
        }
        cr_assert(k < n - 1, "numeral %d has no token", i);
        cr_assert_eq(t[k].kind, TK_NUMBER, "numeral %d '%.*s'", i, (int)(end - src - at[i]),
                     src + at[i]);
        cr_assert(memcmp(&t[k].num, &want, sizeof want) == 0, "'%.*s': lexed %.17g, strtod %.17g",
                  (int)(end - src - at[i]), src + at[i], t[k].num, want);
        k++;
        fast += end - (src + at[i]) < 12;
    }
    cr_assert_eq(n, k + 1, "%d tokens for %d numerals in range", n, k);
    cr_assert(dropped > 0 && dropped < N / 10, "%ld numerals past the largest double", dropped);
    cr_assert(fast > N / 4, "only %ld short numerals", fast);
    free(t);
    scad_arena_free(a);
    free(src);
    free(at);
}

/* Interning against strcmp: 5000 names (enough to grow the table several
 * times), each interned twice from different buffers, give one pointer per
 * distinct string and distinct pointers for distinct strings. */
Test(scad_names, equal_names_are_one_pointer)
{
    scad_arena *a = scad_arena_new();
    scad_names *t = scad_names_new(a);
    cr_assert(t);
    enum { N = 5000 };
    static const char *first[N];
    char buf[32];
    for (int i = 0; i < N; i++) {
        int n = snprintf(buf, sizeof buf, "n%d_%c", i % 2500, 'a' + i / 2500);
        first[i] = scad_names_intern(t, buf, (size_t)n);
        cr_assert_str_eq(first[i], buf);
    }
    for (int i = 0; i < N; i++) {
        int n = snprintf(buf, sizeof buf, "n%d_%c", i % 2500, 'a' + i / 2500);
        cr_assert_eq(scad_names_intern(t, buf, (size_t)n), first[i], "%s", buf);
        cr_assert_eq(scad_names_find(t, buf), first[i]);
        if (i > 0) cr_assert_neq(first[i], first[i - 1]);
    }
    cr_assert_null(scad_names_find(t, "never_seen"));
    cr_assert_eq(scad_name_keyword(scad_names_intern(t, "module", 6)), TK_MODULE);
    cr_assert_eq(scad_name_keyword(scad_names_intern(t, "modules", 7)), 0);
    scad_arena_free(a);
}

/* A scope finds the last of several definitions of a name, as openscad
 * 2021.01 does (its .echo of this source is the two lines asserted). */
Test(scad_names, scope_finds_the_last_definition)
{
    lines m = {0};
    scad_result r;
    int rc = eval_src("function f() = 1; function g() = 2; function f() = 3;\n"
                      "module m() echo(\"first\"); module m() echo(\"second\");\n"
                      "echo(f(), g()); m();\n",
                      &m, &r, 0);
    cr_assert_eq(rc, 0);
    scad_result_free(&r);
    cr_assert_eq(m.n, 2);
    cr_assert_str_eq(m.v[0], "ECHO: 3, 2");
    cr_assert_str_eq(m.v[1], "ECHO: \"second\"");
    lines_free(&m);
}

Test(scad_tree, translate_cube)
{
    expect_bounds("translate([1,2,3]) cube(2);", 1, 2, 3, 3, 4, 5);
}
Test(scad_tree, cube_center)
{
    expect_bounds("cube([2,4,6], center=true);", -1, -2, -3, 1, 2, 3);
}
Test(scad_tree, sphere_diameter)
{
    expect_bounds("sphere(d=4);", -2, -2, -2, 2, 2, 2);
}
Test(scad_tree, cylinder_centered)
{
    expect_bounds("cylinder(h=2, r=1, center=true);", -1, -1, -1, 1, 1, 1);
}
Test(scad_tree, cylinder_d_over_r)
{
    expect_bounds("cylinder(h=1, r=5, d=2);", -1, -1, 0, 1, 1, 1);
}
Test(scad_tree, rotate_z_then_translate)
{
    /* rotate applies after translate: the unit cube at x in [1,2] turns to y in [1,2] */
    expect_bounds("rotate([0,0,90]) translate([1,0,0]) cube(1);", -1, 1, 0, 0, 2, 1);
}
Test(scad_tree, rotate_scalar_is_about_z)
{
    expect_bounds("rotate(180) cube(1);", -1, -1, 0, 0, 0, 1);
}
Test(scad_tree, scale_mirror_multmatrix)
{
    expect_bounds("scale([2,1,1]) mirror([1,0,0]) cube(1);", -2, 0, 0, 0, 1, 1);
    expect_bounds("multmatrix([[1,0,0,5],[0,1,0,0],[0,0,1,0]]) cube(1);", 5, 0, 0, 6, 1, 1);
}
Test(scad_tree, module_and_for)
{
    expect_bounds("module c(s) translate([s,0,0]) cube(1); for (i=[0:2]) c(i*2);", 0, 0, 0, 5, 1,
                  1);
}
Test(scad_tree, children_transformed)
{
    expect_bounds("module up() translate([0,0,10]) children(); up() cube(1);", 0, 0, 10, 1, 1, 11);
}

static const csg_material *first_material(const char *src, csg_scene **keep)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src(src, &m, &r, 0), 0);
    csg_node_free(r.highlight);
    csg_node_free(r.background);
    lines_free(&m);
    *keep = scene_of(r.model);
    cr_assert_geq(csg_scene_prim_count(*keep), 1);
    return csg_scene_material(*keep, 0);
}

Test(scad_tree, color_forms)
{
    csg_scene *s;
    const csg_material *m = first_material("cube(1);", &s);
    cr_expect_eq(m->has_color, 0);
    csg_scene_free(s);
    m = first_material("color(\"#ff000080\") cube(1);", &s);
    cr_expect(m->has_color && m->rgba[0] == 1 && m->rgba[1] == 0 &&
              fabsf(m->rgba[3] - 128 / 255.0f) < 1e-6);
    csg_scene_free(s);
    m = first_material("color(\"SteelBlue\", 0.5) cube(1);", &s);
    cr_expect(m->has_color && fabsf(m->rgba[0] - 70 / 255.0f) < 1e-6 && m->rgba[3] == 0.5f);
    csg_scene_free(s);
    m = first_material("color([0, 1, 0]) cube(1);", &s);
    cr_expect(m->has_color && m->rgba[1] == 1 && m->rgba[3] == 1);
    csg_scene_free(s);
    /* OpenSCAD 2021.01: the outermost color() wins */
    m = first_material("color(\"red\") color(\"blue\") cube(1);", &s);
    cr_expect(m->has_color && m->rgba[0] == 1 && m->rgba[2] == 0);
    csg_scene_free(s);
    /* an invalid outer colour (alpha only) leaves the inner one */
    m = first_material("color(alpha=0.5) color(\"blue\") cube(1);", &s);
    cr_expect(m->has_color && m->rgba[2] == 1);
    csg_scene_free(s);
}

/* OpenSCAD 2021.01 extrudes its children's 2D geometry, which has no
 * colour: a color() or '#' inside linear_extrude() or rotate_extrude() is
 * lost (its preview draws the default yellow, and nothing highlighted),
 * one outside it is kept. */
Test(scad_tree, colours_inside_extrusions_are_lost)
{
    const char *lost[] = {"linear_extrude(5) color(\"red\") square(5);",
                          "linear_extrude(5, twist = 30) color(\"red\") square(5);",
                          "rotate_extrude() color(\"red\") translate([5, 0]) circle(1);"};
    csg_scene *s;
    for (int i = 0; i < 3; i++) {
        const csg_material *m = first_material(lost[i], &s);
        cr_expect_eq(m->has_color, 0, "%s", lost[i]);
        csg_scene_free(s);
    }
    const csg_material *m = first_material("color(\"blue\") linear_extrude(5) color(\"red\") "
                                           "square(5);",
                                           &s);
    cr_expect(m->has_color && m->rgba[2] == 1 && m->rgba[0] == 0);
    csg_scene_free(s);
    lines l = {0};
    scad_result r;
    cr_assert_eq(eval_src("linear_extrude(5) #square(5);", &l, &r, 0), 0);
    cr_expect_null(r.highlight, "a '#' inside an extrusion highlights nothing");
    scad_result_free(&r);
    cr_assert_eq(eval_src("#linear_extrude(5) square(5);", &l, &r, 0), 0);
    cr_expect_not_null(r.highlight);
    scad_result_free(&r);
    lines_free(&l);
}

Test(scad_tree, modifiers)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("#cube(1); %sphere(1); *cylinder(); echo(1);", &m, &r, 0), 0);
    cr_expect_not_null(r.model);
    cr_expect_not_null(r.highlight);
    cr_expect_not_null(r.background);
    cr_expect_eq(csg_node_child_count(r.model), 0, "model is the cube alone");
    scad_result_free(&r);
    cr_assert_eq(eval_src("*cube(1);", &m, &r, 0), 0);
    cr_expect_null(r.model);
    scad_result_free(&r);
    lines_free(&m);
    /* '!' makes that subtree the only root, without the transforms above it */
    expect_bounds("sphere(5); translate([10,0,0]) !cube(2);", 0, 0, 0, 2, 2, 2);
}

Test(scad_tree, difference_skips_empty_first_child)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("difference() { echo(); cube(5); sphere(1); }", &m, &r, 0), 0);
    cr_assert_not_null(r.model);
    cr_expect_eq(csg_node_child_count(r.model), 2);
    scad_result_free(&r);
    lines_free(&m);
}

Test(scad_tree, degenerate_primitives_make_nothing)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(
        eval_src("cube(-1); sphere(0); cylinder(h=-1); cube(0/0); sphere(1/0);", &m, &r, 0), 0);
    cr_expect_null(r.model);
    scad_result_free(&r);
    lines_free(&m);
}

/* ---- errors and limits ----------------------------------------------------- */

Test(scad_errors, syntax_error_location)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("echo(1);\nx = 5 + ;\n", &m, &r, 0), -1);
    cr_expect(has_line(&m, "t.scad:2:9: error: syntax error: expected an expression before ';'"));
    cr_expect_null(r.model);
    lines_free(&m);
}

Test(scad_errors, all_syntax_errors_reported)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("a = ;\nb = 1;\nc = );\n", &m, &r, 0), -1);
    cr_expect(has_line(&m, "t.scad:1:5: error: syntax error: expected an expression before ';'"));
    cr_expect(has_line(&m, "t.scad:3:5: error: syntax error: expected an expression before ')'"));
    lines_free(&m);
}

/* `use` is a statement of a file's top level only (2021.01's grammar):
 * in braces, a module's body or an instantiation's child it is an error
 * at the `use`, found or not. */
Test(scad_errors, use_only_at_top_level)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("module m() {\n  use <nowhere.scad>\n}\n", &m, &r, 0), -1);
    cr_expect(has_line(&m, "t.scad:2:3: error: syntax error: use <nowhere.scad> is allowed only "
                           "at the top level of a file"));
    lines_free(&m);
    cr_assert_eq(eval_src("translate([1, 0, 0]) use <nowhere.scad>\n", &m, &r, 0), -1);
    cr_expect(has_line(&m, "t.scad:1:22: error: syntax error: use <nowhere.scad> is allowed only "
                           "at the top level of a file"));
    lines_free(&m);
}

/* An instantiation's children (braced or not, an if's or else's too) hold
 * no module or function definitions in 2021.01's grammar; a module's body
 * and a bare block do. */
Test(scad_errors, no_definitions_among_children)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("translate([1, 0, 0]) {\n  function f() = 1;\n  cube();\n}\n", &m, &r, 0),
                 -1);
    cr_expect(has_line(&m, "t.scad:2:3: error: syntax error: an instantiation's children cannot "
                           "define a function"));
    lines_free(&m);
    cr_assert_eq(eval_src("if (true) cube(); else module q() cube();\n", &m, &r, 0), -1);
    cr_expect(has_line(&m, "t.scad:1:24: error: syntax error: an instantiation's children cannot "
                           "define a module"));
    lines_free(&m);
    cr_assert_eq(eval_src("module a() { module b() cube(); b(); }\n{ function g() = 1; }\na();\n",
                          &m, &r, 0),
                 0);
    scad_result_free(&r);
    lines_free(&m);
}

Test(scad_errors, unterminated_string_and_comment)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("echo(1);\ny = \"abc;\n", &m, &r, 0), -1);
    cr_expect(has_line(&m, "t.scad:2:5: error: unterminated string"));
    lines_free(&m);
    cr_assert_eq(eval_src("echo(1);\n  /* abc\n", &m, &r, 0), -1);
    cr_expect(has_line(&m, "t.scad:2:3: error: unterminated comment"));
    lines_free(&m);
}

Test(scad_errors, assert_failure)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(
        eval_src("echo(\"before\");\nassert(1 == 2, \"boom\");\necho(\"after\");", &m, &r, 0), -1);
    cr_expect(has_line(&m, "ECHO: \"before\""));
    cr_expect(has_line(&m, "t.scad:2:1: error: Assertion '(1 == 2)' failed: \"boom\""));
    cr_expect(!has_line(&m, "ECHO: \"after\""));
    lines_free(&m);
}

Test(scad_limits, deep_function_recursion)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(
        eval_src("function f(n) = n <= 0 ? 0 : 1 + f(n - 1);\necho(f(9000));\necho(f(1000000));",
                 &m, &r, 0),
        -1);
    cr_expect(has_line(&m, "ECHO: 9000"));
    cr_expect(has_line(
        &m, "t.scad:1:34: error: recursion deeper than 10000 calls (calling function 'f')"));
    lines_free(&m);
}

Test(scad_limits, deep_module_recursion)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(
        eval_src("module m(n) { if (n > 0) m(n - 1); else cube(1); }\nm(9000);\nm(1000000);", &m,
                 &r, 0),
        -1);
    cr_expect(has_prefix(
        &m, "t.scad:1:26: error: recursion deeper than 10000 calls (calling module 'm')"));
    lines_free(&m);
}

Test(scad_limits, custom_recursion_limit)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(eval_src("function f(n) = n <= 0 ? 0 : 1 + f(n - 1);\necho(f(100));", &m, &r, 50),
                 -1);
    cr_expect(has_prefix(&m, "t.scad:1:34: error: recursion deeper than 50 calls"));
    lines_free(&m);
}

Test(scad_limits, huge_loops_refused)
{
    lines m = {0};
    scad_result r;
    cr_assert_eq(
        eval_src("for (i = [0:1e7]) cube(i);\necho(len([for (i = [0:2e6]) i]));", &m, &r, 0), 0);
    cr_expect(has_line(&m, "WARNING: Bad range parameter in for statement: too many elements "
                           "(10000001) in file t.scad, line 1"));
    cr_expect(has_line(&m, "ECHO: 0"));
    scad_result_free(&r);
    lines_free(&m);
}

Test(scad_limits, deep_nesting_in_source)
{
    size_t n = 100000;
    char *src = malloc(2 * n + 16);
    strcpy(src, "x = ");
    size_t k = 4;
    for (size_t i = 0; i < n; i++)
        src[k++] = '(';
    src[k++] = '1';
    for (size_t i = 0; i < n; i++)
        src[k++] = ')';
    strcpy(src + k, ";");
    lines m = {0};
    scad_result r;
    cr_expect_eq(eval_src(src, &m, &r, 0), -1);
    cr_expect(has_prefix(&m, "t.scad:1:"));
    free(src);
    lines_free(&m);
}

Test(scad_limits, garbage_never_crashes)
{
    unsigned seed = 12345;
    static const char alphabet[] = "abcxyz019 ;,.()[]{}<>=!?:+-*/%^#$\"\\\n/*&|'";
    for (int t = 0; t < 300; t++) {
        char src[200];
        int n = (int)(seed % 199);
        for (int i = 0; i < n; i++) {
            seed = seed * 1103515245u + 12345u;
            src[i] = alphabet[(seed >> 16) % (sizeof alphabet - 1)];
        }
        src[n] = 0;
        lines m = {0};
        scad_result r;
        int rc = eval_src(src, &m, &r, 0);
        cr_assert(rc == 0 || rc == -1, "seed %u", seed);
        if (rc == 0) scad_result_free(&r);
        lines_free(&m);
    }
}

Test(scad_options, defines_override_top_level)
{
    const char *defs[] = {"a=5", "b=\"x\""};
    scad_options o;
    memset(&o, 0, sizeof o);
    o.services = test_services();
    lines m = {0};
    o.message = collect;
    o.ud = &m;
    o.defines = defs;
    o.define_count = 2;
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad", "a = 1; echo(a, b);", &o, &r), 0);
    cr_expect(has_line(&m, "ECHO: 5, \"x\""));
    scad_result_free(&r);
    lines_free(&m);
}

Test(scad_result, file_settings_and_camera_variables)
{
    scad_options o;
    memset(&o, 0, sizeof o);
    o.services = test_services();
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad",
                                  "$rs_aperture = 2.5; $rs_shadows = true; $rs_label = \"x\";\n"
                                  "$vpr = [10, 20]; $vpt = [1, 2, \"z\"]; $vpd = 50;\n"
                                  "module m() { $rs_focus = 9; cube(1); }\nm();\n",
                                  &o, &r),
                 0);
    /* numbers and booleans at top level only; a string is left out */
    cr_assert_eq(r.nsettings, 2);
    cr_expect_str_eq(r.settings[0].name, "$rs_aperture");
    cr_expect_eq(r.settings[0].value, 2.5);
    cr_expect_str_eq(r.settings[1].name, "$rs_shadows");
    cr_expect_eq(r.settings[1].value, 1);
    /* $vpr with two numbers gets z = 0; a $vpt with a string is unusable but
     * still turns viewall off, as Camera::updateView */
    cr_expect_eq(r.vp_set, SCAD_VP_R | SCAD_VP_D);
    cr_expect_eq(r.vp_auto_off, 1);
    cr_expect(r.vpr[0] == 10 && r.vpr[1] == 20 && r.vpr[2] == 0);
    cr_expect_eq(r.vpd, 50);
    scad_result_free(&r);
}

Test(scad_limits, list_and_string_sizes)
{
    /* doubling 40 times would ask for 2^40 elements or bytes: a named error
     * long before memory runs out (concat's count once overflowed an int);
     * small limits keep the test fast, the defaults work the same way */
    const char *src[] = {
        "function d(v, n) = n == 0 ? v : d(concat(v, v), n - 1);\necho(len(d([1], 40)));",
        "function d(s, n) = n == 0 ? s : d(str(s, s), n - 1);\necho(len(d(\"ab\", 40)));",
        "function d(v, n) = n == 0 ? v : d([each v, each v], n - 1);\necho(len(d([1], 40)));",
    };
    const char *want[] = {"list longer than 1000 elements", "string longer than 3000 bytes",
                          "list longer than 1000 elements"};
    for (int i = 0; i < 3; i++) {
        lines got = {0};
        scad_options o;
        memset(&o, 0, sizeof o);
        o.services = test_services();
        o.message = collect;
        o.ud = &got;
        o.max_list = 1000;
        o.max_string = 3000;
        scad_result r;
        cr_expect_eq(scad_eval_string("t.scad", src[i], &o, &r), -1, "case %d", i);
        int found = 0;
        for (int k = 0; k < got.n; k++)
            if (strstr(got.v[k], want[i]) && strstr(got.v[k], "t.scad:1:")) found = 1;
        cr_expect(found, "case %d: no '%s' error at t.scad:1", i, want[i]);
        lines_free(&got);
    }
}

/* Evaluates src with a step limit (0: the default); the messages into m. */
static int eval_steps_facets(const char *src, lines *m, long max_steps, int facets)
{
    scad_options o;
    memset(&o, 0, sizeof o);
    o.services = test_services();
    o.message = collect;
    o.ud = m;
    o.max_steps = max_steps;
    o.facets = facets;
    scad_result r;
    int rc = scad_eval_string("t.scad", src, &o, &r);
    if (rc == 0) scad_result_free(&r);
    return rc;
}

static int eval_steps(const char *src, lines *m, long max_steps)
{
    return eval_steps_facets(src, m, max_steps, 0);
}

Test(scad_env, special_variables_are_dynamically_scoped)
{
    /* each well-known $-variable is found without walking the caller chain
     * (eval.c: scad_env.special); what OpenSCAD 2021.01 echoes */
    lines m = {0};
    cr_assert_eq(eval_steps("$fa = 6;\n"
                            "module m() { echo($fn, $fa, $t, $preview); n(); }\n"
                            "module n() { echo(inner = $fn); }\n"
                            "m($fn = 5);\n"
                            "f = function() $fn;\n"
                            "echo(let($fn = 7) f());\n"
                            "echo($fs);\n"
                            "for ($fn = [1, 2]) echo(loop = $fn);\n"
                            "module k() { $fs = 0.5; children(); }\n"
                            "k() echo(child = $fs);\n",
                            &m, 0),
                 0);
    const char *want[] = {"ECHO: 5, 6, 0, true", "ECHO: inner = 5", "ECHO: 7",          "ECHO: 2",
                          "ECHO: loop = 1",      "ECHO: loop = 2",  "ECHO: child = 0.5"};
    filter(&m);
    cr_assert_eq(m.n, 7);
    for (int i = 0; i < 7; i++)
        cr_expect_str_eq(m.v[i], want[i]);
    lines_free(&m);
}

Test(scad_limits, deep_recursion_with_a_primitive_per_level, .timeout = 10)
{
    /* each cube() reads $fn, $fa, $fs and the $rs_ variables: once a walk
     * up all 10000 callers each (seconds), now O(1) */
    lines m = {0};
    cr_assert_eq(eval_steps("module tree(n) { cube(1); translate([0, 0, 1]) tree(n + 1); }\n"
                            "tree(0);",
                            &m, 0),
                 -1);
    cr_expect(has_line(
        &m, "t.scad:1:48: error: recursion deeper than 10000 calls (calling module 'tree')"));
    lines_free(&m);
}

Test(scad_limits, exponential_children_stop_at_the_step_limit, .timeout = 10)
{
    /* 2^30 children() instantiations: each counts as a call */
    lines m = {0};
    cr_assert_eq(
        eval_steps(
            "module m(n) { if (n > 0) m(n - 1) { children(); children(); } else children(); }\n"
            "m(30) cube();",
            &m, 100000),
        -1);
    cr_expect(has_line(
        &m, "t.scad:1:49: error: evaluation took more than 100000 steps (calls and loop values)"));
    lines_free(&m);
}

Test(scad_limits, concat_counts_the_elements_it_copies)
{
    /* doubling by concat: each copied element is a step, as [each a, each
     * b] counts them, so the step limit stops it long before the list limit
     * (2^26 elements, a GB) */
    lines m = {0};
    cr_assert_eq(eval_steps("function d(l, n) = n == 0 ? l : d(concat(l, l), n - 1);\n"
                            "echo(len(d([1], 40)));",
                            &m, 100000),
                 -1);
    cr_expect(has_line(&m, "t.scad:1:35: error: evaluation took more than 100000 steps (concat)"));
    lines_free(&m);
    /* under the limit, the same list as before */
    cr_assert_eq(eval_steps("echo(concat([1, [2]], 3, [], [[4]], \"ab\"));", &m, 100), 0);
    cr_expect(has_line(&m, "ECHO: [1, [2], 3, [4], \"ab\"]"));
    lines_free(&m);
}

Test(scad_limits, round_points_and_minkowski_sums_are_steps)
{
    /* minkowski() of two smooth spheres: 2048 points each, 4194304 sums */
    lines m = {0};
    cr_assert_eq(
        eval_steps("minkowski() { sphere(1, $fn = 1e9); sphere(1, $fn = 1e9); }", &m, 1000000), -1);
    cr_expect(
        has_line(&m, "t.scad:1:1: error: evaluation took more than 1000000 steps (minkowski)"));
    lines_free(&m);
    /* a $fn of 10^9 asks for 5·10^9 points of a sphere: hull(), resize()
     * and minkowski() count them before making them */
    const char *src[] = {"hull($fn = 1e9) sphere(1);", "resize([1, 2, 3], $fn = 1e9) sphere(1);",
                         "minkowski($fn = 1e9) { sphere(1); cube(); }"};
    const char *want[] = {
        "t.scad:1:1: error: evaluation took more than 1000000000 steps (hull)",
        "t.scad:1:1: error: evaluation took more than 1000000000 steps (resize)",
        "t.scad:1:1: error: evaluation took more than 1000000000 steps (minkowski)"};
    for (int i = 0; i < 3; i++) {
        cr_expect_eq(eval_steps(src[i], &m, 0), -1, "case %d", i);
        cr_expect(has_line(&m, want[i]), "case %d", i);
        lines_free(&m);
    }
    /* and so does a sphere built with OpenSCAD's facets */
    cr_expect_eq(eval_steps_facets("sphere(1, $fn = 1e9);", &m, 0, RAYSCAD_FACETS_OPENSCAD), -1);
    cr_expect(
        has_line(&m, "t.scad:1:1: error: evaluation took more than 1000000000 steps (sphere)"));
    lines_free(&m);
}

Test(scad_limits, twisted_extrusion_vertices_are_steps)
{
    /* a 100,000-gon at 25,000 slices: 2.5·10^9 mesh vertices, once built
     * until memory ran out (minutes, then nothing drawn); with OpenSCAD's
     * facets (else the circle is a smooth one's 256-gon), and a radius at
     * which Clipper keeps every point (each 0.001 or more off the line
     * through its neighbours) */
    lines m = {0};
    cr_assert_eq(eval_steps_facets("linear_extrude(height = 1, twist = 90, slices = 25000) "
                                   "circle(1e6, $fn = 1e9);",
                                   &m, 0, RAYSCAD_FACETS_OPENSCAD),
                 -1);
    cr_expect(has_line(
        &m, "t.scad:1:1: error: evaluation took more than 1000000000 steps (linear_extrude)"));
    lines_free(&m);
}
