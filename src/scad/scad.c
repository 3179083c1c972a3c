/*
 * scad.c — the public entry points (scad.h): read, parse, apply -D
 * overrides, evaluate, and turn the evaluator's geometry into csg trees.
 *
 * The parse owns its AST in one arena and the evaluation its geometry in
 * another; both are freed before returning, so the caller owns nothing but
 * the csg trees in the result.  Evaluation runs on its own thread with a
 * large stack (EVAL_STACK bytes, reserved, not committed), so that deep but
 * legal recursion never depends on the caller's stack; the evaluator stops
 * with a named error well before that stack is used up.
 */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "ast_print.h"
#include "builtins/builtins.h"
#include "eval.h"
#include "registry.h"

enum { DEFAULT_MAX_RECURSION = 10000 };
/* Calls and loop values before the evaluation stops: a guard for runaway
 * input, set well above what real library code needs (BOSL2's
 * fractal_tree example takes 5e7, its gaussian_rands test 3e7). */
#define DEFAULT_MAX_STEPS 1000000000L
#define EVAL_STACK ((size_t)1 << 30)
#define STACK_MARGIN ((size_t)64 << 20)

/* ---- geometry → csg ------------------------------------------------------------ */

/* The csg tree of g (NULL for the empty set); with marked, of the leaves
 * a '#' still marks alone (one inside an extrusion is lost: extrude.c's
 * extrusion_colour).  Out of memory, *oom is set to the node that could
 * not be made or take a child (its location goes into the error). */
static csg_node *to_csg(const scad_geom *g, int marked, const scad_geom **oom)
{
    if (!g || *oom || scad_geom_is_empty(g) || (marked && g->is_leaf && !g->mat.highlight))
        return NULL;
    if (g->is_leaf) {
        csg_node *n = csg_node_shape(&g->shape, g->xf, &g->mat);
        if (!n) *oom = g;
        return n;
    }
    csg_node *n = csg_node_op(g->op);
    if (!n) {
        *oom = g;
        return NULL;
    }
    if (g->whole) csg_node_frame_whole(n);
    for (int i = 0; i < g->n; i++) {
        csg_node *k = to_csg(g->kids[i], marked, oom);
        if (k && csg_node_add(n, k) && !*oom) *oom = g;
    }
    return n;
}

#define PI 3.14159265358979323846

/* The largest factor by which affine xf stretches a length (its linear
 * part's largest column norm: exact for rotations and axis scales). */
static double stretch(const csg_affine xf)
{
    double best = 0;
    for (int c = 0; c < 3; c++)
        best = fmax(best, sqrt(xf[c] * xf[c] + xf[4 + c] * xf[4 + c] + xf[8 + c] * xf[8 + c]));
    return best;
}

/* The least facet sag of g's round leaves (scad_result.facet_sag); INFINITY
 * when none.  A leaf's fragments are those recorded when it was made
 * (g->cap); a revolve's, its steps over its angle at the region's widest
 * radius. */
static double facet_sag(const scad_geom *g)
{
    if (!g) return INFINITY;
    if (!g->is_leaf) {
        double best = INFINITY;
        for (int i = 0; i < g->n; i++)
            best = fmin(best, facet_sag(g->kids[i]));
        return best;
    }
    const iv_shape *sh = &g->shape;
    double r = 0, half = 0; /* radius, half the angle of one fragment (radians) */
    if (g->cap >= 3 && (sh->kind == IV_SHAPE_SPHERE || sh->kind == IV_SHAPE_CONE ||
                        (sh->kind == IV_SHAPE_PRISM && !sh->u.prism.g))) {
        r = sh->kind == IV_SHAPE_SPHERE ? sh->u.sphere.r
            : sh->kind == IV_SHAPE_CONE ? fmax(sh->u.cone.r1, sh->u.cone.r2)
                                        : sh->u.prism.r;
        half = PI / g->cap;
    } else if (sh->kind == IV_SHAPE_REVOLVE && sh->u.revolve.fragments > 0 && sh->u.revolve.g) {
        int n;
        const double(*P)[2] = iv_region_points(sh->u.revolve.g, &n);
        for (int i = 0; i < n; i++)
            r = fmax(r, fabs(P[i][0]));
        half = sh->u.revolve.angle * PI / 360 / sh->u.revolve.fragments;
    }
    double sag = r * stretch(g->xf) * (1 - cos(half));
    return sag > 0 ? sag : INFINITY;
}

