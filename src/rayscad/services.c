/*
 * services.c — what the language needs from outside (scad_services), as the
 * library provides it: files from the file system, meshes and images
 * through src/io; for offset, projection, minkowski and text, polygon
 * booleans, offsets and Minkowski sums (Clipper, io/polygon.h), text
 * outlines (io/text.h) and the meshing of a csg tree (src/mesh).  A caller's
 * rayscad_services replaces any of the file, mesh and image readers.
 *
 * OpenSCAD writes OFF files with the counts on the header line ("OFF 8 6
 * 0"), which OpenMesh 9.0's reader takes for something else and runs out of
 * memory on (REFERENCE.md).  read_mesh gives such a file to io_mesh_read as
 * a copy in a private temporary folder with the header split into "OFF" and
 * a line of counts — the form OpenMesh reads.  AMF and 3MF files go to
 * their own readers (io_amf_read, io_3mf_read), by extension.
 */
#include "services.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../io/io.h"
#include "../io/polygon.h"
#include "../io/text.h"
#include "../mesh/mesh.h"

/* ---- files --------------------------------------------------------------------------- */

/* An OFF file whose header needs fixing is read whole first: at most this. */
#define MAX_MESH_BYTES ((size_t)1 << 30)

/* 1 when path is a regular file that reads: a folder opens on Linux but
 * does not read, and a device (/dev/zero, /dev/stdin) may never end.  The
 * modification time comes with any file stat() can see. */
static int stat_file(void *ud, const char *path, long long *mtime)
{
    (void)ud;
    struct stat st;
    if (stat(path, &st) != 0) return 0;
    if (mtime) *mtime = (long long)st.st_mtime;
    if (!S_ISREG(st.st_mode)) return 0;
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    char c;
    size_t got = fread(&c, 1, 1, f);
    int ok = !ferror(f);
    (void)got;
    fclose(f);
    return ok;
}

static int read_file(void *ud, const char *path, size_t max, char **data, size_t *len, char *err,
                     size_t errlen)
{
    (void)ud;
    *data = NULL;
    *len = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s", strerror(errno));
        return -1;
    }
    size_t cap = 65536, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        size_t got = fread(buf + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0) break;
        if (n + 1 == cap) {
            if (cap >= max) {
                free(buf);
                fclose(f);
                snprintf(err, errlen, "%s", strerror(EFBIG));
                return -1;
            }
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    int bad = ferror(f);
    int saved = errno;
    fclose(f);
    if (!buf || bad) {
        snprintf(err, errlen, "%s", buf ? strerror(saved) : "out of memory");
        free(buf);
        return -1;
    }
    buf[n] = 0;
    *data = buf;
    *len = n;
    return 0;
}

/* ---- meshes and images ----------------------------------------------------------------- */

/* Where the counts start when the first line of an OFF file holds its
 * keyword (OFF, COFF, NOFF, STOFF …) followed by numbers; 0 when the
 * header is already on a line of its own. */
static size_t off_counts_on_header(const char *b, size_t n)
{
    size_t i = 0;
    while (i < n && isalpha((unsigned char)b[i]))
        i++;
    if (i < 3 || memcmp(b + i - 3, "OFF", 3) != 0) return 0;
    size_t j = i;
    while (j < n && (b[j] == ' ' || b[j] == '\t'))
        j++;
    return j > i && j < n && isdigit((unsigned char)b[j]) ? i : 0;
}

