/*
 * test_mesh_export.c — AMF and 3MF export (io_amf_write, io_3mf_write, and
 * rayscad_mesh_write choosing them by extension): a box and a tetrahedron
 * read back through our importers (counts, every vertex, the closed-form
 * volume) and through the openscad binary's import() (the volume of the
 * STL it exports), the AMF laid out line for line as openscad 2021.01
 * lays out its own, the 3MF's unit, object and build item, and writes that
 * fail leaving nothing behind.  Run from the repository root.
 */
#include "../../src/io/io.h"
#include "../../src/mesh/mesh.h"
#include "../../src/rayscad/rayscad_internal.h"

#include <criterion/criterion.h>

#include <ctype.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[64];

static void make_dir(void)
{
    snprintf(dir, sizeof dir, "/tmp/rayscad-export-XXXXXX");
    cr_assert_not_null(mkdtemp(dir));
}

static void remove_dir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) { /* a leftover in /tmp is harmless */
    }
}

TestSuite(io_export, .init = make_dir, .fini = remove_dir);

/* A 2 × 3 × 4 box from the origin, triangles counter-clockwise seen from
 * outside: volume 24. */
static const float box_v[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0},
                                  {0, 0, 4}, {2, 0, 4}, {2, 3, 4}, {0, 3, 4}};
static const int32_t box_t[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                     {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                     {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};

/* The corner tetrahedron of edges A, B, C along the axes, moved by
 * (-1/3, 5/7, 1e-3): volume A·B·C/6 (translation changes nothing).  The
 * coordinates need all of a float's digits. */
#define TA 1.1f
#define TB 2.3f
#define TC 0.7f
static float tet_v[4][3];
static const int32_t tet_t[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

static void make_tet(void)
{
    const float o[3] = {-1.0f / 3, 5.0f / 7, 1e-3f};
    const float e[4][3] = {{0, 0, 0}, {TA, 0, 0}, {0, TB, 0}, {0, 0, TC}};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++)
            tet_v[i][k] = o[k] + e[i][k];
}

/* Signed volume of triangles counter-clockwise seen from outside. */
static double volume(const float *v, const int32_t *t, int nt)
{
    double sum = 0;
    for (int i = 0; i < nt; i++) {
        const float *a = v + 3 * t[3 * i], *b = v + 3 * t[3 * i + 1], *c = v + 3 * t[3 * i + 2];
        sum += a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
               a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
               a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0]);
    }
    return sum / 6;
}

static double tet_volume(void)
{
    /* the edges as the floats hold them, in double */
    return ((double)tet_v[1][0] - tet_v[0][0]) * ((double)tet_v[2][1] - tet_v[0][1]) *
           ((double)tet_v[3][2] - tet_v[0][2]) / 6;
}

typedef int (*writer)(const char *, const float *, int, const int32_t *, int, char *, size_t);
typedef int (*reader)(const char *, float **, int *, int32_t **, int *, char *, size_t);

/* io_3mf_write without colours, as a writer. */
static int plain_3mf(const char *path, const float *v, int nv, const int32_t *t, int nt, char *err,
                     size_t errlen)
{
    return io_3mf_write(path, v, nv, t, nt, NULL, err, errlen);
}

static void path_in_dir(char *path, size_t len, const char *name)
{
    snprintf(path, len, "%s/%s", dir, name);
}

/* Write (v, t) with w, read it back with r: the same counts, every written
 * vertex found within tol per coordinate, the closed-form volume. */