/* What openscad's render (a mesh export) makes of g, in place; returns
 * the dimension it gives g: 3, 2, or 0 (nothing).  As 2021.01's
 * GeometryEvaluator: an operation takes the dimension of its first child
 * that has one; in a 3D operation each 2D child is an empty operand
 * ("Ignoring 2D child object for 3D operation"): passed over by a union,
 * emptying an intersection, and a difference whose first operand it is.
 * (A 2D operation's 3D children are left: the whole is 2D, and a 3D
 * parent takes it as empty.) */
static int render_dims(scad_geom *g)
{
    if (!g) return 0;
    if (g->is_leaf) return scad_geom_is_flat(g) ? 2 : 3;
    if (g->n == 0) return 0;
    int *d = malloc((size_t)g->n * sizeof *d), dim = 0;
    if (!d) return scad_geom_dims(g) & 2 ? 3 : 2; /* out of memory: as it is */
    for (int i = 0; i < g->n; i++) {
        d[i] = render_dims(g->kids[i]);
        if (!dim) dim = d[i];
    }
    if (dim == 3) {
        int n = 0, empty = 0;
        for (int i = 0; i < g->n; i++) {
            if (d[i] != 2) {
                g->kids[n++] = g->kids[i];
            } else if (g->op == CSG_OP_INTERSECTION || (g->op == CSG_OP_DIFFERENCE && i == 0)) {
                empty = 1;
            }
        }
        g->n = empty ? 0 : n;
    }
    free(d);
    return dim;
}

/* The one path of a raw2d leaf, placed: 0, or -1 (not one usable path,
 * out of memory: then flattened as any other). */
static int raw_region(const scad_geom *g, scad_paths *out)
{
    int n, np;
    const double(*P)[2] = iv_region_points(g->shape.u.prism.g, &n);
    const int *ps = iv_region_paths(g->shape.u.prism.g, &np);
    const double *t = g->xf;
    double det = t[0] * t[5] - t[1] * t[4];
    if (np != 1 || ps[0] != 0 || ps[1] != n || n < 3 || !(det != 0)) return -1;
    out->pts = malloc((size_t)n * sizeof *out->pts);
    out->start = malloc(2 * sizeof *out->start);
    if (!out->pts || !out->start) {
        free(out->pts);
        free(out->start);
        out->pts = NULL;
        out->start = NULL;
        return -1;
    }
    /* untransformed, as openscad: its -0s stay (x·1 + 0 would be +0) */
    int moved = memcmp(t, csg_affine_identity, sizeof(csg_affine)) != 0;
    for (int i = 0; i < n; i++) {
        int k = det < 0 ? n - 1 - i : i;
        out->pts[i][0] = moved ? t[0] * P[k][0] + t[1] * P[k][1] + t[3] : P[k][0];
        out->pts[i][1] = moved ? t[4] * P[k][0] + t[5] * P[k][1] + t[7] : P[k][1];
    }
    out->start[0] = 0;
    out->start[1] = n;
    out->npaths = 1;
    return 0;
}

/* The 2D model g (render_dims 2) as one polygon set in out->region, as
 * openscad's 2D export takes it: 3D leaves left out, circles at OpenSCAD's
 * facets (the evaluation built them so: for_2d forces them).  A failure is
 * an evaluation error (ev->aborted). */
static void flatten_root(scad_eval *ev, const scad_geom *g, scad_result *out)
{
    /* openscad passes a lone child through every 2D operation and group
     * untouched, so a lone square() or circle() reaches the export as the
     * primitive made it: unsnapped, from its first corner, reversed by a
     * mirroring transform (Polygon2d::transform) */
    const scad_geom *lone = g;
    while (lone && !lone->is_leaf && lone->n == 1)
        lone = lone->kids[0];
    if (lone && lone->is_leaf && lone->raw2d && scad_geom_is_flat(lone) && lone->shape.u.prism.g &&
        raw_region(lone, &out->region) == 0)
        return;
    /* The facets only reach smooth discs, which for_2d never builds. */
    scad_facet_params f = {0, 12, 2};
    if (scad_flatten_2d(ev, g, csg_affine_identity, f, ev->at, "export", &out->region) != 0)
        ev->aborted = 1;
}

