/*
 * services.c — scad_services for the command: meshes and images through
 * src/io; for offset, projection, minkowski and text, polygon booleans,
 * offsets and Minkowski sums (Clipper, io/polygon.h), text outlines
 * (io/text.h) and the meshing of a csg tree (src/mesh).
 *
 * OpenSCAD writes OFF files with the counts on the header line ("OFF 8 6
 * 0"), which OpenMesh 9.0's reader takes for something else and runs out of
 * memory on (REFERENCE.md).  read_mesh gives such a file to io_mesh_read as
 * a copy in a private temporary folder with the header split into "OFF" and
 * a line of counts — the form OpenMesh reads.
 */
#include "services.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "../io/io.h"
#include "../io/polygon.h"
#include "../io/text.h"
#include "../mesh/mesh.h"
#include "options.h"

/* The whole file at path, malloc'ed, its length in *n; NULL on failure. */
static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, len = 0;
    char *b = malloc(cap);
    while (b) {
        len += fread(b + len, 1, cap - len, f);
        if (len < cap) break;
        char *nb = realloc(b, cap * 2);
        if (!nb) {
            free(b);
            b = NULL;
            break;
        }
        b = nb;
        cap *= 2;
    }
    if (b && ferror(f)) {
        free(b);
        b = NULL;
    }
    fclose(f);
    *n = len;
    return b;
}

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

static int has_off_extension(const char *path)
{
    size_t n = strlen(path);
    if (n < 4 || path[n - 4] != '.') return 0;
    return tolower((unsigned char)path[n - 3]) == 'o' &&
           tolower((unsigned char)path[n - 2]) == 'f' && tolower((unsigned char)path[n - 1]) == 'f';
}

static int read_mesh(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen)
{
    (void)ud;
    if (!has_off_extension(path)) return io_mesh_read(path, v, nv, t, nt, err, errlen);
    size_t n = 0;
    char *b = slurp(path, &n);
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

/* The width and height of a PNG file from its IHDR chunk: 0, or -1 when
 * path is not a readable PNG. */
static int png_size(const char *path, unsigned long *w, unsigned long *h)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char b[24];
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    if (n != sizeof b || memcmp(b, sig, 8) || memcmp(b + 12, "IHDR", 4)) return -1;
    *w = (unsigned long)b[16] << 24 | (unsigned long)b[17] << 16 | (unsigned long)b[18] << 8 | b[19];
    *h = (unsigned long)b[20] << 24 | (unsigned long)b[21] << 16 | (unsigned long)b[22] << 8 | b[23];
    return 0;
}

/* The process's data memory as RLIMIT_DATA counts it (VmData), in bytes;
 * 0 when unknown. */
static unsigned long long data_in_use(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    unsigned long long kb = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "VmData: %llu kB", &kb) == 1) break;
    fclose(f);
    return kb * 1024;
}

/* surface() runs while --max-memory applies, and OpenImageIO does not
 * survive that: its libraries' initialisers, and the first read (its
 * plugin catalogue and thread pool: about 100 MB of VmData), throw where
 * they cannot unwind or dereference null below about 150 MiB.  So the
 * adapter is loaded with the limit lifted (cli_load_image_adapter), and a
 * PNG is read with it lifted too, but only when its pixels fit under the
 * limit beside what the process holds: twice the image as 4 floats a
 * pixel (ours and OpenImageIO's scanlines), else out of memory.  Other
 * files are read under the limit. */
static int read_image(void *ud, const char *path, int *width, int *height, int *channels,
                      float **pixels, char *err, size_t errlen)
{
    (void)ud;
    cli_load_image_adapter();
    unsigned long w, h;
    struct rlimit was;
    if (png_size(path, &w, &h) != 0 || getrlimit(RLIMIT_DATA, &was) != 0 ||
        was.rlim_cur == was.rlim_max)
        return io_image_read(path, width, height, channels, pixels, err, errlen);
    unsigned long long need = 2ULL * w * h * 4 * sizeof(float), used = data_in_use();
    if (!used || need > (unsigned long long)was.rlim_cur - used || used > was.rlim_cur) {
        snprintf(err, errlen, "%s: out of memory for a %lux%lu image", path, w, h);
        *pixels = NULL;
        return -1;
    }
    int lifted = cli_data_limit_lift(&was);
    int rc = io_image_read(path, width, height, channels, pixels, err, errlen);
    cli_data_limit_restore(lifted, &was);
    return rc;
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
    (void)ud;
    io_text_params q = {p->text,    p->size,      p->font,     p->halign, p->valign,
                        p->spacing, p->direction, p->language, p->script, p->segments};
    io_paths r;
    if (io_text_render(&q, &r, err, errlen) != 0) return -1;
    from_io(&r, out);
    return 0;
}

const scad_services *cli_services(void)
{
    static const scad_services s = {
        .read_mesh = read_mesh,
        .read_image = read_image,
        .paths_clip = clip_paths,
        .paths_offset = offset_paths,
        .paths_minkowski = minkowski_paths,
        .mesh_tree = mesh_tree,
        .text = text_outlines,
    };
    return &s;
}
