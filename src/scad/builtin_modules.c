/*
 * builtin_modules.c — cube (sphere and cylinder are builtin_geometry.c's,
 * with OpenSCAD's facets), the transforms (translate, rotate, scale, mirror, multmatrix), color, and the
 * CSG operations (union, group, render, difference, intersection).
 *
 * A transform composes its matrix onto the inherited world_from_object
 * (state.xf ∘ M, so M applies first) and evaluates its children with it;
 * leaves copy the full transform, so nothing is multiplied per ray.
 * Arguments follow OpenSCAD 2021.01: positional order, defaults, the
 * degenerate sizes (a zero cube edge, NaN) produce nothing, silently, as
 * OpenSCAD.
 */
#include <math.h>
#include <string.h>

#include "builtin_geometry.h"
#include "eval.h"
#include "material.h"

static int num_of(scad_value v, double *x)
{
    if (v.kind != SV_NUM) return 0;
    *x = v.u.num;
    return 1;
}

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

/* A leaf at state's transform (then local, when given); its material is the
 * inherited colour plus the $rs_ optics visible here (material.c). */
static scad_geom *leaf(scad_eval *ev, scad_env *env, const scad_argv *a, const iv_shape *s,
                       const scad_state *state, const csg_affine local)
{
    scad_state st = *state;
    if (local) csg_affine_mul(state->xf, local, st.xf);
    scad_material_apply(ev, env, a, s, st.xf, &st.mat);
    return scad_geom_leaf(ev, s, &st);
}

