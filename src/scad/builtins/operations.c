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

/* OpenSCAD 2021.01's Value::getVec3, quirks and all: a vector of 3 is
 * read in order and stored as read, so a bad element leaves the earlier
 * ones set (mirror and scale use them), 1 when all were numbers; a vector
 * of 2 sets x and y only when both are numbers, z = dflt, and gives 1
 * either way. */
static int get_vec3(scad_value v, double out[3], double dflt)
{
    if (v.kind != SV_VEC || v.u.vec->n < 2 || v.u.vec->n > 3) return 0;
    const scad_value *e = v.u.vec->v;
    if (v.u.vec->n == 2) {
        if (e[0].kind == SV_NUM && e[1].kind == SV_NUM) {
            out[0] = e[0].u.num;
            out[1] = e[1].u.num;
        }
        out[2] = dflt;
        return 1;
    }
    for (int i = 0; i < 3; i++) {
        if (e[i].kind != SV_NUM) return 0;
        out[i] = e[i].u.num;
    }
    return 1;
}

/* The call's matrix as OpenSCAD keeps it: a full 4x4, row-major. */
typedef struct transform_args {
    double m[16];
} transform_args;

static void identity4(double m[16])
{
    for (int i = 0; i < 16; i++)
        m[i] = i % 5 == 0 ? 1 : 0;
}

/* m = the identity transform with its linear part times r (row-major
 * 3x3), summed as a matrix product as Eigen composes it, so an infinite or
 * NaN entry spreads NaN through its column exactly as openscad prints it. */
static void linear_onto_identity(double m[16], const double r[9])
{
    identity4(m);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double sum = 0;
            for (int k = 0; k < 3; k++)
                sum += (i == k ? 1.0 : 0.0) * r[k * 3 + j];
            m[i * 4 + j] = sum;
        }
}

/* "<name>(<value>)" for a warning, the value as echo prints it. */
static void conversion_warning(scad_call *c, const char *fmt, scad_value v)
{
    scad_buf b = {0};
    scad_value_format(&b, v, 1);
    scad_diag_warning(c->ev->d, c->st->loc, fmt, scad_buf_str(&b));
    scad_buf_free(&b);
}

static void translate_matrix(scad_call *c, double m[16])
{
    double v[3] = {0, 0, 0};
    identity4(m);
    if (get_vec3(c->arg[0], v, 0.0) && isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])) {
        m[3] = v[0];
        m[7] = v[1];
        m[11] = v[2];
    } else {
        conversion_warning(
            c, "Unable to convert translate(%s) parameter to a vec3 or vec2 of numbers", c->arg[0]);
    }
}

/* OpenSCAD's angle_axis_degrees: the rotation by a degrees about v (not
 * normalized first; none for a zero v), row-major 3x3. */
static void angle_axis(double a, const double v[3], double r[9])
{
    double s = iv_sin_degrees(a), co = iv_cos_degrees(a);
    double m = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    for (int i = 0; i < 9; i++)
        r[i] = i % 4 == 0 ? 1 : 0;
    if (!(m > 0)) return;
    double k = (1 - co) / m, len = sqrt(m);
    double cv[3] = {v[0] * k, v[1] * k, v[2] * k};
    double us[3] = {v[0] / len * s, v[1] / len * s, v[2] / len * s};
    double out[9] = {cv[0] * v[0] + co,    cv[1] * v[0] - us[2], cv[2] * v[0] + us[1],
                     cv[0] * v[1] + us[2], cv[1] * v[1] + co,    cv[2] * v[1] - us[0],
                     cv[0] * v[2] - us[1], cv[1] * v[2] + us[0], cv[2] * v[2] + co};
    memcpy(r, out, sizeof out);
}

/* rotate(a = [x, y, z]) or rotate(a, v), with 2021.01's conversions: the
 * angles read z, y, x, a bad one taking the value read before it; more
 * than three warn and use the first three. */