static csg_node *list_to_csg(scad_geom **v, int n, int marked, const scad_geom **oom)
{
    if (n == 0) return NULL;
    if (n == 1) return to_csg(v[0], marked, oom);
    csg_node *u = csg_node_op(CSG_OP_UNION);
    if (!u) {
        *oom = v[0];
        return NULL;
    }
    for (int i = 0; i < n; i++) {
        csg_node *k = to_csg(v[i], marked, oom);
        if (k && csg_node_add(u, k) && !*oom) *oom = v[i];
    }
    return u;
}

/* ---- evaluation ------------------------------------------------------------------ */

typedef struct job {
    const scad_options *opt;
    scad_diag *d;
    scad_names *names;
    const char *name, *src; /* parsed by the job itself (parse_job) */
    scad_arena *a;
    scad_scope *top;
    scad_result *out;
    size_t stack_size;
    int status;
    scad_buf *dump; /* non-NULL: write the .csg text here, build no trees */
    int dump_text;  /* 0: the .csg tree is evaluated, its text not written (.echo) */
    int ast;        /* 1: the file is parsed, not evaluated, and its .ast written to dump */
} job;

static void set_value(scad_eval *ev, scad_env *e, const char *name, scad_value v)
{
    const char *n = scad_names_intern(ev->names, name, strlen(name));
    if (n)
        scad_env_set(e, n, v);
    else
        scad_eval_error(ev, ev->at, "out of memory");
}

static void set_num(scad_eval *ev, scad_env *e, const char *name, double x)
{
    set_value(ev, e, name, scad_num(x));
}

static void set_vec3(scad_eval *ev, scad_env *e, const char *name, double x, double y, double z)
{
    scad_value v = scad_vec_new(3);
    if (v.kind == SV_VEC) {
        v.u.vec->v[0] = scad_num(x);
        v.u.vec->v[1] = scad_num(y);
        v.u.vec->v[2] = scad_num(z);
    }
    set_value(ev, e, name, v);
}

/* Camera::updateView's reading of one $vp variable: $vpr and $vpt take 2
 * or 3 numbers (z = 0 when missing), $vpd and $vpf a number; NaN and
 * infinities make it unusable (it still turns viewall off). */
static void take_vp(scad_result *out, char which, scad_value v)
{
    if (which == 'd' || which == 'f') {
        if (v.kind != SV_NUM || !isfinite(v.u.num)) return;
        *(which == 'd' ? &out->vpd : &out->vpf) = v.u.num;
        out->vp_set |= which == 'd' ? SCAD_VP_D : SCAD_VP_F;
        return;
    }
    if (v.kind != SV_VEC || v.u.vec->n < 2 || v.u.vec->n > 3) return;
    double xyz[3] = {0, 0, 0};
    for (int k = 0; k < v.u.vec->n; k++) {
        if (v.u.vec->v[k].kind != SV_NUM || !isfinite(v.u.vec->v[k].u.num)) return;
        xyz[k] = v.u.vec->v[k].u.num;
    }
    memcpy(which == 'r' ? out->vpr : out->vpt, xyz, sizeof xyz);
    out->vp_set |= which == 'r' ? SCAD_VP_R : SCAD_VP_T;
}

/* OpenSCAD 2021.01's Camera::updateView, run when the file sets any $vp*:
 * $vpr, $vpt (its getVec3: 2 or 3 numbers) and $vpd (a number) as the file
 * sees them, each taken or warned about in that order ($vpf taken quietly);
 * 1 when one was taken, which turns --viewall/--autocenter off. */
