/*
 * settings.c — a file's $rs_ scene settings onto the command's options.
 * An option counts as unset while it holds its default (0 for the light
 * model's fields, 1 for --samples), so a flag always wins over the file.
 */
#include "settings.h"

#include <math.h>
#include <string.h>

/* A boolean arrives as 0 or 1 (rayscad_model_setting), so only $rs_shadows is one;
 * the others take numbers, in the same ranges as their flags. */
typedef struct setting {
    const char *name;
    double lo, hi; /* the valid range, inclusive */
    int integer;
} setting;

static const setting known[] = {
    {"$rs_shadows", 0, 1, 1},          {"$rs_light_samples", 1, 16, 1}, {"$rs_bounces", 1, 64, 1},
    {"$rs_refract", 1, 10, 0},         {"$rs_aperture", 0, 1e9, 0},     {"$rs_focus", 0, 1e9, 0},
    {"$rs_xray", 1e-9, 1, 0},          {"$rs_thickness", 1e-9, 1e9, 0}, {"$rs_samples", 1, 16, 1},
    {"$rs_path_trace", 1, 1000000, 1},
};

/* The option a setting fills, and whether the command line left it unset. */
static double *slot(cli_options *o, const char *name, double *tmp, int *unset)
{
    rayscad_render_options *p = &o->optics;
    if (!strcmp(name, "$rs_aperture")) return *unset = p->aperture == 0, &p->aperture;
    if (!strcmp(name, "$rs_focus")) return *unset = p->focus == 0, &p->focus;
    if (!strcmp(name, "$rs_xray")) return *unset = p->xray == 0, &p->xray;
    if (!strcmp(name, "$rs_thickness")) return *unset = p->absorb == 0, &p->absorb;
    if (!strcmp(name, "$rs_refract")) return *unset = p->ior == 0, &p->ior;
    if (!strcmp(name, "$rs_shadows")) *unset = p->shadows == 0;
    if (!strcmp(name, "$rs_light_samples")) *unset = p->light_samples == 0;
    if (!strcmp(name, "$rs_bounces")) *unset = p->bounces == 0;
    if (!strcmp(name, "$rs_samples")) *unset = o->samples == 1;
    if (!strcmp(name, "$rs_path_trace")) *unset = p->path_trace == 0;
    return tmp; /* an int option: copied back by the caller */
}

void cli_settings_apply(cli_options *o, const rayscad_model *m, FILE *warn)
{
    for (int i = 0; i < rayscad_model_setting_count(m); i++) {
        double v;
        const char *name = rayscad_model_setting(m, i, &v);
        const setting *k = NULL;
        for (size_t j = 0; j < sizeof known / sizeof known[0]; j++)
            if (!strcmp(known[j].name, name)) k = &known[j];
        if (!k) continue;
        if (!(v >= k->lo && v <= k->hi) || (k->integer && v != floor(v))) {
            if (warn)
                fprintf(warn, "rayscad: warning: %s = %g is outside %g..%g%s; ignored\n", k->name,
                        v, k->lo, k->hi, k->integer ? " (whole numbers)" : "");
            continue;
        }
        double tmp = 0;
        int unset = 0;
        double *dst = slot(o, k->name, &tmp, &unset);
        if (!unset) continue;
        *dst = v;
        if (dst != &tmp) continue;
        if (!strcmp(k->name, "$rs_shadows")) o->optics.shadows = v != 0;
        if (!strcmp(k->name, "$rs_light_samples")) o->optics.light_samples = (int)v;
        if (!strcmp(k->name, "$rs_bounces")) o->optics.bounces = (int)v;
        if (!strcmp(k->name, "$rs_samples")) o->samples = (int)v;
        if (!strcmp(k->name, "$rs_path_trace")) o->optics.path_trace = (int)v;
    }
}
