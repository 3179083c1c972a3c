/*
 * eval_stmt.c — statements: the geometry nodes a scope makes, assignments,
 * instantiations of user modules, builtin modules (through the registry)
 * and the control modules (if, for, intersection_for, let, echo, assert,
 * children), and the file's top-level scope.
 *
 * A scope evaluates all its assignments in order (each name once, at its
 * first position) before instantiating anything.
 */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval.h"
#include "registry.h"

/* ---- geometry ----------------------------------------------------------------- */

scad_geom *scad_geom_leaf(scad_eval *ev, const iv_shape *s, const scad_state *state)
{
    scad_geom *g = scad_arena_alloc(ev->arena, sizeof *g);
    if (!g) {
        scad_eval_error(ev, scad_eval_here(ev), "out of memory");
        return NULL;
    }
    g->is_leaf = 1;
    g->shape = *s;
    g->loc = scad_eval_here(ev);
    memcpy(g->xf, state->xf, sizeof g->xf);
    g->mat = state->mat;
    return g;
}

scad_geom *scad_geom_op(scad_eval *ev, csg_op op)
{
    scad_geom *g = scad_arena_alloc(ev->arena, offsetof(scad_geom, shape)); /* eval.h */
    if (!g) {
        scad_eval_error(ev, scad_eval_here(ev), "out of memory");
        return NULL;
    }
    g->op = op;
    g->loc = scad_eval_here(ev);
    return g;
}

void scad_geom_add(scad_eval *ev, scad_geom *parent, scad_geom *child)
{
    if (!parent || !child) return;
    if (ev->dump && !child->text) { /* a bare list: its children in its place */
        for (int i = 0; i < child->n; i++)
            scad_geom_add(ev, parent, child->kids[i]);
        return;
    }
    if (parent->n == parent->cap) {
        int cap = parent->cap ? parent->cap * 2 : 4;
        scad_geom **k = scad_arena_alloc(ev->arena, sizeof *k * (size_t)cap);
        if (!k) {
            scad_eval_error(ev, scad_eval_here(ev), "out of memory");
            return;
        }
        if (parent->n) memcpy(k, parent->kids, sizeof *k * (size_t)parent->n);
        parent->kids = k;
        parent->cap = cap;
    }
    parent->kids[parent->n++] = child;
}

int scad_geom_keep(scad_eval *ev, iv_shape *s)
{
    if (ev->nowned == ev->capowned) {
        int cap = ev->capowned ? 2 * ev->capowned : 16;
        iv_shape *v = realloc(ev->owned, (size_t)cap * sizeof *v);
        if (!v) {
            iv_shape_release(s);
            return -1;
        }
        ev->owned = v;
        ev->capowned = cap;
    }
    ev->owned[ev->nowned++] = *s;
    return 0;
}

void scad_geometry_release(scad_eval *ev)
{
    for (int i = 0; i < ev->nowned; i++)
        iv_shape_release(&ev->owned[i]);
    free(ev->owned);
    ev->owned = NULL;
    ev->nowned = ev->capowned = 0;
}

/* Collects the children of one node; combined by `finish`. */
typedef struct gather {
    scad_geom **v;
    int n, cap;
} gather;

static void gather_add(scad_eval *ev, gather *g, scad_geom *x)
{
    if (!x) return;
    if (ev->dump && !x->text) {
        for (int i = 0; i < x->n; i++)
            gather_add(ev, g, x->kids[i]);
        return;
    }
    if (g->n == g->cap) {
        int cap = g->cap ? g->cap * 2 : 8;
        scad_geom **v = realloc(g->v, sizeof *v * (size_t)cap);
        if (!v) {
            scad_eval_error(ev, scad_eval_here(ev), "out of memory");
            return;
        }
        g->v = v;
        g->cap = cap;
    }
    g->v[g->n++] = x;
}

