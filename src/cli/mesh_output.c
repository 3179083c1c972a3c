/*
 * mesh_output.c — see mesh_output.h.  One tri-dexel sampling serves every
 * request: the measurement integrates its intervals, the thin-feature scan
 * reads its chords, and the contour meshes it; the sampling is freed before
 * the mesh is written, so peak memory is the larger of the two.
 *
 * Thin walls: a contour on a grid of spacing h cannot keep a wall (or a gap)
 * thinner than h — both faces may fall between two rows of nodes, and the
 * wall vanishes or gets holes.  The command says so instead of writing such
 * a mesh silently: rayscad_sampling_thin finds, along the rays, parallel
 * opposite faces closer than h (the chord between them is short across the
 * faces, and their normals are nearly opposite, which tells a wall from a
 * ray grazing a curved surface), and the warning names the thinnest and
 * where it is.  Comparing the mesh's volume with the measured one would not
 * do: the measurement's midpoint rule is itself off by up to h/2 times the
 * faces parallel to a ray family (10 % on a plate 2.5 cells thick), so it
 * cannot tell a lost wall from quadrature error.
 */
#include "mesh_output.h"
#include "memory.h"
#include "progress.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void print_vec(const char *fmt, const double v[3])
{
    printf(fmt, v[0], v[1], v[2]);
}

/* How a measurement was made: exactly from rays to a tolerance (> 0), or
 * on the grid of spacing h (said as well where a mesh was made on one). */
typedef struct how {
    double h, tolerance;
    double mesh_tolerance; /* what the mesh was simplified to (0: not) */
    long long over;        /* the exact measurement needed more rays than this */
    double over_s;         /* or more seconds than this */
} how;

static void print_measure(const cli_options *o, const rayscad_measurement *m, how w,
                          const rayscad_mesh *msh, double mesh_volume)
{
    int empty = !(m->lo[0] <= m->hi[0]);
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = empty ? 0 : m->lo[k];
        hi[k] = empty ? 0 : m->hi[k];
    }
    if (o->json) {
        printf("{\n  \"volume\": %.15g,\n  \"area\": %.15g,\n", m->volume, m->area);
        print_vec("  \"bounds\": {\"min\": [%.15g, %.15g, %.15g], ", lo);
        print_vec("\"max\": [%.15g, %.15g, %.15g]},\n", hi);
        print_vec("  \"centroid\": [%.15g, %.15g, %.15g],\n", m->centroid);
        printf("  \"empty\": %s,\n", empty ? "true" : "false");
        if (w.tolerance > 0)
            printf("  \"method\": \"exact\",\n  \"tolerance\": %.3g,\n  \"rays\": %lld",
                   w.tolerance, m->crossings);
        else
            printf("  \"method\": \"grid\",\n  \"crossings\": %lld", m->crossings);
        if (w.over) printf(",\n  \"exact_needs_more_rays_than\": %lld", w.over);
        if (w.over_s > 0) printf(",\n  \"exact_needs_more_seconds_than\": %g", w.over_s);
        if (w.h > 0) printf(",\n  \"grid_spacing\": %.10g", w.h);
        if (msh)
            printf(",\n  \"mesh\": {\"vertices\": %d, \"triangles\": %d, \"volume\": %.10g, "
                   "\"tolerance\": %.6g}",
                   rayscad_mesh_vertex_count(msh), rayscad_mesh_triangle_count(msh), mesh_volume,
                   w.mesh_tolerance);
        printf("\n}\n");
        return;
    }
    printf("volume:         %.12g\n", m->volume);
    printf("surface area:   %.12g\n", m->area);
    if (empty) {
        printf("bounding box:   (empty)\n");
    } else {
        print_vec("bounding box:   [%.10g, %.10g, %.10g]", lo);
        print_vec(" to [%.10g, %.10g, %.10g]", hi);
        printf(" (size %.10g x %.10g x %.10g)\n", hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    }
    print_vec("centre of mass: [%.12g, %.12g, %.12g]\n", m->centroid);
    if (w.tolerance > 0)
        printf("method:         exact, tolerance %.3g (%lld rays)\n", w.tolerance, m->crossings);
    if (w.over)
        printf("method:         grid (exact needs more than %lld rays; a larger "
               "--measure-tolerance fewer)\n",
               w.over);
    if (w.over_s > 0)
        printf("method:         grid (exact needs more than %g s; a larger "
               "--measure-tolerance less)\n",
               w.over_s);
    if (w.h > 0) printf("grid spacing:   %.10g\n", w.h);
    if (msh)
        printf("mesh:           %d vertices, %d triangles, volume %.10g\n",
               rayscad_mesh_vertex_count(msh), rayscad_mesh_triangle_count(msh), mesh_volume);
}

