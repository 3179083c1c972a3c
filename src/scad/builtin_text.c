/*
 * builtin_text.c — text(): OpenSCAD 2021.01's arguments and defaults (a
 * string argument that is not a string is taken as absent, as OpenSCAD's
 * lookup_variable_with_default does), the curve resolution it derives from
 * $fn/$fa/$fs (fragments of a circle of radius size, / 8, + 1, at least 2
 * points per curve), and the outlines from the text service, as one region
 * leaf in the call's frame.
 */
#include "geom2d.h"

#include <math.h>
#include <stdlib.h>

static const char *str_arg(const scad_argv *a, const char *name, int pos, const char *dflt)
{
    scad_value v = scad_argv_get(a, name, pos);
    return v.kind == SV_STR ? v.u.str->s : dflt;
}

static double num_arg(const scad_argv *a, const char *name, int pos, double dflt)
{
    double x;
    return scad_to_num(scad_argv_get(a, name, pos), &x) ? x : dflt;
}

scad_geom *scad_module_text(scad_eval *ev, scad_env *env, const scad_stmt *st,
                            const scad_argv *a, const scad_state *state)
{
    static const char *const known[] = {"text",   "size",   "font",    "direction", "language",
                                        "script", "halign", "valign",  "spacing",   NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    scad_eval_children(ev, env, st, state, CSG_OP_UNION); /* text() takes none */
    scad_text_params p;
    p.text = str_arg(a, "text", 0, "");
    p.size = num_arg(a, "size", 1, 10);
    p.font = str_arg(a, "font", 2, "");
    p.direction = str_arg(a, "direction", -1, "");
    p.language = str_arg(a, "language", -1, "en");
    p.script = str_arg(a, "script", -1, "");
    p.halign = str_arg(a, "halign", -1, "left");
    p.valign = str_arg(a, "valign", -1, "baseline");
    p.spacing = num_arg(a, "spacing", -1, 1);
    int n = scad_fragments(p.size, scad_facets_lookup(ev, env, a, st->loc));
    p.segments = (int)fmax(floor(n / 8.0) + 1, 2);
    if (!*p.text || !isfinite(p.size) || !isfinite(p.spacing)) return NULL;
    const scad_services *s = ev->services;
    if (!s->text) {
        scad_diag_error(ev->d, st->loc, "text() is not available here (no font service)");
        return NULL;
    }
    scad_paths out = {NULL, NULL, 0};
    char err[256];
    if (s->text(s->ud, &p, &out, err, sizeof err) != 0) {
        scad_diag_error(ev->d, st->loc, "text(): %s", err);
        return NULL;
    }
    scad_geom *g = scad_region_geom(ev, &out, state);
    scad_paths_free(&out);
    return g;
}