static void rotate_matrix(scad_call *c, double m[16])
{
    scad_value av = c->arg[0], vv = c->arg[1];
    scad_buf b = {0}, bv = {0};
    scad_value_format(&b, av, 1);
    scad_value_format(&bv, vv, 1);
    double r[9];
    if (av.kind == SV_VEC) {
        const scad_vec *va = av.u.vec;
        double sx = 0, sy = 0, sz = 0, cx = 1, cy = 1, cz = 1, a = 0;
        int ok = va->n <= 3;
        int n = va->n > 3 ? 3 : va->n;
        for (int k = n - 1; k >= 0; k--) {
            if (va->v[k].kind == SV_NUM)
                a = va->v[k].u.num;
            else
                ok = 0;
            if (!isfinite(a)) ok = 0;
            double sn = iv_sin_degrees(a), cs = iv_cos_degrees(a);
            if (k == 2) sz = sn, cz = cs;
            if (k == 1) sy = sn, cy = cs;
            if (k == 0) sx = sn, cx = cs;
        }
        if (ok && vv.kind != SV_UNDEF)
            scad_diag_warning(c->ev->d, c->st->loc,
                              "When parameter a is supplied as vector, v is ignored rotate(a=%s, "
                              "v=%s)",
                              scad_buf_str(&b), scad_buf_str(&bv));
        else if (!ok && vv.kind != SV_UNDEF)
            scad_diag_warning(c->ev->d, c->st->loc,
                              "Problem converting rotate(a=%s, v=%s) parameter", scad_buf_str(&b),
                              scad_buf_str(&bv));
        else if (!ok)
            scad_diag_warning(c->ev->d, c->st->loc, "Problem converting rotate(a=%s) parameter",
                              scad_buf_str(&b));
        double out[9] = {cy * cz,
                         cz * sx * sy - cx * sz,
                         cx * cz * sy + sx * sz,
                         cy * sz,
                         cx * cz + sx * sy * sz,
                         -cz * sx + cx * sy * sz,
                         -sy,
                         cy * sx,
                         cx * cy};
        memcpy(r, out, sizeof out);
    } else {
        double a = 0, v[3] = {0, 0, 1};
        int a_ok = av.kind == SV_NUM && isfinite(av.u.num);
        if (a_ok) a = av.u.num;
        int v_ok = get_vec3(vv, v, 0.0);
        angle_axis(a_ok ? a : 0, v, r);
        if (vv.kind != SV_UNDEF && !v_ok) {
            if (a_ok)
                scad_diag_warning(c->ev->d, c->st->loc,
                                  "Problem converting rotate(..., v=%s) parameter",
                                  scad_buf_str(&bv));
            else
                scad_diag_warning(c->ev->d, c->st->loc,
                                  "Problem converting rotate(a=%s, v=%s) parameter",
                                  scad_buf_str(&b), scad_buf_str(&bv));
        } else if (!a_ok) {
            scad_diag_warning(c->ev->d, c->st->loc, "Problem converting rotate(a=%s) parameter",
                              scad_buf_str(&b));
        }
    }
    scad_buf_free(&b);
    scad_buf_free(&bv);
    linear_onto_identity(m, r);
}

static void scale_matrix(scad_call *c, double m[16])
{
    double v[3] = {1, 1, 1};
    scad_value sv = c->arg[0];
    if (!get_vec3(sv, v, 1.0)) {
        if (sv.kind == SV_NUM)
            v[0] = v[1] = v[2] = sv.u.num;
        else
            conversion_warning(c,
                               "Unable to convert scale(%s) parameter to a number, a vec3 or vec2 "
                               "of numbers or a number",
                               sv);
    }
    double r[9] = {v[0], 0, 0, 0, v[1], 0, 0, 0, v[2]};
    linear_onto_identity(m, r);
}

/* mirror(v): the reflection across the plane through the origin normal to
 * v, (1, 0, 0) when v is no vector of 2 or 3 numbers (what was read of it
 * kept), none for a zero v; set, not composed, as OpenSCAD does. */