/* The empty set as an operand: an op node without children.  OpenSCAD
 * 2021.01 makes a node of every module instantiation (a union(), a for
 * over nothing, a cube(0), a missing import), and such a node is an
 * operand even when it holds nothing: an intersection() with it is empty,
 * and so is a difference() whose first operand it is.  Only echo(),
 * assert(), an if() whose branch is absent and children() of no child
 * make no node (NULL here), as .csg shows. */
scad_geom *scad_geom_empty(scad_eval *ev)
{
    return scad_geom_op(ev, CSG_OP_UNION);
}

int scad_geom_is_empty(const scad_geom *g)
{
    return g && !g->is_leaf && g->n == 0;
}

/* g, or the empty set where g is no node: what a construct that always
 * makes a node returns. */
static scad_geom *node_of(scad_eval *ev, scad_geom *g)
{
    return g || ev->dump ? g : scad_geom_empty(ev);
}

/* The children combined by op: NULL when there are none (no node), a
 * single child standing for itself, and the empty set where an empty
 * operand decides (an intersection with one, a difference whose first
 * operand is one, a union of nothing else).  In dump mode the result is a
 * bare list of all of them (NULL when none). */
static scad_geom *finish(scad_eval *ev, gather *g, csg_op op)
{
    scad_geom *r = NULL;
    if (ev->dump) {
        if (g->n > 0) r = scad_geom_op(ev, op);
        for (int i = 0; r && i < g->n; i++)
            scad_geom_add(ev, r, g->v[i]);
    } else if (g->n > 0) {
        int n = 0, empty = 0;
        for (int i = 0; i < g->n; i++) {
            if (!scad_geom_is_empty(g->v[i]))
                g->v[n++] = g->v[i];
            else if (op == CSG_OP_INTERSECTION || (op == CSG_OP_DIFFERENCE && i == 0))
                empty = 1;
        }
        if (empty || n == 0)
            r = scad_geom_empty(ev);
        else if (n == 1)
            r = g->v[0];
        else
            r = scad_geom_op(ev, op);
        for (int i = 0; r && !empty && n > 1 && i < n; i++)
            scad_geom_add(ev, r, g->v[i]);
    }
    free(g->v);
    g->v = NULL;
    g->n = g->cap = 0;
    return r;
}

static void list_add(scad_eval *ev, scad_geom ***v, int *n, int *cap, scad_geom *g)
{
    if (*n == *cap) {
        int c = *cap ? *cap * 2 : 4;
        scad_geom **nv = realloc(*v, sizeof *nv * (size_t)c);
        if (!nv) {
            scad_eval_error(ev, scad_eval_here(ev), "out of memory");
            return;
        }
        *v = nv;
        *cap = c;
    }
    (*v)[(*n)++] = g;
}

/* ---- statements ----------------------------------------------------------------- */

static scad_geom *instantiate(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_state *state);

void scad_run_assignments(scad_eval *ev, scad_env *env, const scad_scope *s)
{
    for (int i = 0; i < s->nassigns && !ev->aborted; i++) {
        if (ev->nframes == 0) ev->at = s->assigns[i].loc;
        scad_env_set(env, s->assigns[i].name, scad_eval_expr(ev, env, s->assigns[i].value));
    }
}

/* Instantiates the statements of s (all of them, or those picked) in env. */
static void run_stmts(scad_eval *ev, scad_env *env, const scad_scope *s, const scad_state *state,
                      gather *out, const int *pick, int npick)
{
    int n = pick ? npick : s->nstmts;
    for (int i = 0; i < n && !ev->aborted; i++) {
        const scad_stmt *st = s->stmts[pick ? pick[i] : i];
        if (ev->nframes == 0) ev->at = st->loc;
        gather_add(ev, out, instantiate(ev, env, st, state));
        if (s == ev->progress_scope && ev->progress) {
            ev->progress_done = (double)(i + 1) / n;
            ev->progress(ev->progress_ud, ev->progress_done);
        }
    }
}

