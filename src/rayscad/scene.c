/*
 * scene.c — rayscad_scene (a model's trees committed for rays) and
 * OpenSCAD's rule for the camera: the view resolved against the bounds of
 * all three roots, as OpenSCAD 2021.01 frames the '#' and '%' subtrees too.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "../render/render.h"
#include "rayscad_internal.h"

void rayscad_say(char *err, size_t errlen, const char *fmt, ...)
{
    if (!err || !errlen) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

rayscad_status rayscad_scene_new(rayscad_model *m, rayscad_scene **out, char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    *out = NULL;
    rayscad_scene *s = calloc(1, sizeof *s);
    if (!s) {
        rayscad_say(err, errlen, "out of memory");
        return RAYSCAD_ERROR_MEMORY;
    }
    s->facet_sag = m->r.facet_sag;
    csg_node *roots[3] = {m->r.model, m->r.highlight, m->r.background};
    m->r.model = m->r.highlight = m->r.background = NULL;
    s->s = csg_scene_new(roots, 3, err, errlen);
    if (!s->s) {
        free(s);
        return RAYSCAD_ERROR;
    }
    *out = s;
    return RAYSCAD_OK;
}

void rayscad_scene_free(rayscad_scene *s)
{
    if (!s) return;
    csg_scene_free(s->s);
    free(s);
}

double rayscad_scene_facet_deviation(const rayscad_scene *s)
{
    return s->facet_sag;
}

int rayscad_scene_bounds(const rayscad_scene *s, int r, double lo[3], double hi[3])
{
    return csg_scene_bounds(s->s, r, lo, hi);
}

rayscad_status rayscad_camera_frame(const rayscad_scene *s, const rayscad_view *v, int width,
                                    int height, rayscad_camera *out, char *err, size_t errlen)
{
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int have_bounds = 0;
    for (int r = 0; r < csg_scene_root_count(s->s); r++) {
        double l[3], h[3];
        if (csg_scene_view_bounds(s->s, r, l, h) != 0) continue;
        for (int k = 0; k < 3; k++) {
            lo[k] = have_bounds && lo[k] < l[k] ? lo[k] : l[k];
            hi[k] = have_bounds && hi[k] > h[k] ? hi[k] : h[k];
        }
        have_bounds = 1;
    }
    if (render_camera_resolve(v, lo, hi, have_bounds, width, height, out) == 0) return RAYSCAD_OK;
    if (v->kind == RAYSCAD_CAMERA_DEFAULT) /* the file's $vp* made it */
        rayscad_say(err, errlen,
                    "the file's $vpr/$vpt/$vpd/$vpf give no usable camera (a distance that is "
                    "zero, negative or not finite)");
    else
        rayscad_say(err, errlen, "the camera's eye and centre coincide");
    return RAYSCAD_ERROR_ARGUMENT;
}

rayscad_status rayscad_colors_by_name(const char *name, rayscad_colors *out)
{
    return render_colors_by_name(name, out) == 0 ? RAYSCAD_OK : RAYSCAD_ERROR_ARGUMENT;
}

const char *rayscad_colors_name(int i)
{
    return render_colors_name(i);
}