static void round_trip(writer w, reader r, const char *name, const float *v, int nv,
                       const int32_t *t, int nt, float tol, double vol)
{
    char path[256], err[512] = "", msg[2048] = "";
    path_in_dir(path, sizeof path, name);
    cr_assert_eq(w(path, v, nv, t, nt, err, sizeof err), 0, "%s", err);
    float *bv = NULL;
    int32_t *bt = NULL;
    int bnv = 0, bnt = 0;
    cr_assert_eq(r(path, &bv, &bnv, &bt, &bnt, msg, sizeof msg), 0, "%s", msg);
    cr_expect_str_empty(msg);
    cr_expect_eq(bnv, nv, "%s: %d vertices back, wrote %d", name, bnv, nv);
    cr_expect_eq(bnt, nt, "%s: %d triangles back, wrote %d", name, bnt, nt);
    for (int i = 0; i < nv; i++) {
        int found = 0;
        for (int j = 0; j < bnv && !found; j++)
            found = fabsf(bv[3 * j] - v[3 * i]) <= tol &&
                    fabsf(bv[3 * j + 1] - v[3 * i + 1]) <= tol &&
                    fabsf(bv[3 * j + 2] - v[3 * i + 2]) <= tol;
        cr_expect(found, "%s: vertex %d (%.9g, %.9g, %.9g) not read back within %g", name, i,
                  v[3 * i], v[3 * i + 1], v[3 * i + 2], tol);
    }
    double got = volume(bv, bt, bnt);
    cr_expect(fabs(got - vol) <= 1e-5 * vol, "%s: volume %.9g, closed form %.9g", name, got, vol);
    free(bv);
    free(bt);
}

Test(io_export, amf_reads_back_exactly)
{
    make_tet();
    /* 9 significant digits: every float comes back as written */
    round_trip(io_amf_write, io_amf_read, "box.amf", &box_v[0][0], 8, &box_t[0][0], 12, 0, 24);
    round_trip(io_amf_write, io_amf_read, "tet.amf", &tet_v[0][0], 4, &tet_t[0][0], 4, 0,
               tet_volume());
}

Test(io_export, threemf_reads_back_to_six_decimals)
{
    make_tet();
    /* lib3mf cuts each coordinate to six decimals, toward zero (as in
     * 2021.01's files): a unit of the sixth decimal, and half a float's
     * spacing below 4 when read back */
    float tol = 1e-6f + 2.5e-7f;
    round_trip(plain_3mf, io_3mf_read, "box.3mf", &box_v[0][0], 8, &box_t[0][0], 12, 0, 24);
    round_trip(plain_3mf, io_3mf_read, "tet.3mf", &tet_v[0][0], 4, &tet_t[0][0], 4, tol,
               tet_volume());
}

/* ---- files as openscad 2021.01 writes and reads them -------------------- */

static int have(const char *tool)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", tool);
    return system(cmd) == 0;
}

/* The whole of a file (malloc'ed, NUL-terminated), or NULL. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    if (b && fread(b, 1, (size_t)n, f) != (size_t)n) {
        free(b);
        b = NULL;
    }
    if (b) b[n] = 0;
    fclose(f);
    return b;
}

/* An AMF's skeleton: every number run replaced by '#' and the producer's
 * name by "P", so files of equal counts compare equal line for line. */
static void skeleton(char *s)
{
    char *p = strstr(s, "<metadata type=\"producer\">");
    if (p) {
        p += strlen("<metadata type=\"producer\">");
        char *end = strchr(p, '<');
        if (end) memmove(p + 1, end, strlen(end) + 1), *p = 'P';
    }
    char *out = s, prev = 0;
    for (const char *in = s; *in;) {
        if (prev == '>' && (isdigit((unsigned char)*in) || *in == '-')) {
            while (*in && *in != '<')
                in++;
            *out++ = prev = '#';
        } else {
            *out++ = prev = *in++;
        }
    }
    *out = 0;
}