/* A child scope: a fresh environment below env for its assignments. */
/* The statements of scope s run in a fresh environment below env (dynamic
 * parent dyn), each one's node gathered into *g, in order. */
static void gather_scope(scad_eval *ev, scad_env *env, scad_env *dyn, const scad_scope *s,
                         const scad_state *state, const int *pick, int npick, gather *g)
{
    if (!s || ev->aborted) return;
    scad_env *ce = scad_env_new(ev, env, dyn, s);
    if (!ce) return;
    scad_run_assignments(ev, ce, s);
    run_stmts(ev, ce, s, state, g, pick, npick);
    scad_env_free(ce);
}

static scad_geom *child_scope(scad_eval *ev, scad_env *env, scad_env *dyn, const scad_scope *s,
                              const scad_state *state, csg_op op, const int *pick, int npick)
{
    gather g = {0};
    gather_scope(ev, env, dyn, s, state, pick, npick, &g);
    return finish(ev, &g, op);
}

scad_geom **scad_eval_children_list(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                    const scad_state *state, int *n)
{
    gather g = {0};
    gather_scope(ev, env, env, st->children, state, NULL, 0, &g);
    *n = g.n;
    return g.v;
}

scad_geom *scad_eval_children(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_state *state, csg_op op)
{
    return child_scope(ev, env, env, st->children, state, op, NULL, 0);
}

static scad_geom *call_module(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_moddef *m, scad_env *def_env, const scad_state *state)
{
    scad_argv argv;
    scad_env *me = scad_env_new(ev, def_env, env, m->body);
    if (!me) return NULL;
    scad_bind_defaults(ev, me, def_env, &m->params);
    if (scad_args_bind(ev, env, &st->args, &argv, 1, &m->params, m->params.n, 1, st->loc)) {
        scad_env_free(me);
        return NULL;
    }
    if (scad_call_enter(ev, st->loc, m->loc, "module", m->name)) {
        scad_argv_free(&argv);
        scad_env_free(me);
        return NULL;
    }
    scad_geom *r = NULL;
    me->is_module = 1;
    me->children = st->children;
    me->children_env = env;
    scad_bind_given(me, &argv);
    scad_env_set(me, ev->sym_children, scad_num(st->children ? st->children->nstmts : 0));
    if (ev->module_depth == ev->module_names_cap) {
        int cap = ev->module_names_cap ? ev->module_names_cap * 2 : 64;
        const char **nn = realloc(ev->module_names, sizeof *nn * (size_t)cap);
        if (nn) {
            ev->module_names = nn;
            ev->module_names_cap = cap;
        }
    }
    if (ev->module_depth < ev->module_names_cap) ev->module_names[ev->module_depth] = m->name;
    ev->module_depth++;
    scad_env_set(me, ev->sym_parent_modules, scad_num(ev->module_depth));
    for (int i = 0; i < m->body->nassigns; i++) {
        const scad_assign *as = &m->body->assigns[i];
        if (!scad_expr_is_literal(as->value)) continue;
        for (int k = 0; k < m->params.n; k++)
            if (m->params.v[k].name == as->name)
                scad_diag_warning(ev->d, as->loc,
                                  "Module %s: Parameter %s is overwritten with a literal", m->name,
                                  as->name);
    }
    gather g = {0};
    scad_run_assignments(ev, me, m->body);
    run_stmts(ev, me, m->body, state, &g, NULL, 0);
    r = node_of(ev, finish(ev, &g, CSG_OP_UNION));
    if (ev->dump) r = scad_dump_node(ev, "group()", r);
    scad_env_free(me);
    ev->module_depth--;
    scad_call_leave(ev);
    scad_argv_free(&argv);
    return r;
}

/* A number as C's (int) conversion gives it on x86-64, where OpenSCAD
 * 2021.01 was built: NaN and out-of-range values become INT_MIN (here
 * without the undefined behaviour of converting them). */