static int file_camera(scad_eval *ev, scad_env *file, scad_result *out)
{
    int set = 0;
    for (int i = 0; i < file->nvars; i++) {
        const char *n = file->vars[i].name;
        if (!strncmp(n, "$vp", 3) && strchr("drtf", n[3]) && !n[4] &&
            file->vars[i].v.kind != SV_UNDEF)
            set = 1;
    }
    if (!set) return 0;
    int taken = 0; /* (values the file does not set are its defaults: checked, not taken) */
    static const char which[] = "rtdf";
    for (int k = 0; k < 4; k++) {
        char name[5] = {'$', 'v', 'p', which[k], 0};
        scad_value v = scad_env_lookup_cstr(ev, file, name, ev->at, 1, NULL);
        int own = 0;
        for (int i = 0; i < file->nvars; i++)
            if (!strcmp(file->vars[i].name, name)) own = 1;
        int ok;
        if (which[k] == 'd' || which[k] == 'f') {
            ok = v.kind == SV_NUM;
        } else {
            ok = v.kind == SV_VEC && (v.u.vec->n == 2 || v.u.vec->n == 3);
            for (int i = 0; ok && v.u.vec->n == 3 && i < 3; i++)
                ok = v.u.vec->v[i].kind == SV_NUM;
        }
        if (ok && own && out) take_vp(out, which[k], v);
        if (which[k] == 'f') break;
        if (ok) {
            taken = 1;
        } else {
            scad_buf b = {0};
            scad_value_format(&b, v, 1);
            char line[600];
            snprintf(line, sizeof line, "WARNING: Unable to convert %s=%.400s to %s", name,
                     scad_buf_str(&b), which[k] == 'd' ? "a number" : "a vec3 or vec2 of numbers");
            scad_buf_free(&b);
            scad_diag_line(ev->d, RAYSCAD_MSG_WARNING, line);
        }
    }
    return taken;
}

/* Set up an evaluator for job j, its stack measured from *base (in the
 * caller's frame): 0, or -1 after an out-of-memory error (nothing to
 * free). */
static int eval_init(scad_eval *ev, job *j, char *base)
{
    memset(ev, 0, sizeof *ev);
    ev->d = j->d;
    ev->names = j->names;
    ev->arena = scad_arena_new();
    ev->max_depth =
        j->opt && j->opt->max_recursion > 0 ? j->opt->max_recursion : DEFAULT_MAX_RECURSION;
    ev->max_steps = j->opt && j->opt->max_steps > 0 ? j->opt->max_steps : DEFAULT_MAX_STEPS;
    ev->progress = j->opt ? j->opt->progress : NULL;
    ev->progress_ud = j->opt ? j->opt->progress_ud : NULL;
    ev->max_list = j->opt && j->opt->max_list > 0 && j->opt->max_list < SCAD_MAX_LIST
                       ? j->opt->max_list
                       : SCAD_MAX_LIST;
    ev->max_string = j->opt && j->opt->max_string > 0 ? j->opt->max_string : SCAD_MAX_STRING;
    ev->stack_base = base;
    ev->stack_budget =
        j->stack_size > 2 * STACK_MARGIN ? j->stack_size - STACK_MARGIN : j->stack_size / 2;
    ev->rand_seed = (unsigned long)time(NULL) ^ (unsigned long)(size_t)base;
    ev->dump = j->dump != NULL;
    ev->at = (scad_loc){j->name, 1, 1};
    if (!ev->arena) {
        scad_diag_error(j->d, ev->at, "out of memory");
        return -1;
    }
    ev->sym_children = scad_names_intern(ev->names, "$children", 9);
    ev->sym_parent_modules = scad_names_intern(ev->names, "$parent_modules", 15);
    ev->sym_children_module = scad_names_intern(ev->names, "children", 8);
    ev->sym_intersection_for = scad_names_intern(ev->names, "intersection_for", 16);
    ev->builtin_params = scad_arena_alloc(ev->arena, sizeof *ev->builtin_params *
                                                         (size_t)scad_registry_module_count());
    if (!ev->sym_children || !ev->sym_parent_modules || !ev->sym_children_module ||
        !ev->sym_intersection_for || !ev->builtin_params) {
        scad_diag_error(j->d, ev->at, "out of memory");
        scad_arena_free(ev->arena);
        return -1;
    }
    ev->top = j->top;
    ev->facets = j->opt ? j->opt->facets : RAYSCAD_FACETS_AUTO;
    ev->for_mesh = j->opt && (j->opt->for_mesh || j->opt->for_2d);
    if (j->opt && j->opt->for_2d) ev->facets = RAYSCAD_FACETS_OPENSCAD;
    static const scad_services no_services;
    ev->services = j->opt && j->opt->services ? j->opt->services : &no_services;
    return 0;
}

