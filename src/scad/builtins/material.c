/*
 * material.c — rayscad's optical $-variables.  OpenSCAD treats any $name it
 * does not know as an ordinary special variable: it is dynamically scoped,
 * inherited by everything instantiated below the call or assignment that
 * set it, and otherwise ignored.  So a file that says
 *     color("silver") mirror_plate($rs_reflect = 0.8);
 * still opens unchanged in OpenSCAD, and here gives the plate's leaves a
 * reflective material.  The variables:
 *   $rs_reflect  mirror reflectivity, clamped to [0, 1]
 *   $rs_absorb   Beer–Lambert coefficient per mm (>= 0): the solid's
 *                opacity over a path of length L is 1 - exp(-k·L)
 *   $rs_ior      index of refraction (>= 1; 1 = none)
 *   $rs_light    a light: the leaf glows and lights the scene with this
 *                intensity (true = 1); its centre and size make an area light
 * Invariant: a leaf with none of them set keeps all optical fields 0, the
 * renderer's OpenSCAD look.
 */
#include "builtins.h"

#include <math.h>

/* The number a $rs_ variable holds (a bool counts as 0 or 1) where the
 * call sees it (its own $-arguments are in its scope); 0 when unset. */
static int lookup(scad_call *c, const char *name, double *out)
{
    scad_value v = scad_env_lookup_cstr(c->ev, c->env, name, c->st->loc, 1, NULL);
    if (v.kind == SV_BOOL) {
        *out = v.u.b ? 1 : 0;
        return 1;
    }
    if (v.kind != SV_NUM || isnan(v.u.num)) return 0;
    *out = v.u.num;
    return 1;
}

static float clampf(double x, double lo, double hi)
{
    return (float)(x < lo ? lo : x > hi ? hi : x);
}

/* The world centre of s and a radius that encloses it (for area lights):
 * the object-space centre and half-extent mapped by xf, its scale taken as
 * the cube root of |det|. */
static void light_shape(const iv_shape *s, const csg_affine xf, float light[4])
{
    double c[3] = {0, 0, 0}, r = 0;
    switch (s->kind) {
    case IV_SHAPE_SPHERE:
        r = s->u.sphere.r;
        break;
    case IV_SHAPE_BOX:
        for (int i = 0; i < 3; i++) {
            double h = (s->u.box.hi[i] - s->u.box.lo[i]) / 2;
            c[i] = (s->u.box.hi[i] + s->u.box.lo[i]) / 2;
            r += h * h;
        }
        r = sqrt(r);
        break;
    case IV_SHAPE_CONE:
        c[2] = s->u.cone.h / 2;
        r = fmax(s->u.cone.r1, s->u.cone.r2);
        break;
    default:
        break;
    }
    double w[3];
    csg_affine_point(xf, c, w);
    double det = xf[0] * (xf[5] * xf[10] - xf[6] * xf[9]) -
                 xf[1] * (xf[4] * xf[10] - xf[6] * xf[8]) + xf[2] * (xf[4] * xf[9] - xf[5] * xf[8]);
    double scale = cbrt(fabs(det));
    for (int i = 0; i < 3; i++)
        light[i] = (float)w[i];
    light[3] = (float)(isfinite(r * scale) ? r * scale : 0);
}

void scad_material_apply(scad_call *c, const iv_shape *s, const csg_affine xf, csg_material *m)
{
    double x;
    if (lookup(c, "$rs_reflect", &x)) m->reflect = clampf(x, 0, 1);
    if (lookup(c, "$rs_absorb", &x)) m->absorb = clampf(x, 0, 1e6);
    if (lookup(c, "$rs_ior", &x)) m->ior = x > 1 ? clampf(x, 1, 10) : 0;
    if (lookup(c, "$rs_light", &x) && x > 0) {
        m->emit = clampf(x, 0, 1e6);
        light_shape(s, xf, m->light);
    }
}