static int x86_int(double k)
{
    return isnan(k) || k >= 2147483648.0 || k < -2147483648.0 ? INT_MIN : (int)k;
}

/* The environment of the user module whose body env is in (lexically), or
 * NULL at file level: whose children children() and child() take. */
static scad_env *module_env(scad_env *env)
{
    while (env && !env->is_module)
        env = env->parent;
    return env;
}

/* children(k)'s index check, with OpenSCAD's two warnings (no location). */
static int children_index_bad(scad_eval *ev, int k, int n)
{
    char line[128];
    if (k < 0)
        snprintf(line, sizeof line, "WARNING: Negative children index (%d) not allowed", k);
    else if (k >= n)
        snprintf(line, sizeof line, "WARNING: Children index (%d) out of bounds (%d children)", k,
                 n);
    else
        return 0;
    scad_diag_line(ev->d, RAYSCAD_MSG_WARNING, line);
    return 1;
}

static scad_geom *do_children(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                              const scad_state *state)
{
    scad_env *m = module_env(env);
    if (!m) return NULL;
    int n = m->children ? m->children->nstmts : 0;
    /* instantiating the caller's children is a call of their scope, and
     * counts as one more step, as a user module's body does */
    if (scad_eval_step(ev, st->loc)) return NULL;
    if (a->n == 0) {
        scad_geom *r =
            n ? child_scope(ev, m->children_env, env, m->children, state, CSG_OP_UNION, NULL, 0)
              : NULL;
        return ev->dump ? scad_dump_node(ev, "group()", r) : node_of(ev, r);
    }
    scad_value sel = scad_argv_get(a, "index", 0);
    scad_vlist idx = {0};
    if (sel.kind == SV_NUM) {
        scad_vlist_push(ev, &idx, scad_value_ref(sel), st->loc);
    } else if (sel.kind == SV_RANGE && scad_range_steps(sel.u.range) > 10000) {
        scad_diag_warning(ev->d, st->loc,
                          "Bad range parameter for children: too many elements (%.0f)",
                          scad_range_steps(sel.u.range));
        return NULL;
    } else if (sel.kind == SV_VEC || sel.kind == SV_RANGE) {
        if (scad_iter_values(ev, sel, st->loc, &idx) < 0) {
            scad_vlist_free(&idx);
            return NULL;
        }
    } else {
        scad_buf b = {0};
        scad_value_format(&b, sel, 1);
        scad_diag_warning(
            ev->d, st->loc,
            "Bad parameter type (%s) for children, only accept: empty, number, vector, range",
            scad_buf_str(&b));
        scad_buf_free(&b);
        return NULL;
    }
    if (ev->dump && sel.kind != SV_NUM) {
        /* OpenSCAD evaluates each index on its own, into one group */
        gather g = {0};
        for (int i = 0; i < idx.n && !ev->aborted; i++) {
            if (idx.v[i].kind != SV_NUM) continue;
            int one = x86_int(idx.v[i].u.num);
            if (children_index_bad(ev, one, n)) continue;
            gather_add(
                ev, &g,
                child_scope(ev, m->children_env, env, m->children, state, CSG_OP_UNION, &one, 1));
        }
        scad_vlist_free(&idx);
        return scad_dump_node(ev, "group()", finish(ev, &g, CSG_OP_UNION));
    }
    int *pick = malloc(sizeof *pick * (size_t)(idx.n ? idx.n : 1));
    int np = 0;
    for (int i = 0; pick && i < idx.n; i++) {
        if (idx.v[i].kind != SV_NUM) continue;
        int k = x86_int(idx.v[i].u.num);
        if (children_index_bad(ev, k, n)) continue;
        pick[np++] = k;
    }
    scad_geom *r =
        np ? child_scope(ev, m->children_env, env, m->children, state, CSG_OP_UNION, pick, np)
           : NULL;
    free(pick);
    scad_vlist_free(&idx);
    return r;
}