static scad_geom *m_cube(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                         const scad_state *state)
{
    (void)env;
    static const char *const known[] = {"size", "center", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double s[3] = {1, 1, 1};
    scad_value size = scad_argv_get(a, "size", 0);
    double x;
    int ok = size.kind == SV_UNDEF;
    if (num_of(size, &x)) {
        s[0] = s[1] = s[2] = x;
        ok = 1;
    } else if (size.kind == SV_VEC && size.u.vec->n == 3) {
        /* as Value::getVec3: elements that are numbers are taken */
        ok = 1;
        for (int i = 0; i < 3; i++)
            if (!num_of(size.u.vec->v[i], &s[i])) ok = 0;
    }
    if (!ok) {
        scad_buf b = {0};
        scad_value_format(&b, size, 1);
        scad_diag_warning(ev->d, st->loc,
                          "Unable to convert cube(size=%s, ...) parameter to a number or a vec3 "
                          "of numbers",
                          scad_buf_str(&b));
        scad_buf_free(&b);
    }
    for (int i = 0; i < 3; i++)
        if (!(s[i] > 0) || !isfinite(s[i])) return NULL;
    int center = scad_value_truthy(scad_argv_get(a, "center", 1)) &&
                 scad_argv_get(a, "center", 1).kind == SV_BOOL;
    iv_shape sh;
    memset(&sh, 0, sizeof sh);
    sh.kind = IV_SHAPE_BOX;
    for (int i = 0; i < 3; i++) {
        sh.u.box.lo[i] = center ? -s[i] / 2 : 0;
        sh.u.box.hi[i] = center ? s[i] / 2 : s[i];
    }
    return leaf(ev, env, a, &sh, state, NULL);
}

static scad_geom *with_matrix(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_state *state, const csg_affine m)
{
    scad_state s = *state;
    csg_affine_mul(state->xf, m, s.xf);
    return scad_eval_children(ev, env, st, &s, CSG_OP_UNION);
}

static void identity(csg_affine m)
{
    memcpy(m, csg_affine_identity, sizeof(csg_affine));
}

static void translate_matrix(scad_eval *ev, const scad_stmt *st, const scad_argv *a, csg_affine m)
{
    static const char *const known[] = {"v", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double v[3] = {0, 0, 0};
    identity(m);
    if (vec3_of(scad_argv_get(a, "v", 0), v)) {
        m[3] = v[0];
        m[7] = v[1];
        m[11] = v[2];
    }
}

static void rotate_matrix(scad_eval *ev, const scad_stmt *st, const scad_argv *a, csg_affine m)
{
    static const char *const known[] = {"a", "v", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    identity(m);
    scad_value av = scad_argv_get(a, "a", 0);
    scad_value vv = scad_argv_get(a, "v", 1);
    if (av.kind == SV_VEC) {
        double ang[3] = {0, 0, 0};
        for (int i = 0; i < av.u.vec->n && i < 3; i++)
            num_of(av.u.vec->v[i], &ang[i]);
        double sx = scad_sin_degrees(ang[0]), cx = scad_cos_degrees(ang[0]);
        double sy = scad_sin_degrees(ang[1]), cy = scad_cos_degrees(ang[1]);
        double sz = scad_sin_degrees(ang[2]), cz = scad_cos_degrees(ang[2]);
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
        if (num_of(av, &ang) && isfinite(ang)) {
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
            double s = scad_sin_degrees(ang), c = scad_cos_degrees(ang), t = 1 - c;
            double x = ax[0], y = ax[1], z = ax[2];
            if (x == 0 && y == 0 && z == 0) {
                /* OpenSCAD 2021.01 skips the rotation for a zero axis */
            } else {
                csg_affine r = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, 0,
                                t * x * y + s * z, t * y * y + c,     t * y * z - s * x, 0,
                                t * x * z - s * y, t * y * z + s * x, t * z * z + c,     0};
                memcpy(m, r, sizeof r);
            }
        }
    }
}

static void scale_matrix(scad_eval *ev, const scad_stmt *st, const scad_argv *a, csg_affine m)
{
    static const char *const known[] = {"v", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double v[3] = {1, 1, 1}, x;
    scad_value sv = scad_argv_get(a, "v", 0);
    if (num_of(sv, &x))
        v[0] = v[1] = v[2] = x;
    else
        vec3_of(sv, v);
    csg_affine r = {v[0], 0, 0, 0, 0, v[1], 0, 0, 0, 0, v[2], 0};
    memcpy(m, r, sizeof r);
}

static void mirror_matrix(scad_eval *ev, const scad_stmt *st, const scad_argv *a, csg_affine m)
{
    static const char *const known[] = {"v", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double v[3] = {0, 0, 0};
    identity(m);
    if (vec3_of(scad_argv_get(a, "v", 0), v)) {
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

static void multmatrix_matrix(scad_eval *ev, const scad_stmt *st, const scad_argv *a, csg_affine m)
{
    static const char *const known[] = {"m", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    identity(m);
    scad_value mv = scad_argv_get(a, "m", 0);
    if (mv.kind == SV_VEC) {
        for (int i = 0; i < 3 && i < mv.u.vec->n; i++) {
            scad_value row = mv.u.vec->v[i];
            if (row.kind != SV_VEC) continue;
            for (int j = 0; j < 4 && j < row.u.vec->n; j++)
                num_of(row.u.vec->v[j], &m[i * 4 + j]);
        }
    }
}

int scad_transform_matrix(scad_eval *ev, const scad_stmt *st, const scad_argv *a, csg_affine m)
{
    static const struct {
        const char *name;
        void (*fn)(scad_eval *, const scad_stmt *, const scad_argv *, csg_affine);
    } xf[] = {{"translate", translate_matrix},
              {"rotate", rotate_matrix},
              {"scale", scale_matrix},
              {"mirror", mirror_matrix},
              {"multmatrix", multmatrix_matrix}};
    for (size_t i = 0; i < sizeof xf / sizeof xf[0]; i++) {
        if (strcmp(xf[i].name, st->name) == 0) {
            xf[i].fn(ev, st, a, m);
            return 1;
        }
    }
    return 0;
}

static scad_geom *m_transform(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                              const scad_state *state)
{
    csg_affine m;
    identity(m);
    scad_transform_matrix(ev, st, a, m);
    return with_matrix(ev, env, st, state, m);
}

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

static scad_geom *m_color(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                          const scad_state *state)
{
    static const char *const known[] = {"c", "alpha", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    float rgba[4] = {-1, -1, -1, 1};
    scad_value c = scad_argv_get(a, "c", 0);
    if (c.kind == SV_VEC) {
        for (int i = 0; i < 4; i++) {
            double x = 1;
            if (i < c.u.vec->n) {
                x = 0;
                num_of(c.u.vec->v[i], &x);
            }
            rgba[i] = (float)x;
            if (rgba[i] > 1 || rgba[i] < 0)
                scad_diag_warning(
                    ev->d, st->loc,
                    "color() expects numbers between 0.0 and 1.0. Value of %.1f is out of range",
                    (double)rgba[i]);
        }
    } else if (c.kind == SV_STR) {
        char name[64];
        size_t n = c.u.str->len < sizeof name - 1 ? c.u.str->len : sizeof name - 1;
        for (size_t i = 0; i < n; i++) {
            char ch = c.u.str->s[i];
            name[i] = (ch >= 'A' && ch <= 'Z') ? (char)(ch + 32) : ch;
        }
        name[n] = 0;
        if (c.u.str->len >= sizeof name ||
            (!scad_color_by_name(name, rgba) && !scad_color_by_hex(name, rgba))) {
            char shown[64];
            memcpy(shown, name, n + 1);
            scad_diag_warning(ev->d, st->loc, "Unable to parse color \"%s\"", shown);
            scad_diag_line(ev->d, SCAD_MSG_WARNING,
                           "Please see https://en.wikipedia.org/wiki/Web_colors");
        }
    }
    double alpha;
    if (num_of(scad_argv_get(a, "alpha", 1), &alpha)) rgba[3] = (float)alpha;
    scad_state s = *state;
    int valid = !(rgba[0] < 0 || rgba[1] < 0 || rgba[2] < 0 || rgba[3] < 0) && !isnan(rgba[0]) &&
                !isnan(rgba[1]) && !isnan(rgba[2]) && !isnan(rgba[3]);
    if (!s.mat.has_color && valid) { /* the outermost valid color() wins */
        s.mat.has_color = 1;
        for (int i = 0; i < 4; i++)
            s.mat.rgba[i] = rgba[i] > 1 ? 1.0f : rgba[i];
    }
    return scad_eval_children(ev, env, st, &s, CSG_OP_UNION);
}

static scad_geom *m_group(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                          const scad_state *state)
{
    static const char *const none[] = {NULL};
    static const char *const render[] = {"convexity", NULL};
    scad_check_arg_names(ev, a, st->loc, strcmp(st->name, "render") ? none : render);
    csg_op op = CSG_OP_UNION;
    if (!strcmp(st->name, "difference")) op = CSG_OP_DIFFERENCE;
    if (!strcmp(st->name, "intersection")) op = CSG_OP_INTERSECTION;
    return scad_eval_children(ev, env, st, state, op);
}

static const struct {
    const char *name;
    scad_builtin_mod fn;
} table[] = {
    {"color", m_color},          {"cube", m_cube},           {"difference", m_group},
    {"group", m_group},          {"intersection", m_group},  {"mirror", m_transform},
    {"multmatrix", m_transform}, {"render", m_group},        {"rotate", m_transform},
    {"scale", m_transform},      {"translate", m_transform}, {"union", m_group},
};

scad_builtin_mod scad_builtin_module(const char *name)
{
    scad_builtin_mod g = scad_geometry_module(name); /* 2D, extrusions, facets */
    if (g) return g;
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (strcmp(table[i].name, name) == 0) return table[i].fn;
    return NULL;
}