Test(io_export, amf_laid_out_as_openscad_lays_it_out, .timeout = 60)
{
    if (!have("openscad")) cr_skip_test("openscad not installed");
    char scad[256], ref[256], ours[256], cmd[1024], err[512] = "";
    path_in_dir(scad, sizeof scad, "box.scad");
    path_in_dir(ref, sizeof ref, "ref.amf");
    path_in_dir(ours, sizeof ours, "ours.amf");
    FILE *f = fopen(scad, "w");
    cr_assert_not_null(f);
    fputs("cube([2, 3, 4]);\n", f); /* 8 vertices, 12 triangles, as ours */
    fclose(f);
    snprintf(cmd, sizeof cmd, "openscad -o '%s' '%s' >/dev/null 2>&1", ref, scad);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    cr_assert_eq(io_amf_write(ours, &box_v[0][0], 8, &box_t[0][0], 12, err, sizeof err), 0, "%s",
                 err);
    char *a = slurp(ref), *b = slurp(ours);
    cr_assert(a && b);
    cr_expect(
        strstr(b, "<metadata type=\"producer\">rayscad " RAYSCAD_VERSION_STRING "</metadata>\r\n"),
        "%s", b);
    skeleton(a);
    skeleton(b);
    cr_expect_str_eq(b, a);
    free(a);
    free(b);
}

/* The model part of a 3MF package (malloc'ed), through unzip. */
static char *model_xml(const char *path)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "unzip -p '%s' 3D/3dmodel.model", path);
    FILE *p = popen(cmd, "r");
    if (!p) return NULL;
    size_t cap = 1 << 16, n = 0;
    char *b = malloc(cap);
    size_t got;
    while (b && (got = fread(b + n, 1, cap - 1 - n, p)) > 0) {
        n += got;
        if (n + 1 == cap) b = realloc(b, cap *= 2);
    }
    pclose(p);
    if (b) b[n] = 0;
    return b;
}

Test(io_export, threemf_holds_one_object_built_in_millimetres)
{
    if (!have("unzip")) cr_skip_test("unzip not installed");
    char path[256], err[512] = "";
    path_in_dir(path, sizeof path, "box.3mf");
    cr_assert_eq(io_3mf_write(path, &box_v[0][0], 8, &box_t[0][0], 12, NULL, err, sizeof err), 0,
                 "%s", err);
    char *x = model_xml(path);
    cr_assert_not_null(x);
    cr_expect(strstr(x, "unit=\"millimeter\""), "%s", x);
    cr_expect(strstr(x, "<object id=\"1\" name=\"rayscad Model\" type=\"model\""), "%s", x);
    cr_expect(strstr(x, "<item objectid=\"1\""), "%s", x);
    cr_expect(
        strstr(x, "<metadata name=\"Application\">rayscad " RAYSCAD_VERSION_STRING "</metadata>"),
        "%s", x);
    const char *p = x;
    int objects = 0, items = 0;
    while ((p = strstr(p, "<object ")))
        objects++, p++;
    for (p = x; (p = strstr(p, "<item ")); p++)
        items++;
    cr_expect_eq(objects, 1);
    cr_expect_eq(items, 1);
    free(x);
}

Test(io_export, threemf_of_one_mesh_is_one_file)
{
    /* the UUIDs come from the mesh, not from chance */
    char a[256], b[256], err[512] = "";
    path_in_dir(a, sizeof a, "a.3mf");
    path_in_dir(b, sizeof b, "b.3mf");
    cr_assert_eq(io_3mf_write(a, &box_v[0][0], 8, &box_t[0][0], 12, NULL, err, sizeof err), 0, "%s",
                 err);
    cr_assert_eq(io_3mf_write(b, &box_v[0][0], 8, &box_t[0][0], 12, NULL, err, sizeof err), 0, "%s",
                 err);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "cmp -s '%s' '%s'", a, b);
    cr_expect_eq(system(cmd), 0, "two writes of one mesh differ");
}

/* Export path through openscad's import() to STL and read that STL's
 * volume; NAN when openscad made no STL. */