/* for / intersection_for: nested loops over the arguments, each evaluated in
 * the environment of the loops outside it (for (i = [0:2], j = [i:2])), once
 * per outer iteration, as OpenSCAD does. */
static void for_loop(scad_eval *ev, const scad_stmt *st, int k, scad_env *cur,
                     const scad_state *state, gather *out)
{
    if (ev->aborted) return;
    if (k == st->args.n) {
        /* for () with no arguments instantiates nothing, as 2021.01's */
        if (k > 0)
            gather_add(ev, out,
                       child_scope(ev, cur, cur, st->children, state, CSG_OP_UNION, NULL, 0));
        return;
    }
    const scad_arg *arg = &st->args.v[k];
    scad_value src = scad_eval_expr(ev, cur, arg->value);
    scad_vlist items = {0};
    if (scad_iter_values(ev, src, arg->loc, &items) > 0) {
        for (int i = 0; i < items.n && !ev->aborted; i++) {
            scad_env *ie = scad_env_new(ev, cur, cur, NULL);
            if (!ie) break;
            if (arg->name) scad_env_set(ie, arg->name, scad_value_ref(items.v[i]));
            for_loop(ev, st, k + 1, ie, state, out);
            scad_env_free(ie);
        }
    }
    scad_vlist_free(&items);
    scad_value_drop(src);
}

/* The interned parameters of builtin module d (registry index id), made on
 * its first call in this evaluation; NULL when out of memory. */
static const scad_args *builtin_params(scad_eval *ev, const scad_module_def *d, int id)
{
    scad_args *p = &ev->builtin_params[id];
    if (p->v || !d->params) return p;
    int n = 0;
    while (d->params[n])
        n++;
    if (n > SCAD_MAX_PARAMS) return NULL;
    scad_arg *v = scad_arena_alloc(ev->arena, sizeof *v * (size_t)n);
    if (!v) return NULL;
    for (int i = 0; i < n; i++) {
        v[i].name = scad_names_intern(ev->names, d->params[i], strlen(d->params[i]));
        if (!v[i].name) return NULL;
    }
    p->v = v;
    p->n = n;
    return p;
}

/* A .csg node for the call: the entry's header and, when it lists them,
 * its children (evaluated in the node's own frame). */
static scad_geom *print_builtin(scad_call *c, const void *args)
{
    scad_eval *ev = c->ev;
    scad_buf b = {0};
    int kids = 1;
    if (c->def->print)
        kids = c->def->print(c, args, &b);
    else
        scad_buf_printf(&b, "%s()", c->def->name);
    scad_geom *list = NULL;
    if (kids) {
        scad_state fresh;
        memcpy(fresh.xf, csg_affine_identity, sizeof fresh.xf);
        memset(&fresh.mat, 0, sizeof fresh.mat);
        list = scad_eval_children(ev, c->env, c->st, &fresh, CSG_OP_UNION);
    }
    scad_geom *g = b.oom ? NULL : scad_dump_node(ev, scad_buf_str(&b), list);
    if (b.oom) scad_eval_error(ev, c->st->loc, "out of memory");
    scad_buf_free(&b);
    return g;
}

/* A builtin module: its arguments bound to the entry's parameters by
 * OpenSCAD's rule, read once by the entry, then printed (dump mode) or
 * built.  Modules that take no arguments (union, group …) evaluate none,
 * as OpenSCAD's CSG modules ignore theirs. */
/* The primitives OpenSCAD 2021.01 warns about when given children (which
 * they ignore; text, import and surface ignore theirs silently). */
static int is_leaf_primitive(const char *name)
{
    static const char *const leaves[] = {"cube",   "sphere", "cylinder", "polyhedron",
                                         "square", "circle", "polygon"};
    for (size_t i = 0; i < sizeof leaves / sizeof leaves[0]; i++)
        if (strcmp(name, leaves[i]) == 0) return 1;
    return 0;
}