static void run_job(job *j)
{
    char base;
    scad_eval ev;
    j->status = -1;
    if (eval_init(&ev, j, &base) != 0) return;
    j->d->hard_stop = scad_eval_hard_stop;
    j->d->hard_ud = &ev;
    scad_env *builtins = scad_env_new(&ev, NULL, NULL, NULL);
    if (builtins) { /* set before any environment below it is made (eval.h) */
        set_num(&ev, builtins, "PI", 3.14159265358979323846);
        set_num(&ev, builtins, "$fn", 0);
        set_num(&ev, builtins, "$fa", 12);
        set_num(&ev, builtins, "$fs", 2);
        set_num(&ev, builtins, "$t", 0);
        set_value(&ev, builtins, "$preview", scad_bool(!ev.for_mesh));
        const scad_options *vo = j->opt && j->opt->view_set ? j->opt : NULL;
        set_num(&ev, builtins, "$vpd", vo ? vo->vpd : 500);
        set_num(&ev, builtins, "$vpf", 22.5);
        set_vec3(&ev, builtins, "$vpr", vo ? vo->vpr[0] : 0, vo ? vo->vpr[1] : 0,
                 vo ? vo->vpr[2] : 0);
        set_vec3(&ev, builtins, "$vpt", vo ? vo->vpt[0] : 0, vo ? vo->vpt[1] : 0,
                 vo ? vo->vpt[2] : 0);
    }
    scad_env *file = builtins ? scad_env_new(&ev, builtins, builtins, j->top) : NULL;
    ev.builtins = builtins;
    if (file) {
        scad_geom *model = scad_eval_file_scope(&ev, file, j->top);
        if (ev.second_root.file && !ev.aborted)
            scad_diag_warning(j->d, ev.second_root, "More than one Root Modifier (!)");
        int vp = !ev.aborted && file_camera(&ev, file, j->out);
        if (j->out) j->out->vp_auto_off = vp;
        for (int i = 0; j->out && i < file->nvars; i++) {
            const char *n = file->vars[i].name;
            scad_value v = file->vars[i].v;
            scad_result *r = j->out;
            if (strncmp(n, "$rs_", 4) || strlen(n) >= sizeof r->settings[0].name ||
                r->nsettings == SCAD_MAX_SETTINGS || (v.kind != SV_NUM && v.kind != SV_BOOL))
                continue;
            strcpy(r->settings[r->nsettings].name, n);
            r->settings[r->nsettings].value = v.kind == SV_BOOL ? v.u.b : v.u.num;
            r->nsettings++;
        }
        if (vp && !ev.aborted)
            scad_diag_line(j->d, RAYSCAD_MSG_WARNING,
                           "WARNING: Viewall and autocenter disabled in favor of $vp*");
        /* for a mesh, the model as openscad's render makes it (in place) */
        int for_2d = !j->dump && j->opt && j->opt->for_2d;
        int dims =
            !ev.aborted && !j->dump && ev.for_mesh ? render_dims(ev.has_root ? ev.root : model) : 3;
        if (!ev.aborted && j->dump && !j->dump_text) {
            j->status = 0;
        } else if (!ev.aborted && j->dump) {
            const scad_geom *failed = scad_dump_write(j->dump, ev.has_root ? ev.root : model);
            if (j->dump->oom)
                scad_diag_error(j->d, failed ? failed->loc : ev.at, "out of memory");
            else
                j->status = 0;
        } else if (!ev.aborted && for_2d) {
            if (dims == 2) flatten_root(&ev, ev.has_root ? ev.root : model, j->out);
            if (!ev.aborted && j->out->region.npaths == 0) /* 3D or empty: openscad's words */
                scad_diag_line(j->d, RAYSCAD_MSG_ERROR,
                               "Current top level object is not a 2D object.");
            else if (!ev.aborted)
                j->status = 0;
        } else if (!ev.aborted && dims == 2) {
            /* openscad's words; it too writes no mesh of a 2D model */
            scad_diag_line(j->d, RAYSCAD_MSG_ERROR,
                           "ERROR: Current top level object is not a 3D object.");
        } else if (!ev.aborted) {
            const scad_geom *oom = NULL;
            if (ev.has_root) model = ev.root;
            double sag = facet_sag(model);
            j->out->facet_sag = sag < INFINITY ? sag : 0;
            j->out->model = to_csg(model, 0, &oom);
            j->out->highlight = list_to_csg(ev.highlights, ev.nhighlights, 1, &oom);
            j->out->background = list_to_csg(ev.backgrounds, ev.nbackgrounds, 0, &oom);
            if (oom) {
                scad_diag_error(j->d, oom->loc.file ? oom->loc : ev.at, "out of memory");
                scad_result_free(j->out);
            } else {
                j->status = 0;
            }
        }
    }
    j->d->hard_stop = NULL;
    scad_env_free(file);
    free(ev.module_names);
    free(ev.frames);
    scad_env_free(builtins);
    scad_eval_free_captured(&ev);
    scad_geometry_release(&ev); /* after to_csg: the nodes hold their own */
    free(ev.highlights);
    free(ev.backgrounds);
    scad_arena_free(ev.arena);
}