static double openscad_volume(const char *path)
{
    char scad[256], stl[256], cmd[1024], err[512];
    path_in_dir(scad, sizeof scad, "import.scad");
    path_in_dir(stl, sizeof stl, "import.stl");
    unlink(stl);
    FILE *f = fopen(scad, "w");
    cr_assert_not_null(f);
    fprintf(f, "import(\"%s\");\n", path);
    fclose(f);
    snprintf(cmd, sizeof cmd, "openscad -o '%s' '%s' >/dev/null 2>&1", stl, scad);
    if (system(cmd) != 0) return NAN;
    float *v = NULL;
    int32_t *t = NULL;
    int nv = 0, nt = 0;
    if (io_mesh_read(stl, &v, &nv, &t, &nt, err, sizeof err) != 0) return NAN;
    double vol = volume(v, t, nt);
    free(v);
    free(t);
    return vol;
}

Test(io_export, openscad_imports_what_we_export, .timeout = 120)
{
    if (!have("openscad")) cr_skip_test("openscad not installed");
    make_tet();
    const char *names[] = {"box.amf", "tet.amf", "box.3mf", "tet.3mf"};
    for (int q = 0; q < 4; q++) {
        char path[256], err[512] = "";
        path_in_dir(path, sizeof path, names[q]);
        writer w = q < 2 ? io_amf_write : plain_3mf;
        int rc = q % 2 ? w(path, &tet_v[0][0], 4, &tet_t[0][0], 4, err, sizeof err)
                       : w(path, &box_v[0][0], 8, &box_t[0][0], 12, err, sizeof err);
        cr_assert_eq(rc, 0, "%s", err);
        double want = q % 2 ? tet_volume() : 24;
        double got = openscad_volume(path);
        /* openscad's STL keeps 6 significant digits */
        cr_expect(fabs(got - want) <= 1e-5 * want, "%s: openscad's volume %.9g, closed form %.9g",
                  names[q], got, want);
    }
}

/* ---- failures ------------------------------------------------------------ */

/* Entries in dir other than . and .. */
static int dir_entries(void)
{
    DIR *d = opendir(dir);
    cr_assert_not_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

/* A refused mesh: -1, the message path + ": " + why, the file already at
 * path untouched and nothing else left in dir. */
static void refused(writer w, const char *name, const float *v, int nv, const int32_t *t, int nt,
                    const char *why)
{
    char path[256], err[512] = "", want[600];
    path_in_dir(path, sizeof path, name);
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f);
    fputs("before", f);
    fclose(f);
    cr_expect_eq(w(path, v, nv, t, nt, err, sizeof err), -1, "%s", name);
    snprintf(want, sizeof want, "%s: %s", path, why);
    cr_expect_str_eq(err, want);
    char *kept = slurp(path);
    cr_expect(kept && !strcmp(kept, "before"), "%s was touched", name);
    free(kept);
    cr_expect_eq(dir_entries(), 1, "%s: something left beside it", name);
    unlink(path);
}

Test(io_export, refused_meshes_leave_nothing)
{
    const int32_t out_of_range[3] = {0, 1, 8}, repeated[3] = {0, 1, 1};
    float nan_v[8][3];
    memcpy(nan_v, box_v, sizeof nan_v);
    nan_v[5][1] = NAN;
    writer ws[2] = {io_amf_write, plain_3mf};
    const char *names[2] = {"x.amf", "x.3mf"};
    for (int q = 0; q < 2; q++) {
        refused(ws[q], names[q], &box_v[0][0], 8, out_of_range, 1,
                "triangle 0 has an index out of range");
        refused(ws[q], names[q], &box_v[0][0], 8, repeated, 1,
                "triangle 0 is degenerate (a repeated vertex)");
        refused(ws[q], names[q], &nan_v[0][0], 8, &box_t[0][0], 12,
                "vertex 5 has a coordinate that is not finite");
    }
}

Test(io_export, unwritable_folder_leaves_nothing)
{
    writer ws[2] = {io_amf_write, plain_3mf};
    const char *names[2] = {"no/such/x.amf", "no/such/x.3mf"};
    for (int q = 0; q < 2; q++) {
        char path[256], err[512] = "";
        path_in_dir(path, sizeof path, names[q]);
        cr_expect_eq(ws[q](path, &box_v[0][0], 8, &box_t[0][0], 12, err, sizeof err), -1);
        cr_expect(strstr(err, "cannot create a temporary file"), "%s", err);
    }
    cr_expect_eq(dir_entries(), 0);
}