static scad_geom *call_builtin(scad_eval *ev, scad_env *env, const scad_stmt *st,
                               const scad_state *state, const scad_module_def *d, int id)
{
    scad_call c = {ev, env, st, state, d, NULL, {{0}}};
    scad_argv a = {0};
    scad_env *dollar = NULL;
    if (st->children && st->children->nstmts > 0 && is_leaf_primitive(d->name))
        scad_diag_warning(ev->d, st->loc, "module %s() does not support child modules", d->name);
    if (d->npositional >= 0) {
        const scad_args *params = builtin_params(ev, d, id);
        if (!params) {
            scad_eval_error(ev, st->loc, "out of memory");
            return NULL;
        }
        if (scad_args_bind(ev, env, &st->args, &a, 1, params, d->npositional, 0, st->loc))
            return NULL;
        for (int k = 0; k < a.n; k++)
            for (int i = 0; i < params->n; i++)
                if (params->v[i].name == a.names[k]) c.arg[i] = a.v[k];
        /* $-arguments of a builtin are seen by its children (dynamic scope) */
        for (int i = 0; i < a.n; i++) {
            if (!a.names[i] || a.names[i][0] != '$') continue;
            if (!dollar && !(dollar = scad_env_new(ev, env, env, NULL))) break;
            scad_env_set(dollar, a.names[i], scad_value_ref(a.v[i]));
        }
        if (dollar) c.env = dollar;
    }
    c.argv = &a;
    _Alignas(16) unsigned char args[SCAD_MAX_ARGS];
    memset(args, 0, d->size);
    scad_geom *r = NULL;
    if (d->read && !ev->aborted) d->read(&c, args);
    if (!ev->aborted) r = ev->dump ? print_builtin(&c, args) : node_of(ev, d->build(&c, args));
    scad_argv_free(&a);
    scad_env_free(dollar);
    return r;
}

/* child(n), deprecated: children(n) for one whole index (default 0), its
 * deprecation said once per evaluation without a place, as openscad 2021.01. */
static scad_geom *deprecated_child(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                   const scad_state *state)
{
    scad_deprecated_once(ev, "child() will be removed in future releases. Use children() instead.");
    scad_argv a;
    if (scad_args_eval(ev, env, &st->args, &a)) return NULL;
    int k = 0;
    if (a.n > 0 && a.v[0].kind == SV_NUM) {
        double t = trunc(a.v[0].u.num);
        k = x86_int(t);
    }
    scad_argv_free(&a);
    if (k < 0) {
        char line[96];
        snprintf(line, sizeof line, "WARNING: Negative child index (%d) not allowed", k);
        scad_diag_line(ev->d, RAYSCAD_MSG_WARNING, line);
        return NULL;
    }
    scad_env *m = module_env(env);
    if (!m || !m->children || k >= m->children->nstmts) return NULL;
    return child_scope(ev, m->children_env, env, m->children, state, CSG_OP_UNION, &k, 1);
}

/* assign(a = …, b = …) children, deprecated: the named arguments, each
 * evaluated in the caller's scope (in parallel, not in sequence), seen by
 * the children, which form a group. */
static scad_geom *deprecated_assign(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                    const scad_state *state)
{
    scad_diag_deprecated(ev->d, st->loc,
                         "The assign() module will be removed in future releases. Use a regular "
                         "assignment instead.");
    scad_argv a;
    if (scad_args_eval(ev, env, &st->args, &a)) return NULL;
    scad_env *ae = scad_env_new(ev, env, env, NULL);
    scad_geom *r = NULL;
    if (ae) {
        for (int i = 0; i < a.n; i++)
            if (a.names[i]) scad_env_set(ae, a.names[i], scad_value_ref(a.v[i]));
        r = child_scope(ev, ae, ae, st->children, state, CSG_OP_UNION, NULL, 0);
        scad_env_free(ae);
    }
    scad_argv_free(&a);
    return ev->dump ? scad_dump_node(ev, "group()", r) : node_of(ev, r);
}