/* ---- -D overrides ------------------------------------------------------------------ */

/* Each define replaces the value of top's assignment of its name, or is
 * added after them.  file non-NULL: the assignments made take the
 * location openscad gives them, line first_line + i of file (it parses
 * the -D assignments as lines of the main file after its end). */
static int apply_defines(scad_arena *a, scad_diag *d, scad_names *names, scad_scope *top,
                         const char *const *defines, int count, const char *file, int first_line)
{
    for (int i = 0; i < count; i++) {
        const char *def = defines[i];
        size_t n = strlen(def);
        char *src = scad_arena_alloc(a, n + 2);
        if (!src) return -1;
        memcpy(src, def, n);
        src[n] = ';';
        scad_scope *s = scad_parse(a, d, names, "<-D>", src);
        if (!s) return -1;
        if (s->nassigns != 1 || s->nstmts || s->nmods || s->nfuncs) {
            scad_diag_error(d, (scad_loc){"<-D>", 1, 1}, "-D expects name=value, got '%s'", def);
            return -1;
        }
        scad_assign *as = &s->assigns[0];
        if (file) as->loc = (scad_loc){file, first_line + i, 1};
        int k;
        for (k = 0; k < top->nassigns; k++)
            if (top->assigns[k].name == as->name) break;
        if (k < top->nassigns) {
            top->assigns[k].value = as->value;
            if (file) top->assigns[k].loc = as->loc;
            continue;
        }
        scad_assign *nv = scad_arena_alloc(a, sizeof *nv * (size_t)(top->nassigns + 1));
        if (!nv) return -1;
        if (top->nassigns) memcpy(nv, top->assigns, sizeof *nv * (size_t)top->nassigns);
        nv[top->nassigns] = *as;
        top->assigns = nv;
        top->nassigns++;
        top->capassigns = top->nassigns;
    }
    return 0;
}

/* ---- customizer parameter sets ----------------------------------------------------- */

typedef struct param_ctx {
    job *j;
} param_ctx;

/* rayscad_parameter_query.default_type: assignment i's expression in an
 * empty context, as openscad 2021.01's ParameterSet::applyParameterSet
 * evaluates it (no variables, no builtin functions), warnings and all. */
static rayscad_value_type default_type(void *ud, int i)
{
    param_ctx *c = ud;
    job *j = c->j;
    char base;
    scad_eval ev;
    if (i < 0 || i >= j->top->nassigns || eval_init(&ev, j, &base) != 0) return RAYSCAD_VALUE_UNDEF;
    ev.no_builtins = 1;
    scad_env *empty = scad_env_new(&ev, NULL, NULL, NULL);
    scad_value v = empty ? scad_eval_expr(&ev, empty, j->top->assigns[i].value) : scad_undef();
    rayscad_value_type t = (rayscad_value_type)v.kind; /* scad_vkind's order */
    scad_value_drop(v);
    scad_env_free(empty);
    free(ev.module_names);
    free(ev.frames);
    scad_eval_free_captured(&ev);
    scad_geometry_release(&ev);
    scad_arena_free(ev.arena);
    return t;
}

/* Ask the caller for the parameter set's overrides and apply them as -D
 * ones: 0, or -1 (the load fails). */