/* 1 when path ends in "." and the three letters ext (lower case), in any case. */
static int read_mesh(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen)
{
    (void)ud;
    if (io_path_has_extension(path, "amf")) return io_amf_read(path, v, nv, t, nt, err, errlen);
    if (io_path_has_extension(path, "3mf")) return io_3mf_read(path, v, nv, t, nt, err, errlen);
    if (!io_path_has_extension(path, "off")) return io_mesh_read(path, v, nv, t, nt, err, errlen);
    size_t n = 0;
    char *b = NULL, msg[64];
    if (read_file(NULL, path, MAX_MESH_BYTES, &b, &n, msg, sizeof msg) != 0) b = NULL;
    size_t split = b ? off_counts_on_header(b, n) : 0;
    if (!split) {
        free(b);
        return io_mesh_read(path, v, nv, t, nt, err, errlen);
    }
    /* the copy: "OFF\n" and the rest of the file from the counts on */
    const char *tmp = getenv("TMPDIR");
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/rayscad-off-XXXXXX", tmp && *tmp ? tmp : "/tmp");
    int rc = -1;
    if (!mkdtemp(dir)) {
        snprintf(err, errlen, "%s: cannot make a temporary folder to read it", path);
    } else {
        char copy[4200];
        snprintf(copy, sizeof copy, "%s/mesh.off", dir);
        FILE *f = fopen(copy, "wb");
        size_t rest = split;
        while (rest < n && (b[rest] == ' ' || b[rest] == '\t'))
            rest++;
        int ok = f && fwrite(b, 1, split, f) == split && fputc('\n', f) != EOF &&
                 fwrite(b + rest, 1, n - rest, f) == n - rest;
        if (f && fclose(f) != 0) ok = 0;
        if (ok) {
            rc = io_mesh_read(copy, v, nv, t, nt, err, errlen);
            /* messages name the user's file, not the copy */
            char *at = rc ? strstr(err, copy) : NULL;
            if (at) {
                char rest_msg[1024];
                snprintf(rest_msg, sizeof rest_msg, "%s", at + strlen(copy));
                snprintf(err, errlen, "%s%s", path, rest_msg);
            }
        } else {
            snprintf(err, errlen, "%s: cannot copy it to a temporary file to read it", path);
        }
        remove(copy);
        rmdir(dir);
    }
    free(b);
    return rc;
}

static int read_image(void *ud, const char *path, int *width, int *height, int *channels,
                      float **pixels, char *err, size_t errlen)
{
    (void)ud;
    return io_image_read(path, width, height, channels, pixels, err, errlen);
}

/* ---- 2D geometry: offset, projection, minkowski, text --------------------------
 * scad_paths and io_paths have the same three members, so a view, nothing
 * copied; results are handed over as they were malloc'ed. */

static io_paths io_view(const scad_paths *p)
{
    io_paths q = {NULL, NULL, 0};
    if (p) {
        q.pts = p->pts;
        q.start = p->start;
        q.npaths = p->npaths;
    }
    return q;
}

static void from_io(const io_paths *q, scad_paths *out)
{
    out->pts = q->pts;
    out->start = q->start;
    out->npaths = q->npaths;
}

static int clip_paths(void *ud, int op, const scad_paths *a, int a_evenodd, const scad_paths *b,
                      int b_evenodd, scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_clip_op o = op == CSG_OP_INTERSECTION ? IO_CLIP_INTERSECTION
                   : op == CSG_OP_DIFFERENCE ? IO_CLIP_DIFFERENCE
                                             : IO_CLIP_UNION;
    io_paths x = io_view(a), y = io_view(b), r;
    if (io_polygon_clip(o, &x, a_evenodd, &y, b_evenodd, &r, err, errlen) != 0) return -1;
    from_io(&r, out);
    return 0;
}

static int offset_paths(void *ud, const scad_paths *a, double delta, int join, double miter_limit,
                        double arc_tolerance, scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_join j = join == SCAD_JOIN_MITER    ? IO_JOIN_MITER
                : join == SCAD_JOIN_SQUARE ? IO_JOIN_SQUARE
                                           : IO_JOIN_ROUND;
    io_paths x = io_view(a), r;
    if (io_polygon_offset(&x, delta, j, miter_limit, arc_tolerance, &r, err, errlen) != 0)
        return -1;
    from_io(&r, out);
    return 0;
}

static int stroke_paths(void *ud, const double (*pts)[2], int n, double width, int cap,
                        scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_cap c = cap == 0 ? IO_CAP_BUTT : cap == 1 ? IO_CAP_ROUND : IO_CAP_SQUARE;
    io_paths r;
    if (io_polygon_stroke(pts, n, width, c, &r, err, errlen) != 0) return -1;
    from_io(&r, out);
    return 0;
}

static int minkowski_paths(void *ud, const scad_paths *a, const scad_paths *b, scad_paths *out,
                           char *err, size_t errlen)
{
    (void)ud;
    io_paths x = io_view(a), y = io_view(b), r;
    if (io_polygon_minkowski(&x, &y, &r, err, errlen) != 0) return -1;
    from_io(&r, out);
    return 0;
}