/* The most rays an exact --measure casts before it gives way to the grid:
 * about 6 s on two cores, enough for the bench part (cube − sphere − three
 * cylinders, 22 million rays).  A model of many faces has as many events
 * along and across the lines (every crossing of a front edge over a back
 * one seen along the rays), and the grid measures it in a fraction of
 * that. */
#define MEASURE_MAX_RAYS (1LL << 25)
/* With a mesh output, whose grid measures anyway: a box or a sphere (60,000
 * rays, 5 ms), no more. */
#define MEASURE_MAX_RAYS_MESH (1LL << 17)
/* Nor longer than this: a ray's cost is not its intervals alone (a
 * rotate_extrude of a smooth circle, a torus of 256 cone bands, spent a
 * minute on 2^25 rays).  About twice what 2^25 plain rays take, so that
 * the ray budget decides where rays are plain (a sanitizer build's are
 * three times slower: tests/cli/measure_openscad.py's slowest scene takes
 * 3 s there). */
#define MEASURE_MAX_SECONDS 10.0

/* The measurement's cancel hook: past the deadline *ud. */
static int past(void *ud)
{
    return cli_now_s() > *(const double *)ud;
}

/* --measure without --mesh-size (or with --measure-tolerance): exactly,
 * into *m; 1 when measured, 0 when it needs more than max_rays
 * (the grid measures instead, and the output says so; a warning too where
 * the tolerance was asked for), -1 on an error (said). */
static int measure_exact(const cli_options *o, const rayscad_scene *scene, long long max_rays,
                         rayscad_measurement *m, how *w)
{
    rayscad_measure_options mo;
    rayscad_measure_options_default(&mo);
    if (o->measure_tolerance > 0) mo.tolerance = o->measure_tolerance;
    mo.max_rays = max_rays;
    mo.max_intervals = o->max_intervals;
    double deadline = cli_now_s() + MEASURE_MAX_SECONDS;
    mo.cancelled = past;
    mo.cancel_ud = &deadline;
    char err[512];
    rayscad_status rc = rayscad_scene_measure(scene, &mo, m, err, sizeof err);
    w->tolerance = mo.tolerance;
    if (rc == RAYSCAD_OK) return 1;
    if (rc == RAYSCAD_ERROR_RAYS || rc == RAYSCAD_CANCELLED) {
        w->tolerance = 0;
        if (rc == RAYSCAD_ERROR_RAYS) {
            w->over = max_rays;
        } else {
            w->over_s = MEASURE_MAX_SECONDS;
            snprintf(err, sizeof err, "the exact measurement needs more than %g s",
                     MEASURE_MAX_SECONDS);
        }
        if (!o->quiet && o->measure_tolerance > 0)
            fprintf(stderr,
                    "rayscad: warning: %s; measured on a grid instead (a larger "
                    "--measure-tolerance needs fewer)\n",
                    err);
        return 0;
    }
    if (rc == RAYSCAD_ERROR_INTERVALS)
        fprintf(stderr, "rayscad: error: %s (--max-intervals)\n", err);
    else
        cli_print_error(o, err);
    return -1;
}

/* One kind of thin-feature warning: "walls thinner", "the thinnest", "thick",
 * what the mesh may do to them and the measure a finer grid must undercut. */
