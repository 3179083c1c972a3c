/*
 * model.c — rayscad_model: a .scad file evaluated by src/scad with the
 * library's services, the .csg text of the same evaluation rule without
 * geometry, and the .ast and .term texts of its parse.  The public options
 * become scad_options here, once.
 */
#include <stdlib.h>
#include <string.h>

#include "rayscad_internal.h"
#include "services.h"

/* The scad_options of o (may be NULL), with services (filled here) as its
 * services. */
static void scad_options_of(const rayscad_eval_options *o, scad_services *services,
                            scad_options *so)
{
    memset(so, 0, sizeof *so);
    rayscad_scad_services(o ? o->services : NULL, services);
    so->services = services;
    if (!o) return;
    so->defines = o->defines;
    so->define_count = o->define_count;
    so->message = o->message;
    so->ud = o->message_ud;
    so->max_recursion = o->max_recursion;
    so->max_steps = o->max_steps;
    so->max_list = o->max_list;
    so->max_string = o->max_string;
    so->facets = (int)o->facets;
    so->for_mesh = o->for_mesh;
    so->for_2d = o->for_2d;
    so->library_path = o->library_path;
    so->hard_warnings = o->hard_warnings;
    so->no_parameter_check = o->no_parameter_check;
    so->range_check = o->range_check;
    so->parameters = o->parameters;
    so->parameters_ud = o->parameters_ud;
    so->progress = o->progress;
    so->progress_ud = o->progress_ud;
    so->view_set = o->view_set;
    memcpy(so->vpr, o->vpr, sizeof so->vpr);
    memcpy(so->vpt, o->vpt, sizeof so->vpt);
    so->vpd = o->vpd;
}

static rayscad_status load(const char *name, const char *src, const rayscad_eval_options *o,
                           rayscad_model **out)
{
    *out = NULL;
    rayscad_model *m = calloc(1, sizeof *m);
    if (!m) return RAYSCAD_ERROR_MEMORY;
    scad_services services;
    scad_options so;
    scad_options_of(o, &services, &so);
    int rc = src ? scad_eval_string(name, src, &so, &m->r) : scad_eval_file(name, &so, &m->r);
    if (rc != 0) {
        free(m);
        return RAYSCAD_ERROR;
    }
    *out = m;
    return RAYSCAD_OK;
}

rayscad_status rayscad_model_load(const char *path, const rayscad_eval_options *o,
                                  rayscad_model **out)
{
    return load(path, NULL, o, out);
}

rayscad_status rayscad_model_load_string(const char *name, const char *src,
                                         const rayscad_eval_options *o, rayscad_model **out)
{
    return load(name ? name : "<string>", src ? src : "", o, out);
}

void rayscad_model_free(rayscad_model *m)
{
    if (!m) return;
    scad_result_free(&m->r);
    free(m);
}

void rayscad_model_file_view(const rayscad_model *m, rayscad_file_view *out)
{
    out->set = m->r.vp_set;
    out->auto_off = m->r.vp_auto_off;
    memcpy(out->vpr, m->r.vpr, sizeof out->vpr);
    memcpy(out->vpt, m->r.vpt, sizeof out->vpt);
    out->vpd = m->r.vpd;
    out->vpf = m->r.vpf;
}

int rayscad_model_setting_count(const rayscad_model *m)
{
    return m->r.nsettings;
}

const char *rayscad_model_setting(const rayscad_model *m, int i, double *value)
{
    if (i < 0 || i >= m->r.nsettings) return NULL;
    if (value) *value = m->r.settings[i].value;
    return m->r.settings[i].name;
}

/* One of scad.h's text dumps (.csg, .ast) of a file (src NULL) or a string. */
typedef struct dumper {
    int (*file)(const char *path, const scad_options *opt, char **text, size_t *len);
    int (*string)(const char *name, const char *src, const scad_options *opt, char **text,
                  size_t *len);
} dumper;

static const dumper csg_dump = {scad_dump_csg_file, scad_dump_csg_string};
static const dumper ast_dump = {scad_dump_ast_file, scad_dump_ast_string};

static rayscad_status dump_text(const dumper *d, const char *name, const char *src,
                                const rayscad_eval_options *o, char **text, size_t *len)
{
    scad_services services;
    scad_options so;
    scad_options_of(o, &services, &so);
    int rc = src ? d->string(name, src, &so, text, len) : d->file(name, &so, text, len);
    return rc == 0 ? RAYSCAD_OK : RAYSCAD_ERROR;
}

rayscad_status rayscad_csg_text(const char *path, const rayscad_eval_options *o, char **text,
                                size_t *len)
{
    return dump_text(&csg_dump, path, NULL, o, text, len);
}

rayscad_status rayscad_csg_text_string(const char *name, const char *src,
                                       const rayscad_eval_options *o, char **text, size_t *len)
{
    return dump_text(&csg_dump, name ? name : "<string>", src ? src : "", o, text, len);
}

rayscad_status rayscad_ast_text(const char *path, const rayscad_eval_options *o, char **text,
                                size_t *len)
{
    return dump_text(&ast_dump, path, NULL, o, text, len);
}

rayscad_status rayscad_ast_text_string(const char *name, const char *src,
                                       const rayscad_eval_options *o, char **text, size_t *len)
{
    return dump_text(&ast_dump, name ? name : "<string>", src ? src : "", o, text, len);
}

/* openscad.cc 2021.01 builds the term with a CSGTreeEvaluator that has no
 * GeometryEvaluator: its leaves (CSGTreeEvaluator::visit of AbstractPolyNode,
 * RenderNode and CgaladvNode) are made from geometry only, so each is a
 * null term, every operation on null terms is null
 * (CSGOperation::createCSGNode), and the root is null whatever the file
 * holds.  What is left of the output is whether the file parses. */
static rayscad_status term_text(const char *name, const char *src, const rayscad_eval_options *o,
                                char **text, size_t *len)
{
    static const char empty[] = "No top-level CSG object\n";
    char *ast;
    rayscad_status rc = dump_text(&ast_dump, name, src, o, &ast, NULL);
    *text = NULL;
    if (len) *len = 0;
    if (rc != RAYSCAD_OK) return rc;
    free(ast);
    *text = malloc(sizeof empty);
    if (!*text) return RAYSCAD_ERROR_MEMORY;
    memcpy(*text, empty, sizeof empty);
    if (len) *len = sizeof empty - 1;
    return RAYSCAD_OK;
}

rayscad_status rayscad_term_text(const char *path, const rayscad_eval_options *o, char **text,
                                 size_t *len)
{
    return term_text(path, NULL, o, text, len);
}

rayscad_status rayscad_term_text_string(const char *name, const char *src,
                                        const rayscad_eval_options *o, char **text, size_t *len)
{
    return term_text(name ? name : "<string>", src ? src : "", o, text, len);
}
