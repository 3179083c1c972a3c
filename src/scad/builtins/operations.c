/*
 * operations.c — the transforms (translate, rotate, scale, mirror,
 * multmatrix), color(), and the CSG operations (union, group, difference,
 * intersection, render).
 *
 * A transform composes its matrix onto the inherited world_from_object
 * (state.xf ∘ M, so M applies first) and evaluates its children with it;
 * leaves copy the full transform, so nothing is multiplied per ray.  In
 * .csg every transform is the multmatrix of that M.  union, group,
 * difference and intersection take no arguments: OpenSCAD 2021.01's CSG
 * modules neither evaluate nor check what they are given.
 */
#include <math.h>
#include <string.h>

#include "builtins.h"

/* Up to 3 numbers of a vector into out (others keep their value); returns
 * 1 when v is a vector of numbers with 1..3 elements … any size accepted. */
static int vec3_of(scad_value v, double out[3])
{
    if (v.kind != SV_VEC) return 0;
    const scad_vec *p = v.u.vec;
    if (p->n < 2 || p->n > 3) return 0;
    for (int i = 0; i < p->n; i++)
        if (p->v[i].kind != SV_NUM) return 0;
    for (int i = 0; i < p->n; i++)
        out[i] = p->v[i].u.num;
    return 1;
}

static void identity(csg_affine m)
{
    memcpy(m, csg_affine_identity, sizeof(csg_affine));
}

static void translate_matrix(scad_call *c, csg_affine m)
{
    double v[3] = {0, 0, 0};
    identity(m);
    if (vec3_of(c->arg[0], v)) {
        m[3] = v[0];
        m[7] = v[1];
        m[11] = v[2];
    }
}

static void rotate_matrix(scad_call *c, csg_affine m)
{
    identity(m);
    scad_value av = c->arg[0];
    scad_value vv = c->arg[1];
    if (av.kind == SV_VEC) {
        double ang[3] = {0, 0, 0};
        for (int i = 0; i < av.u.vec->n && i < 3; i++)
            scad_arg_num(av.u.vec->v[i], &ang[i]);
        double sx = iv_sin_degrees(ang[0]), cx = iv_cos_degrees(ang[0]);
        double sy = iv_sin_degrees(ang[1]), cy = iv_cos_degrees(ang[1]);
        double sz = iv_sin_degrees(ang[2]), cz = iv_cos_degrees(ang[2]);
        csg_affine r = {cy * cz,
                        cz * sx * sy - cx * sz,
                        cx * cz * sy + sx * sz,
                        0,
                        cy * sz,
                        cx * cz + sx * sy * sz,
                        -cz * sx + cx * sy * sz,
                        0,
                        -sy,
                        cy * sx,
                        cx * cy,
                        0};
        memcpy(m, r, sizeof r);
    } else {
        double ang;
        if (scad_arg_num(av, &ang) && isfinite(ang)) {
            double ax[3] = {0, 0, 1};
            if (vv.kind == SV_VEC) {
                double v[3] = {0, 0, 0};
                if (vec3_of(vv, v) && isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])) {
                    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                    if (n > 0) {
                        ax[0] = v[0] / n;
                        ax[1] = v[1] / n;
                        ax[2] = v[2] / n;
                    } else {
                        ax[0] = ax[1] = ax[2] = 0;
                    }
                }
            }
            double s = iv_sin_degrees(ang), co = iv_cos_degrees(ang), t = 1 - co;
            double x = ax[0], y = ax[1], z = ax[2];
            if (x == 0 && y == 0 && z == 0) {
                /* OpenSCAD 2021.01 skips the rotation for a zero axis */
            } else {
                csg_affine r = {t * x * x + co,    t * x * y - s * z, t * x * z + s * y, 0,
                                t * x * y + s * z, t * y * y + co,    t * y * z - s * x, 0,
                                t * x * z - s * y, t * y * z + s * x, t * z * z + co,    0};
                memcpy(m, r, sizeof r);
            }
        }
    }
}

static void scale_matrix(scad_call *c, csg_affine m)
{
    double v[3] = {1, 1, 1}, x;
    scad_value sv = c->arg[0];
    if (scad_arg_num(sv, &x))
        v[0] = v[1] = v[2] = x;
    else
        vec3_of(sv, v);
    csg_affine r = {v[0], 0, 0, 0, 0, v[1], 0, 0, 0, 0, v[2], 0};
    memcpy(m, r, sizeof r);
}

