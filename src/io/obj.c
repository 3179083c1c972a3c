/*
 * obj.c — OBJ with colours, and the colour helpers of io.h.  OpenMesh's
 * OBJ writer can write colours too, but it names its material file after
 * the file it writes (".mat" beside our temporary name) and points the OBJ
 * at that name, so the pair would not survive the rename into place; this
 * writes the pair under their final names, each through a temporary file.
 */
#include "io.h"
#include "temp_file.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const float io_default_rgba[4] = {0xf9 / 255.0f, 0xd7 / 255.0f, 0x2c / 255.0f, 1};

static const float *rgba_of(const io_colors *c, int i)
{
    int k = c && c->of_tri ? c->of_tri[i] : 0;
    return k > 0 && k <= c->n ? c->rgba[k - 1] : io_default_rgba;
}

void io_color_bytes(const io_colors *c, int i, unsigned char out[4])
{
    const float *f = rgba_of(c, i);
    for (int k = 0; k < 4; k++) {
        float x = f[k] < 0 ? 0 : f[k] > 1 ? 1 : f[k];
        out[k] = (unsigned char)(x * 255 + 0.5f);
    }
}

typedef struct obj_job {
    const float *v;
    int nv;
    const int32_t *t;
    int nt;
    const io_colors *c;
    const char *mtl_name; /* as the OBJ names it: no folder */
} obj_job;

static int write_mtl(FILE *f, void *ctx, char *why, size_t whylen)
{
    (void)why;
    (void)whylen;
    const obj_job *j = ctx;
    fprintf(f, "# rayscad: the colours of the OBJ of the same name\n");
    for (int k = 0; k <= j->c->n; k++) {
        const float *p = k ? j->c->rgba[k - 1] : io_default_rgba;
        fprintf(f, "\nnewmtl color%d\nKd %.6g %.6g %.6g\nd %.6g\n", k, p[0], p[1], p[2], p[3]);
    }
    return 0;
}

static int write_obj(FILE *f, void *ctx, char *why, size_t whylen)
{
    (void)why;
    (void)whylen;
    const obj_job *j = ctx;
    fprintf(f, "# rayscad\nmtllib %s\n", j->mtl_name);
    for (int i = 0; i < j->nv; i++)
        fprintf(f, "v %.9g %.9g %.9g\n", j->v[3 * (size_t)i], j->v[3 * (size_t)i + 1],
                j->v[3 * (size_t)i + 2]);
    /* Faces grouped by colour, each group once (0: the default). */
    for (int k = 0; k <= j->c->n; k++) {
        int named = 0;
        for (int i = 0; i < j->nt; i++) {
            int ki = j->c->of_tri[i];
            if ((ki > j->c->n ? 0 : ki) != k) continue;
            if (!named) fprintf(f, "usemtl color%d\n", k);
            named = 1;
            const int32_t *p = j->t + 3 * (size_t)i;
            fprintf(f, "f %d %d %d\n", p[0] + 1, p[1] + 1, p[2] + 1);
        }
    }
    return 0;
}

int io_obj_write(const char *path, const float *v, int nv, const int32_t *t, int nt,
                 const io_colors *c, char *err, size_t errlen)
{
    for (long long q = 0; q < 3LL * nt; q++)
        if (t[q] < 0 || t[q] >= nv) {
            snprintf(err, errlen, "%s: triangle %lld has a vertex index out of range", path, q / 3);
            return -1;
        }
    /* path's name with .mtl for .obj */
    size_t n = strlen(path);
    char *mtl = malloc(n + 5);
    if (!mtl) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    memcpy(mtl, path, n + 1);
    char *dot = strrchr(mtl, '.'), *slash = strrchr(mtl, '/');
    if (!dot || (slash && dot < slash)) dot = mtl + n;
    strcpy(dot, ".mtl");
    obj_job j = {v, nv, t, nt, c, slash ? slash + 1 : mtl};
    int rc = io_write_through_temp(mtl, write_mtl, &j, err, errlen);
    if (rc == 0) rc = io_write_through_temp(path, write_obj, &j, err, errlen);
    free(mtl);
    return rc;
}