static scad_geom *instantiate_plain(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                    const scad_state *state)
{
    const char *name = st->name;
    int keyword = scad_name_keyword(name);
    if (keyword == TK_IF) {
        scad_value c = scad_eval_expr(ev, env, st->cond);
        int t = scad_value_truthy(c);
        scad_value_drop(c);
        scad_geom *r = child_scope(ev, env, env, t ? st->children : st->else_children, state,
                                   CSG_OP_UNION, NULL, 0);
        if (t || st->else_children)
            r = ev->dump ? scad_dump_node(ev, "group()", r) : node_of(ev, r);
        return r;
    }
    scad_env *def_env;
    int fresh;
    const scad_moddef *m = scad_find_module(ev, env, name, &def_env, &fresh);
    if (m) {
        scad_geom *r = call_module(ev, env, st, m, def_env, state);
        if (fresh) scad_env_free(def_env);
        return r;
    }

    if (keyword == TK_LET) {
        scad_env *le = scad_env_new(ev, env, env, NULL);
        if (!le) return NULL;
        scad_assign_seq(ev, le, &st->args);
        scad_geom *r = child_scope(ev, le, le, st->children, state, CSG_OP_UNION, NULL, 0);
        scad_env_free(le);
        return ev->dump ? scad_dump_node(ev, "group()", r) : node_of(ev, r);
    }
    if (keyword == TK_ASSERT) {
        if (scad_check_assert(ev, env, &st->args, st->loc)) return NULL;
        scad_geom *r = scad_eval_children(ev, env, st, state, CSG_OP_UNION);
        return ev->dump && r ? scad_dump_node(ev, "group()", r) : r;
    }
    int is_for = keyword == TK_FOR, is_ifor = name == ev->sym_intersection_for;
    int is_children = name == ev->sym_children_module;
    if (!is_for && !is_ifor && !is_children && keyword != TK_ECHO) {
        int id;
        const scad_module_def *d = scad_registry_module(name, &id);
        if (d) return call_builtin(ev, env, st, state, d, id);
        if (!strcmp(name, "child")) return deprecated_child(ev, env, st, state);
        if (!strcmp(name, "assign")) return deprecated_assign(ev, env, st, state);
        scad_diag_warning(ev->d, st->loc, "Ignoring unknown module '%s'", name);
        return NULL;
    }
    if (is_for || is_ifor) {
        gather g = {0};
        for_loop(ev, st, 0, env, state, &g);
        scad_geom *r = finish(ev, &g, is_for ? CSG_OP_UNION : CSG_OP_INTERSECTION);
        return ev->dump ? scad_dump_node(ev, is_for ? "group()" : "intersection()", r)
                        : node_of(ev, r);
    }
    scad_argv a;
    if (scad_args_eval(ev, env, &st->args, &a)) return NULL;
    scad_geom *r = NULL;
    /* $-arguments of a control module are seen by its children */
    scad_env *dollar = NULL;
    for (int i = 0; i < a.n; i++) {
        if (!a.names[i] || a.names[i][0] != '$') continue;
        if (!dollar && !(dollar = scad_env_new(ev, env, env, NULL))) break;
        scad_env_set(dollar, a.names[i], scad_value_ref(a.v[i]));
    }
    if (dollar) env = dollar;
    if (ev->aborted) {
        /* nothing */
    } else if (keyword == TK_ECHO) {
        scad_echo_line(ev, &a);
        r = scad_eval_children(ev, env, st, state, CSG_OP_UNION);
        if (ev->dump && r) r = scad_dump_node(ev, "group()", r);
    } else {
        r = do_children(ev, env, st, &a, state);
    }
    scad_argv_free(&a);
    scad_env_free(dollar);
    return r;
}

static scad_geom *instantiate_framed(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                     const scad_state *state);