Test(io_export, rewrite_keeps_the_targets_mode)
{
    writer ws[2] = {io_amf_write, plain_3mf};
    const char *names[2] = {"m.amf", "m.3mf"};
    for (int q = 0; q < 2; q++) {
        char path[256], err[512] = "";
        path_in_dir(path, sizeof path, names[q]);
        cr_assert_eq(ws[q](path, &box_v[0][0], 8, &box_t[0][0], 12, err, sizeof err), 0, "%s", err);
        cr_assert_eq(chmod(path, 0640), 0);
        cr_assert_eq(ws[q](path, &box_v[0][0], 8, &box_t[0][0], 12, err, sizeof err), 0, "%s", err);
        struct stat st;
        cr_assert_eq(stat(path, &st), 0);
        cr_expect_eq(st.st_mode & 07777, 0640, "%s: mode %o", names[q], st.st_mode & 07777);
    }
}

/* ---- through the library's face ------------------------------------------ */

Test(io_export, format_supported)
{
    cr_expect_eq(rayscad_mesh_format_supported("a.amf"), 1);
    cr_expect_eq(rayscad_mesh_format_supported("dir/a.AMF"), 1);
    cr_expect_eq(rayscad_mesh_format_supported("a.3mf"), 1);
    cr_expect_eq(rayscad_mesh_format_supported("a.3MF"), 1);
    cr_expect_eq(rayscad_mesh_format_supported("a.stl"), 1);
    cr_expect_eq(rayscad_mesh_format_supported("a.Ply"), 1);
    cr_expect_eq(rayscad_mesh_format_supported("a.amfx"), 0);
    cr_expect_eq(rayscad_mesh_format_supported("a.xamf"), 0);
    cr_expect_eq(rayscad_mesh_format_supported("amf"), 0);
    cr_expect_eq(rayscad_mesh_format_supported("a.3m"), 0);
    cr_expect_eq(rayscad_mesh_format_supported("a.png"), 0);
    cr_expect_eq(rayscad_mesh_format_supported(NULL), 0);
}

Test(io_export, mesh_write_chooses_by_extension)
{
    mesh *m = mesh_new_from_arrays(&box_v[0][0], 8, &box_t[0][0], 12);
    cr_assert_not_null(m);
    rayscad_mesh rm = {m, 0};
    const char *names[2] = {"w.AMF", "w.3Mf"};
    reader rs[2] = {io_amf_read, io_3mf_read};
    for (int q = 0; q < 2; q++) {
        char path[256], err[512] = "", msg[2048] = "";
        path_in_dir(path, sizeof path, names[q]);
        for (int ascii = 0; ascii < 2; ascii++) { /* ascii has no say */
            cr_assert_eq(rayscad_mesh_write(&rm, path, ascii, err, sizeof err), RAYSCAD_OK, "%s",
                         err);
            float *v = NULL;
            int32_t *t = NULL;
            int nv = 0, nt = 0;
            cr_assert_eq(rs[q](path, &v, &nv, &t, &nt, msg, sizeof msg), 0, "%s: %s", names[q],
                         msg);
            cr_expect_eq(nt, 12);
            cr_expect_float_eq(volume(v, t, nt), 24.0, 1e-9);
            free(v);
            free(t);
        }
    }
    char path[256], err[512] = "", want[600];
    path_in_dir(path, sizeof path, "w.amf2");
    cr_expect_eq(rayscad_mesh_write(&rm, path, 0, err, sizeof err), RAYSCAD_ERROR);
    snprintf(want, sizeof want,
             "%s: unknown mesh format (use .stl, .off, .obj, .ply, .amf or .3mf)", path);
    cr_expect_str_eq(err, want);
    cr_expect_eq(access(path, F_OK), -1);
    mesh_free(m);
}
