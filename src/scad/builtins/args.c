/*
 * args.c — reading a builtin module's arguments as OpenSCAD 2021.01 reads
 * them: its Value conversions (getDouble, getVec2/getVec3, toBool of a
 * boolean only), lookup_radius, and the $fn/$fa/$fs a node keeps.  A value
 * of the wrong type leaves the default in place, as OpenSCAD's nodes do;
 * only the warnings OpenSCAD gives are given.
 */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "../../geom/fragments.h"
#include "builtins.h"

int scad_arg_num(scad_value v, double *x)
{
    if (v.kind != SV_NUM) return 0;
    *x = v.u.num;
    return 1;
}

int scad_arg_vec(scad_value v, int n, double *out)
{
    if (v.kind != SV_VEC || v.u.vec->n != n) return 0;
    for (int i = 0; i < n; i++)
        if (!scad_arg_num(v.u.vec->v[i], &out[i])) return 0;
    return 1;
}

int scad_arg_bool(scad_value v, int dflt)
{
    return v.kind == SV_BOOL ? v.u.b : dflt;
}

int scad_arg_int(scad_value v, int dflt)
{
    double x;
    if (!scad_arg_num(v, &x) || !isfinite(x)) return dflt;
    if (x >= INT_MAX) return INT_MAX;
    if (x <= INT_MIN) return INT_MIN;
    return (int)x;
}

int scad_arg_radius(scad_call *c, int d, int r, const char *dname, const char *rname, double *out)
{
    double x;
    if (scad_arg_num(c->arg[d], &x)) {
        if (c->arg[r].kind == SV_NUM)
            scad_diag_warning(c->ev->d, c->st->loc,
                              "Ignoring radius variable '%s' as diameter '%s' is defined too.",
                              rname, dname);
        *out = x / 2;
        return 1;
    }
    return scad_arg_num(c->arg[r], out);
}

/* A $-variable as the call sees it, as a number (0 when it is none). */
static double special(scad_call *c, const char *name)
{
    double x = 0;
    scad_arg_num(scad_env_lookup_cstr(c->ev, c->env, name, c->st->loc, 1, NULL), &x);
    return x;
}

scad_facet_params scad_facets_read(scad_call *c)
{
    scad_facet_params f = {special(c, "$fn"), special(c, "$fa"), special(c, "$fs")};
    return f;
}

scad_facet_params scad_facets_read_clamped(scad_call *c)
{
    scad_facet_params f = scad_facets_read(c);
    if (f.fs < 0.01) {
        scad_diag_warning(c->ev->d, c->st->loc, "$fs too small - clamping to %f", 0.01);
        f.fs = 0.01;
    }
    if (f.fa < 0.01) {
        scad_diag_warning(c->ev->d, c->st->loc, "$fa too small - clamping to %f", 0.01);
        f.fa = 0.01;
    }
    return f;
}

int scad_fragments(double r, scad_facet_params f)
{
    return geom_fragments(r, f.fn, f.fa, f.fs);
}

/* AUTO draws OpenSCAD's facets where the user asked for coarse ones: the
 * fragment count for radius r is at most 16 and comes from settings the
 * user changed ($fn set, or $fa/$fs off their defaults 12 and 2) — a
 * cylinder($fn = 6) nut, a sphere under $fa = 30.  OpenSCAD's defaults
 * alone stay smooth, even for a small sphere they would cut into 10. */
int scad_facets_shown(const scad_eval *ev, scad_facet_params f, double r)
{
    if (ev->facets == RAYSCAD_FACETS_OPENSCAD) return 1;
    if (ev->facets == RAYSCAD_FACETS_SMOOTH) return 0;
    int chosen = f.fn > 0 || f.fa != 12 || f.fs != 2;
    return chosen && scad_fragments(r, f) <= 16;
}