static void warn_narrow(const char *kind, const char *extreme, const char *unit, double h,
                        double size, const double at[3], long long rays, const char *effect,
                        const char *measure)
{
    fprintf(stderr,
            "rayscad: warning: %s than the grid spacing %g (%s %.3g %s, at [%.4g, %.4g, %.4g]; "
            "%lld rays): the mesh may %s; a --mesh-size below their %s resolves them\n",
            kind, h, extreme, size, unit, at[0], at[1], at[2], rays, effect, measure);
}

static void warn_thin(const rayscad_thin *t)
{
    if (t->walls)
        warn_narrow("walls thinner", "the thinnest", "thick", t->wall_h, t->min_wall, t->wall_at,
                    t->walls, "lose them or have holes through them", "thickness");
    if (t->gaps)
        warn_narrow("gaps narrower", "the narrowest", "wide", t->gap_h, t->min_gap, t->gap_at,
                    t->gaps, "close them", "width");
}

typedef struct mesh_file {
    const cli_options *o;
    const rayscad_mesh *msh;
    const cli_output *out;
} mesh_file;

static int write_mesh_to(void *ctx, const char *path, char *err, size_t errlen)
{
    const mesh_file *f = ctx;
    int flags = f->out->ascii ? RAYSCAD_WRITE_ASCII : 0;
    /* An OBJ's colours go to a material file beside it, named in the OBJ:
     * not for the standard output, nor for a temporary name moved after. */
    if (f->out->temporary && !strcmp(f->out->ext, "obj") && rayscad_mesh_color_count(f->msh)) {
        flags |= RAYSCAD_WRITE_NO_COLORS;
        if (!f->o->quiet)
            fprintf(stderr,
                    "rayscad: warning: %s: colours not written: an OBJ keeps them in a material "
                    "file beside it, so only an output named .obj has them\n",
                    f->out->path);
    }
    return rayscad_mesh_write(f->msh, path, flags, err, errlen) == RAYSCAD_OK ? 0 : -1;
}

/* Write msh to every mesh output (paths[i] the name of outs[i], a frame's
 * when animating); 0 or 1 (printed). */
static int write_mesh_files(const cli_options *o, const rayscad_mesh *msh, cli_output *outs,
                            const char *const *paths, int n)
{
    char err[512];
    for (int i = 0; i < n; i++) {
        mesh_file f = {o, msh, &outs[i]};
        if (cli_output_write(&outs[i], paths[i], write_mesh_to, &f, err, sizeof err) != 0) {
            cli_print_error(o, err);
            return 1;
        }
    }
    return 0;
}

/* The largest contour simplified without --mesh-tolerance (about 3 s),
 * and, where few of its vertices are corners of three sharp edges (plane
 * and smooth faces, text, thin walls), the largest simplified all the same
 * (a thin-walled cup's 990,476 triangles, 1.2 s, came down to 842 in 1.5 s
 * more; a PNG heightmap's 1,981,066, a corner at every 40 vertices, took
 * 12 s more to 149,826). */
#define DEFAULT_SIMPLIFY_MAX (1LL << 19)
#define DEFAULT_SIMPLIFY_MAX_SMOOTH (1LL << 21)

/* The tolerance a mesh is simplified to: the user's, else the deviation
 * OpenSCAD's facets would give the model's round parts (so the mesh is as
 * close to the model as openscad's), else — a model of flat faces, which
 * simplify exactly — a ten-thousandth of its longest side, above the
 * contour's own placement noise (EPS·h, 1/256 of a cell). */
static double mesh_tolerance(const cli_options *o, const rayscad_scene *scene)
{
    if (o->mesh_tolerance >= 0) return o->mesh_tolerance;
    double sag = rayscad_scene_facet_deviation(scene), lo[3], hi[3], size = 0;
    if (rayscad_scene_bounds(scene, RAYSCAD_ROOT_MODEL, lo, hi) == 0)
        for (int k = 0; k < 3; k++)
            if (isfinite(hi[k] - lo[k])) size = fmax(size, hi[k] - lo[k]);
    return sag > 0 ? sag : 1e-4 * size;
}