static void mirror_matrix(scad_call *c, csg_affine m)
{
    double v[3] = {0, 0, 0};
    identity(m);
    if (vec3_of(c->arg[0], v)) {
        double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (n > 0 && isfinite(n)) {
            double x = v[0] / n, y = v[1] / n, z = v[2] / n;
            csg_affine r = {1 - 2 * x * x, -2 * y * x,    -2 * z * x,    0,
                            -2 * x * y,    1 - 2 * y * y, -2 * z * y,    0,
                            -2 * x * z,    -2 * y * z,    1 - 2 * z * z, 0};
            memcpy(m, r, sizeof r);
        }
    }
}

static void multmatrix_matrix(scad_call *c, csg_affine m)
{
    identity(m);
    scad_value mv = c->arg[0];
    if (mv.kind == SV_VEC) {
        for (int i = 0; i < 3 && i < mv.u.vec->n; i++) {
            scad_value row = mv.u.vec->v[i];
            if (row.kind != SV_VEC) continue;
            for (int j = 0; j < 4 && j < row.u.vec->n; j++)
                scad_arg_num(row.u.vec->v[j], &m[i * 4 + j]);
        }
    }
}

typedef struct transform_args {
    csg_affine m;
} transform_args;

static void transform_read(scad_call *c, void *out)
{
    static const struct {
        const char *name;
        void (*fn)(scad_call *, csg_affine);
    } kinds[] = {{"translate", translate_matrix},
                 {"rotate", rotate_matrix},
                 {"scale", scale_matrix},
                 {"mirror", mirror_matrix},
                 {"multmatrix", multmatrix_matrix}};
    transform_args *p = out;
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++)
        if (strcmp(kinds[i].name, c->def->name) == 0) kinds[i].fn(c, p->m);
}

static int transform_print(scad_call *c, const void *args, scad_buf *b)
{
    const transform_args *p = args;
    (void)c;
    scad_buf_puts(b, "multmatrix([");
    for (int i = 0; i < 4; i++) {
        scad_buf_puts(b, i ? ", [" : "[");
        for (int j = 0; j < 4; j++) {
            char t[32];
            scad_format_number(i < 3 ? p->m[i * 4 + j] : (j == 3 ? 1 : 0), t);
            if (j) scad_buf_puts(b, ", ");
            scad_buf_puts(b, t);
        }
        scad_buf_puts(b, "]");
    }
    scad_buf_puts(b, "])");
    return 1;
}

static scad_geom *transform_build(scad_call *c, const void *args)
{
    const transform_args *p = args;
    scad_state s = *c->state;
    csg_affine_mul(c->state->xf, p->m, s.xf);
    return scad_call_children(c, &s);
}

#define TRANSFORM(var, name, param)                                                                \
    static const char *const var##_params[] = {param, NULL};                                       \
    static const scad_module_def var = {                                                           \
        name,           var##_params, 1, sizeof(transform_args), transform_read, transform_print,  \
        transform_build}
TRANSFORM(translate, "translate", "v");
TRANSFORM(scale, "scale", "v");
TRANSFORM(mirror, "mirror", "v");
TRANSFORM(multmatrix, "multmatrix", "m");
static const char *const rotate_params[] = {"a", "v", NULL};
static const scad_module_def rotate = {
    "rotate",        rotate_params,  2, sizeof(transform_args), transform_read,
    transform_print, transform_build};

/* ---- color ------------------------------------------------------------------------- */

int scad_color_by_hex(const char *s, float rgba[4])
{
    size_t n = strlen(s);
    if (s[0] != '#' || !(n == 4 || n == 5 || n == 7 || n == 9)) return 0;
    int stride = (n == 4 || n == 5) ? 1 : 2;
    float max = stride == 1 ? 15.0f : 255.0f;
    for (size_t i = 1; i < n; i++) {
        char c = s[i];
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'))) return 0;
    }
    rgba[3] = 1;
    for (size_t i = 0; i < (n - 1) / (size_t)stride; i++) {
        int v = 0;
        for (int k = 0; k < stride; k++) {
            char c = s[1 + i * (size_t)stride + (size_t)k];
            int d = c <= '9' ? c - '0' : (c | 32) - 'a' + 10;
            v = v * 16 + d;
        }
        rgba[i] = (float)v / max;
    }
    return 1;
}

enum { COLOR_C, COLOR_ALPHA };

/* The colour as given (a component may lie outside [0, 1] or be NaN;
 * -1: not set). */
typedef struct color_args {
    float rgba[4];
} color_args;