static scad_geom *instantiate(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_state *state)
{
    if (st->disable || ev->aborted || scad_eval_step(ev, st->loc)) return NULL;
    int pushed = scad_frame_push(ev, st->name, st->loc);
    scad_geom *g = instantiate_framed(ev, env, st, state);
    scad_frame_pop(ev, pushed);
    return g;
}

/* 1 when st is children(i) with a number i under a modifier: 2021.01 then
 * returns the child's own node, and the statement's %, # or ! is lost with
 * the node that would have carried it (children() and children([…]) make
 * a node of their own, which keeps it).  The argument is evaluated here
 * once more; children()'s arguments are plain expressions. */
static int bare_child(scad_eval *ev, scad_env *env, const scad_stmt *st)
{
    if (!(st->highlight || st->background || st->root) || st->name != ev->sym_children_module)
        return 0;
    scad_argv a;
    if (scad_args_eval(ev, env, &st->args, &a)) return 0;
    int bare = a.n > 0 && scad_argv_get(&a, "index", 0).kind == SV_NUM;
    scad_argv_free(&a);
    return bare;
}

static scad_geom *instantiate_framed(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                     const scad_state *state)
{
    if (bare_child(ev, env, st)) return instantiate_plain(ev, env, st, state);
    if (ev->dump && (st->highlight || st->background) && !st->root) {
        scad_geom *g = instantiate_plain(ev, env, st, state);
        if (g && g->text) {
            size_t n = strlen(g->text);
            char *t = scad_arena_alloc(ev->arena, n + 3);
            if (!t) return g;
            size_t k = 0;
            if (st->background) t[k++] = '%';
            if (st->highlight) t[k++] = '#';
            memcpy(t + k, g->text, n + 1);
            g->text = t;
        }
        return g;
    }
    if (st->root) {
        scad_state fresh;
        memcpy(fresh.xf, csg_affine_identity, sizeof fresh.xf);
        memset(&fresh.mat, 0, sizeof fresh.mat);
        /* the first '!' met (an outer one before those inside it) is the
         * root; one of another statement is noted for the warning openscad
         * gives once the tree is built (a '!' in a loop is one statement) */
        int first = !ev->root_stmt, nested = ev->in_root;
        if (first)
            ev->root_stmt = st;
        else if (st != ev->root_stmt && !nested && !ev->second_root.file)
            ev->second_root = st->loc;
        ev->in_root++;
        scad_geom *g = instantiate_plain(ev, env, st, nested ? state : &fresh);
        ev->in_root--;
        if (first) {
            ev->root = g;
            ev->has_root = 1;
        }
        return nested ? g : NULL; /* a '!' inside another is a plain part of it */
    }
    scad_state marked;
    if (st->highlight) { /* its leaves drawn in the highlight colour, in the model too */
        marked = *state;
        marked.mat.highlight = 1;
        state = &marked;
    }
    scad_geom *g = instantiate_plain(ev, env, st, state);
    if (g && st->background) {
        list_add(ev, &ev->backgrounds, &ev->nbackgrounds, &ev->capbackgrounds, g);
        return NULL;
    }
    if (g && st->highlight) list_add(ev, &ev->highlights, &ev->nhighlights, &ev->caphighlights, g);
    return g;
}

/* The file: its scope in env, top-level objects as an implicit union. */
scad_geom *scad_eval_file_scope(scad_eval *ev, scad_env *env, const scad_scope *s)
{
    scad_state st;
    memcpy(st.xf, csg_affine_identity, sizeof st.xf);
    memset(&st.mat, 0, sizeof st.mat);
    gather g = {0};
    ev->progress_scope = s;
    ev->progress_done = 0;
    if (ev->progress) ev->progress(ev->progress_ud, 0);
    scad_run_assignments(ev, env, s);
    run_stmts(ev, env, s, &st, &g, NULL, 0);
    return finish(ev, &g, CSG_OP_UNION);
}