static int apply_parameters(job *j)
{
    scad_scope *top = j->top;
    const char **names = scad_arena_alloc(j->a, sizeof *names * (size_t)(top->nassigns + 1));
    if (!names) {
        scad_diag_error(j->d, (scad_loc){j->name, 1, 1}, "out of memory");
        return -1;
    }
    for (int i = 0; i < top->nassigns; i++)
        names[i] = top->assigns[i].name;
    param_ctx c = {j};
    rayscad_parameter_query q = {top->nassigns, names, default_type, &c};
    const char *const *overrides = NULL;
    int n = 0;
    if (j->opt->parameters(j->opt->parameters_ud, &q, &overrides, &n) != 0) {
        j->d->errors++; /* the hook said why */
        return -1;
    }
    if (apply_defines(j->a, j->d, j->names, top, overrides, n, NULL, 0)) {
        if (j->d->errors == 0) scad_diag_error(j->d, (scad_loc){j->name, 1, 1}, "out of memory");
        return -1;
    }
    return 0;
}

/* Parse the job's source and apply the -D overrides, on the job's own
 * stack: a file nested MAX_DEPTH levels deep recurses that far in the
 * parser, which a sanitizer build's larger frames do not fit in 8 MB.
 * Returns 0, or -1 after reporting the error. */
static int parse_job(job *j)
{
    j->top = scad_parse(j->a, j->d, j->names, j->name, j->src);
    if (!j->top) {
        if (j->d->errors == 0) scad_diag_error(j->d, (scad_loc){j->name, 1, 1}, "out of memory");
        scad_diag_parse_failed(j->d, j->name);
        return -1;
    }
    if (j->opt && apply_defines(j->a, j->d, j->names, j->top, j->opt->defines, j->opt->define_count,
                                j->ast ? j->name : NULL, j->top->end_line + 2)) {
        if (j->d->errors == 0) scad_diag_error(j->d, (scad_loc){j->name, 1, 1}, "out of memory");
        return -1;
    }
    return j->opt && j->opt->parameters ? apply_parameters(j) : 0;
}

/* The job's parse as openscad's .ast: the customizer annotations read
 * from the text openscad parses (the file, "\n\x03\n", each -D and
 * ";\n"), then the scopes printed into j->dump. */
static void ast_job(job *j)
{
    scad_buf text = {0};
    scad_buf_puts(&text, j->src);
    scad_buf_puts(&text, "\n\x03\n");
    for (int i = 0; j->opt && i < j->opt->define_count; i++) {
        scad_buf_puts(&text, j->opt->defines[i]);
        scad_buf_puts(&text, ";\n");
    }
    const scad_annotation *notes =
        text.oom ? NULL : scad_annotations_collect(j->a, j->top, j->name, scad_buf_str(&text));
    scad_buf_free(&text);
    if (notes) scad_ast_print(j->dump, j->top, notes);
    if (!notes || j->dump->oom)
        scad_diag_error(j->d, (scad_loc){j->name, 1, 1}, "out of memory");
    else
        j->status = 0;
}

static void run_parsed(job *j)
{
    if (j->ast)
        ast_job(j);
    else
        run_job(j);
}

static void *job_thread(void *p)
{
    job *j = p;
    if (parse_job(j) == 0) run_parsed(j);
    return NULL;
}

/* ---- public ----------------------------------------------------------------------- */