static void mirror_matrix(scad_call *c, double m[16])
{
    double v[3] = {1, 0, 0};
    identity4(m);
    if (!get_vec3(c->arg[0], v, 0.0))
        conversion_warning(c, "Unable to convert mirror(%s) parameter to a vec3 or vec2 of numbers",
                           c->arg[0]);
    double x = v[0], y = v[1], z = v[2];
    if (x == 0 && y == 0 && z == 0) return;
    double a = x * x + y * y + z * z;
    double r[16] = {1 - 2 * x * x / a,
                    -2 * y * x / a,
                    -2 * z * x / a,
                    0,
                    -2 * x * y / a,
                    1 - 2 * y * y / a,
                    -2 * z * y / a,
                    0,
                    -2 * x * z / a,
                    -2 * y * z / a,
                    1 - 2 * z * z / a,
                    0,
                    0,
                    0,
                    0,
                    1};
    memcpy(m, r, sizeof r);
}

/* multmatrix(m): up to 4x4 numbers over the identity (others ignored),
 * divided by m[3][3] when that is not 1. */
static void multmatrix_matrix(scad_call *c, double m[16])
{
    identity4(m);
    scad_value mv = c->arg[0];
    if (mv.kind != SV_VEC) return;
    for (int i = 0; i < 4 && i < mv.u.vec->n; i++) {
        scad_value row = mv.u.vec->v[i];
        if (row.kind != SV_VEC) continue;
        for (int j = 0; j < 4 && j < row.u.vec->n; j++)
            if (row.u.vec->v[j].kind == SV_NUM) m[i * 4 + j] = row.u.vec->v[j].u.num;
    }
    double w = m[15];
    if (w != 1.0)
        for (int i = 0; i < 16; i++)
            m[i] /= w;
}

static void transform_read(scad_call *c, void *out)
{
    static const struct {
        const char *name;
        void (*fn)(scad_call *, double[16]);
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
            scad_format_number(p->m[i * 4 + j], t);
            if (j) scad_buf_puts(b, ", ");
            scad_buf_puts(b, t);
        }
        scad_buf_puts(b, "]");
    }
    scad_buf_puts(b, "])");
    return 1;
}

/* The affine part builds: a projective bottom row (multmatrix's) is kept
 * for .csg only. */
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

/* render(): OpenSCAD's rendered geometry of the children, one object.  A
 * 2D subtree becomes the one region its booleans make (Clipper, as
 * OpenSCAD's), which also bounds it exactly (a difference from a huge
 * square, the usual way to invert a shape, bounds the view by what is
 * left, not by the square); 3D stays exact CSG. */
static scad_geom *render_build(scad_call *c, const void *args)
{
    (void)args;
    scad_eval *ev = c->ev;
    scad_geom *kids = scad_eval_children(ev, c->env, c->st, c->state, CSG_OP_UNION);
    int dims = scad_geom_dims(kids);
    if (dims == 2 && !kids->is_leaf) kids->whole = 1;
    if (dims != 1 || (kids->is_leaf && scad_geom_is_flat(kids))) return kids;
    csg_affine inv;
    if (csg_affine_invert(c->state->xf, inv) != 0) return kids;
    scad_paths r = {0};
    if (scad_flatten_2d(ev, kids, inv, scad_facets_read(c), c->st->loc, "render", &r) != 0)
        return NULL;
    scad_state st = *c->state;
    st.mat = kids->is_leaf ? kids->mat : st.mat;
    scad_geom *g = scad_region_geom(ev, &r, &st);
    scad_paths_free(&r);
    return g ? g : scad_geom_empty(ev);
}

static const char *const render_params[] = {"convexity", NULL};
static const scad_module_def render = {"render",    render_params, 1,           sizeof(render_args),
                                       render_read, render_print,  render_build};

const scad_module_def *const scad_operation_modules[] = {
    &translate, &rotate, &scale,      &mirror,       &multmatrix, &color,
    &union_,    &group,  &difference, &intersection, &render,     NULL};