static int mesh_tree(void *ud, csg_node *root, double h, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen)
{
    (void)ud;
    *v = NULL;
    *t = NULL;
    *nv = *nt = 0;
    csg_scene *s = csg_scene_new(&root, 1, err, errlen);
    if (!s) return -1;
    mesh_options o;
    mesh_options_default(&o);
    o.h = h;
    o.cells_per_side = 256;
    mesh *m = NULL;
    int rc = mesh_from_scene(s, &o, &m, NULL, err, errlen);
    csg_scene_free(s);
    if (rc != 0) return -1;
    int n = mesh_vertex_count(m), k = mesh_triangle_count(m);
    *v = malloc((size_t)(n ? n : 1) * 3 * sizeof **v);
    *t = malloc((size_t)(k ? k : 1) * 3 * sizeof **t);
    if (!*v || !*t) {
        free(*v);
        free(*t);
        *v = NULL;
        *t = NULL;
        mesh_free(m);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    memcpy(*v, mesh_vertices(m), (size_t)n * 3 * sizeof **v);
    memcpy(*t, mesh_triangles(m), (size_t)k * 3 * sizeof **t);
    *nv = n;
    *nt = k;
    mesh_free(m);
    return 0;
}

static int text_outlines(void *ud, const scad_text_params *p, scad_paths *out, char *err,
                         size_t errlen)
{
    const rayscad_services *caller = ud;
    char font[4096] = "";
    io_text_params q = {p->text,       p->size,        p->font,     p->halign,  p->valign,
                        p->spacing,    p->direction,   p->language, p->script,  p->segments,
                        p->font_files, p->nfont_files, font,        sizeof font};
    io_paths r;
    int rc = io_text_render(&q, &r, err, errlen);
    if (font[0] && caller && caller->file_read) caller->file_read(caller->ud, font);
    if (rc != 0) return rc;
    from_io(&r, out);
    return 0;
}

/* ---- the caller's services over the defaults ------------------------------------------ */

/* ud is the caller's rayscad_services (or NULL): each member it sets
 * replaces the library's; file_read hears of each file read, make_file of
 * each file to import that is not there. */
static void told(const rayscad_services *p, const char *path, int rc)
{
    if (rc == 0 && p && p->file_read) p->file_read(p->ud, path);
}

static void make_if_missing(const rayscad_services *p, const char *path)
{
    struct stat st;
    if (p && p->make_file && stat(path, &st) != 0 && errno == ENOENT) p->make_file(p->ud, path);
}

static void want_file_via(void *ud, const char *path)
{
    make_if_missing(ud, path);
}

static int read_file_via(void *ud, const char *path, size_t max, char **data, size_t *len,
                         char *err, size_t errlen)
{
    const rayscad_services *p = ud;
    make_if_missing(p, path); /* an import: an include is read once found */
    int rc = p && p->read_file ? p->read_file(p->ud, path, max, data, len, err, errlen)
                               : read_file(NULL, path, max, data, len, err, errlen);
    told(p, path, rc);
    return rc;
}

static int stat_file_via(void *ud, const char *path, long long *mtime)
{
    const rayscad_services *p = ud;
    if (p && p->stat_file) return p->stat_file(p->ud, path, mtime);
    return stat_file(NULL, path, mtime);
}

static int read_mesh_via(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt,
                         char *err, size_t errlen)
{
    const rayscad_services *p = ud;
    make_if_missing(p, path);
    int rc = p && p->read_mesh ? p->read_mesh(p->ud, path, v, nv, t, nt, err, errlen)
                               : read_mesh(NULL, path, v, nv, t, nt, err, errlen);
    told(p, path, rc);
    return rc;
}

static int read_image_via(void *ud, const char *path, int *width, int *height, int *channels,
                          float **pixels, char *err, size_t errlen)
{
    const rayscad_services *p = ud;
    make_if_missing(p, path);
    int rc = p && p->read_image
                 ? p->read_image(p->ud, path, width, height, channels, pixels, err, errlen)
                 : read_image(NULL, path, width, height, channels, pixels, err, errlen);
    told(p, path, rc);
    return rc;
}

void rayscad_scad_services(const rayscad_services *caller, scad_services *out)
{
    scad_services s = {
        .ud = (void *)(uintptr_t)caller,
        .read_file = read_file_via,
        .stat_file = stat_file_via,
        .want_file = want_file_via,
        .read_mesh = read_mesh_via,
        .read_image = read_image_via,
        .paths_clip = clip_paths,
        .paths_offset = offset_paths,
        .paths_stroke = stroke_paths,
        .paths_minkowski = minkowski_paths,
        .mesh_tree = mesh_tree,
        .text = text_outlines,
    };
    *out = s;
}

int rayscad_default_read_file(const char *path, size_t max, char **data, size_t *len, char *err,
                              size_t errlen)
{
    return read_file(NULL, path, max, data, len, err, errlen);
}