int cli_mesh_output(const cli_options *o, const rayscad_scene *scene, cli_output *outs,
                    const char *const *paths, int n)
{
    int write_mesh = n > 0;
    rayscad_measurement m;
    how w = {0};
    int exact = 0;
    if (o->measure && (o->measure_tolerance > 0 || !(o->mesh_size > 0))) {
        /* where a mesh's grid measures anyway, exact only while cheap */
        exact =
            measure_exact(o, scene, write_mesh ? MEASURE_MAX_RAYS_MESH : MEASURE_MAX_RAYS, &m, &w);
        if (exact < 0) return 1;
        if (exact && !write_mesh) {
            print_measure(o, &m, w, NULL, 0);
            return 0;
        }
    }
    rayscad_mesh_options mo;
    rayscad_mesh_options_default(&mo);
    mo.h = o->mesh_size;
    mo.tolerance = mesh_tolerance(o, scene);
    /* unasked, a contour of millions of triangles is written as it is
     * (simplifying it would take several times as long as the rest),
     * unless few of its vertices are corners (see DEFAULT_SIMPLIFY_MAX) */
    if (o->mesh_tolerance < 0) {
        mo.simplify_max_triangles = DEFAULT_SIMPLIFY_MAX;
        mo.simplify_max_triangles_smooth = DEFAULT_SIMPLIFY_MAX_SMOOTH;
    }
    mo.threads = o->threads;
    mo.root = RAYSCAD_ROOT_MODEL;
    mo.max_cells = o->max_mesh_cells;
    mo.max_intervals = o->max_intervals;
    progress bar;
    progress_start(&bar, o->quiet ? NULL : "sampling");
    mo.progress = progress_phase;
    mo.progress_ud = &bar;
    char err[512];
    rayscad_sampling *d;
    rayscad_status rc = rayscad_sampling_new(scene, &mo, &d, err, sizeof err);
    if (!write_mesh || rc != RAYSCAD_OK) progress_finish(&bar);
    if (rc == RAYSCAD_ERROR_CELLS) {
        fprintf(stderr, "rayscad: error: %s (--max-mesh-cells; a larger --mesh-size needs fewer)\n",
                err);
        return 1;
    }
    if (rc == RAYSCAD_ERROR_INTERVALS) {
        fprintf(stderr, "rayscad: error: %s (--max-intervals)\n", err);
        return 1;
    }
    if (rc != RAYSCAD_OK) {
        cli_print_error(o, err);
        return 1;
    }
    double h, org[3];
    int cells[3];
    rayscad_sampling_grid(d, &h, org, cells);
    if (!exact) rayscad_sampling_measure(d, &m);
    w.h = h;
    rayscad_mesh *msh = NULL;
    double mesh_volume = 0;
    if (write_mesh) {
        rayscad_thin thin;
        rayscad_sampling_thin(d, 0, &thin);
        rc = rayscad_sampling_mesh(d, &mo, &msh, err, sizeof err);
        progress_finish(&bar);
        rayscad_sampling_free(d);
        d = NULL;
        if (rc != RAYSCAD_OK) {
            cli_print_error(o, err);
            return 1;
        }
        if (!o->quiet) warn_thin(&thin);
        if (rayscad_mesh_triangle_count(msh) == 0) {
            fprintf(stderr, "rayscad: error: %s: the model is empty; there is no mesh to write\n",
                    paths[0]);
            rayscad_mesh_free(msh);
            return 1;
        }
        mesh_volume = rayscad_mesh_volume(msh);
        w.mesh_tolerance = rayscad_mesh_tolerance(msh);
        if (write_mesh_files(o, msh, outs, paths, n) != 0) {
            rayscad_mesh_free(msh);
            return 1;
        }
    }
    rayscad_sampling_free(d);
    if (o->measure) print_measure(o, &m, w, msh, mesh_volume);
    rayscad_mesh_free(msh);
    return 0;
}
