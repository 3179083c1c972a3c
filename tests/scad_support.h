/*
 * scad_support.h — what the suites that evaluate OpenSCAD source share:
 * messages collected into a buffer, a scratch folder per test for the files
 * a model reads, the model of a source as a committed scene, and its volume
 * by vertical rays.  Header-only, on support.h's arena.
 */
#ifndef RAYSCAD_TESTS_SCAD_SUPPORT_H
#define RAYSCAD_TESTS_SCAD_SUPPORT_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../src/csg/csg.h"
#include "../src/scad/scad.h"
#include "services.h"
#include "support.h"

typedef struct msgs {
    char text[8192];
} msgs;

/* A scad message callback: each line appended to the msgs ud. */
static inline void on_msg(void *ud, scad_msg_kind kind, const char *line)
{
    (void)kind;
    msgs *m = ud;
    size_t n = strlen(m->text);
    snprintf(m->text + n, sizeof m->text - n, "%s\n", line);
}

/* The test's scratch folder: .init = scratch_setup (also the arena),
 * .fini = scratch_teardown (removes it). */
static char scratch[64];

static inline void scratch_setup(void)
{
    arena_setup();
    snprintf(scratch, sizeof scratch, "/tmp/rayscad-test-XXXXXX");
    cr_assert(mkdtemp(scratch));
}

static inline void scratch_teardown(void)
{
    arena_teardown();
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", scratch);
    cr_assert_eq(system(cmd), 0);
}

/* Writes text to scratch/name; the path into out. */
static inline void write_file(const char *name, const char *text, char *out, size_t n)
{
    snprintf(out, n, "%s/%s", scratch, name);
    FILE *f = fopen(out, "w");
    cr_assert(f);
    fputs(text, f);
    fclose(f);
}

/* The result of src evaluated as the file main_file with the test services;
 * messages into m.  The evaluation must succeed. */
static inline void eval_as(const char *main_file, const char *src, msgs *m, scad_result *r)
{
    scad_options o;
    memset(&o, 0, sizeof o);
    o.services = test_services();
    o.message = on_msg;
    o.ud = m;
    cr_assert_eq(scad_eval_string(main_file, src, &o, r), 0, "%s", m->text);
}

/* The model of src, evaluated as main_file, as a scene. */
static inline csg_scene *scene_as(const char *main_file, const char *src, msgs *m)
{
    scad_result r;
    eval_as(main_file, src, m, &r);
    csg_node *root = r.model;
    r.model = NULL;
    scad_result_free(&r);
    char err[256];
    csg_scene *s = csg_scene_new(&root, 1, err, sizeof err);
    cr_assert(s, "%s", err);
    return s;
}

/* Volume by vertical rays through the centres of an n × n grid over the
 * scene's bounds: Σ length inside × cell area.  The error is the boundary
 * band of the grid, O(perimeter · cell). */
static inline double traced_volume(const csg_scene *s, int n)
{
    double lo[3], hi[3];
    if (csg_scene_bounds(s, 0, lo, hi) != 0) return 0;
    double dx = (hi[0] - lo[0]) / n, dy = (hi[1] - lo[1]) / n, v = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            iv_arena_reset(arena);
            double o[3] = {lo[0] + (i + 0.5) * dx, lo[1] + (j + 0.5) * dy, lo[2] - 1};
            iv_list l;
            cr_assert_eq(csg_trace(s, 0, o, (double[3]){0, 0, 1}, 0, INFINITY, arena, &l), 0);
            for (int k = 0; k < l.n; k++)
                v += (l.v[k].exit.t - l.v[k].enter.t) * dx * dy;
        }
    return v;
}

#endif