static int eval_source(const char *name, const char *src, scad_arena *a, const scad_options *opt,
                       scad_result *out, scad_buf *dump, int dump_text, int ast)
{
    scad_diag d;
    memset(&d, 0, sizeof d);
    d.opt = opt;
    const char *slash = strrchr(name, '/');
    d.base_dir = slash ? scad_arena_strndup(a, name, (size_t)(slash - name + 1)) : "";
    d.arena = a;
    char cwd[4096];
    if (getcwd(cwd, sizeof cwd)) d.cwd = scad_arena_strndup(a, cwd, strlen(cwd));
    scad_names *names = scad_names_new(a);
    if (!names) {
        scad_diag_error(&d, (scad_loc){name, 1, 1}, "out of memory");
        return -1;
    }
    job j = {opt, &d, names, name, src, a, NULL, out, EVAL_STACK, -1, dump, dump_text, ast};
    pthread_attr_t attr;
    pthread_t th;
    int started = 0;
    if (pthread_attr_init(&attr) == 0) {
        if (pthread_attr_setstacksize(&attr, EVAL_STACK) == 0 &&
            pthread_create(&th, &attr, job_thread, &j) == 0)
            started = 1;
        pthread_attr_destroy(&attr);
    }
    if (started) {
        pthread_join(th, NULL);
    } else {
        /* No thread: use the caller's stack, with a budget from its limit. */
        struct rlimit rl;
        size_t lim = (size_t)8 << 20;
        if (getrlimit(RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < lim)
            lim = (size_t)rl.rlim_cur;
        j.stack_size = lim / 2;
        if (parse_job(&j) == 0) run_parsed(&j);
    }
    out->warnings = d.warnings;
    if (j.status != 0) scad_result_free(out);
    return j.status;
}

int scad_eval_string(const char *name, const char *src, const scad_options *opt, scad_result *out)
{
    memset(out, 0, sizeof *out);
    scad_arena *a = scad_arena_new();
    if (!a) return -1;
    int r = eval_source(name ? name : "<string>", src ? src : "", a, opt, out, NULL, 0, 0);
    scad_arena_free(a);
    return r;
}

static int eval_path(const char *path, const scad_options *opt, scad_result *out, scad_buf *dump,
                     int dump_text, int ast)
{
    memset(out, 0, sizeof *out);
    scad_arena *a = scad_arena_new();
    if (!a) return -1;
    char err[512];
    char *src = scad_read_file(a, opt, path, err, sizeof err);
    if (!src) {
        scad_diag d;
        memset(&d, 0, sizeof d);
        d.opt = opt;
        scad_diag_error(&d, (scad_loc){path, 1, 1}, "cannot read file: %s", err);
        scad_arena_free(a);
        return -1;
    }
    int r = eval_source(path, src, a, opt, out, dump, dump_text, ast);
    scad_arena_free(a);
    return r;
}

int scad_eval_file(const char *path, const scad_options *opt, scad_result *out)
{
    return eval_path(path, opt, out, NULL, 0, 0);
}

static int dump_finish(int r, scad_buf *b, char **text, size_t *len)
{
    if (!text) return r; /* evaluated only */
    if (r != 0 || b->oom) {
        scad_buf_free(b);
        return -1;
    }
    if (!b->p) scad_buf_put(b, "", 0);
    *text = b->p;
    if (len) *len = b->n;
    if (!*text) {
        *text = calloc(1, 1);
        if (!*text) return -1;
    }
    return 0;
}

int scad_dump_csg_file(const char *path, const scad_options *opt, char **text, size_t *len)
{
    scad_buf b = {0};
    scad_result res;
    if (text) *text = NULL;
    if (len) *len = 0;
    return dump_finish(eval_path(path, opt, &res, &b, text != NULL, 0), &b, text, len);
}

int scad_dump_csg_string(const char *name, const char *src, const scad_options *opt, char **text,
                         size_t *len)
{
    scad_buf b = {0};
    scad_result res;
    if (text) *text = NULL;
    if (len) *len = 0;
    memset(&res, 0, sizeof res);
    scad_arena *a = scad_arena_new();
    if (!a) return -1;
    int r =
        eval_source(name ? name : "<string>", src ? src : "", a, opt, &res, &b, text != NULL, 0);
    scad_arena_free(a);
    return dump_finish(r, &b, text, len);
}

int scad_dump_ast_file(const char *path, const scad_options *opt, char **text, size_t *len)
{
    scad_buf b = {0};
    scad_result res;
    *text = NULL;
    if (len) *len = 0;
    return dump_finish(eval_path(path, opt, &res, &b, 1, 1), &b, text, len);
}

int scad_dump_ast_string(const char *name, const char *src, const scad_options *opt, char **text,
                         size_t *len)
{
    scad_buf b = {0};
    scad_result res;
    *text = NULL;
    if (len) *len = 0;
    memset(&res, 0, sizeof res);
    scad_arena *a = scad_arena_new();
    if (!a) return -1;
    int r = eval_source(name ? name : "<string>", src ? src : "", a, opt, &res, &b, 1, 1);
    scad_arena_free(a);
    return dump_finish(r, &b, text, len);
}

void scad_result_free(scad_result *r)
{
    if (!r) return;
    csg_node_free(r->model);
    csg_node_free(r->highlight);
    csg_node_free(r->background);
    r->model = r->highlight = r->background = NULL;
    free(r->region.pts);
    free(r->region.start);
    r->region.pts = NULL;
    r->region.start = NULL;
    r->region.npaths = 0;
}