static void color_read(scad_call *c, void *out)
{
    color_args *p = out;
    float *rgba = p->rgba;
    rgba[0] = rgba[1] = rgba[2] = -1;
    rgba[3] = 1;
    scad_value v = c->arg[COLOR_C];
    if (v.kind == SV_VEC) {
        for (int i = 0; i < 4; i++) {
            double x = 1;
            if (i < v.u.vec->n) {
                x = 0;
                scad_arg_num(v.u.vec->v[i], &x);
            }
            rgba[i] = (float)x;
            if (rgba[i] > 1 || rgba[i] < 0)
                scad_diag_warning(
                    c->ev->d, c->st->loc,
                    "color() expects numbers between 0.0 and 1.0. Value of %.1f is out of range",
                    (double)rgba[i]);
        }
    } else if (v.kind == SV_STR) {
        char name[64];
        size_t n = v.u.str->len < sizeof name - 1 ? v.u.str->len : sizeof name - 1;
        for (size_t i = 0; i < n; i++) {
            char ch = v.u.str->s[i];
            name[i] = (ch >= 'A' && ch <= 'Z') ? (char)(ch + 32) : ch;
        }
        name[n] = 0;
        if (v.u.str->len >= sizeof name ||
            (!scad_color_by_name(name, rgba) && !scad_color_by_hex(name, rgba))) {
            scad_diag_warning(c->ev->d, c->st->loc, "Unable to parse color \"%s\"", name);
            scad_diag_line(c->ev->d, RAYSCAD_MSG_WARNING,
                           "Please see https://en.wikipedia.org/wiki/Web_colors");
        }
    }
    double alpha;
    if (scad_arg_num(c->arg[COLOR_ALPHA], &alpha)) rgba[3] = (float)alpha;
}

static int color_print(scad_call *c, const void *args, scad_buf *b)
{
    const color_args *p = args;
    (void)c;
    scad_buf_puts(b, "color([");
    for (int i = 0; i < 4; i++) {
        if (i) scad_buf_puts(b, ", ");
        scad_print_g(b, p->rgba[i]);
    }
    scad_buf_puts(b, "])");
    return 1;
}

static scad_geom *color_build(scad_call *c, const void *args)
{
    const float *rgba = ((const color_args *)args)->rgba;
    scad_state s = *c->state;
    int valid = !(rgba[0] < 0 || rgba[1] < 0 || rgba[2] < 0 || rgba[3] < 0) && !isnan(rgba[0]) &&
                !isnan(rgba[1]) && !isnan(rgba[2]) && !isnan(rgba[3]);
    if (!s.mat.has_color && valid) { /* the outermost valid color() wins */
        s.mat.has_color = 1;
        for (int i = 0; i < 4; i++)
            s.mat.rgba[i] = rgba[i] > 1 ? 1.0f : rgba[i];
    }
    return scad_call_children(c, &s);
}

static const char *const color_params[] = {"c", "alpha", NULL};
static const scad_module_def color = {"color",    color_params, 2,          sizeof(color_args),
                                      color_read, color_print,  color_build};

/* ---- CSG operations ------------------------------------------------------------------ */

static scad_geom *group_build(scad_call *c, const void *args)
{
    (void)args;
    csg_op op = CSG_OP_UNION;
    if (!strcmp(c->def->name, "difference")) op = CSG_OP_DIFFERENCE;
    if (!strcmp(c->def->name, "intersection")) op = CSG_OP_INTERSECTION;
    return scad_eval_children(c->ev, c->env, c->st, c->state, op);
}

static const scad_module_def union_ = {"union", NULL, -1, 0, NULL, NULL, group_build};
static const scad_module_def group = {"group", NULL, -1, 0, NULL, NULL, group_build};
static const scad_module_def difference = {"difference", NULL, -1, 0, NULL, NULL, group_build};
static const scad_module_def intersection = {"intersection", NULL, -1, 0, NULL, NULL, group_build};

typedef struct render_args {
    int convexity;
} render_args;

static void render_read(scad_call *c, void *out)
{
    ((render_args *)out)->convexity = scad_arg_int(c->arg[0], 1);
}

static int render_print(scad_call *c, const void *args, scad_buf *b)
{
    (void)c;
    scad_buf_printf(b, "render(convexity = %d)", ((const render_args *)args)->convexity);
    return 1;
}

static const char *const render_params[] = {"convexity", NULL};
static const scad_module_def render = {"render",    render_params, 1,          sizeof(render_args),
                                       render_read, render_print,  group_build};

const scad_module_def *const scad_operation_modules[] = {
    &translate, &rotate, &scale,      &mirror,       &multmatrix, &color,
    &union_,    &group,  &difference, &intersection, &render,     NULL};
