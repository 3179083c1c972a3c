/*
 * env.c — environments and argument binding.
 *
 * Environments form two chains: `parent` is lexical (plain variables,
 * functions and modules are looked up there, as OpenSCAD does) and `dyn` is
 * the caller (for $-variables, which OpenSCAD scopes dynamically).  An
 * environment is freed when its scope ends unless a function literal closed
 * over it; those are kept on ev->captured until the evaluation ends.
 * Variables are found by their interned names (names.c): a scan of a few
 * pointers, or a hash table once an environment holds more than a handful.
 * A call's arguments are bound to parameters by OpenSCAD 2021.01's rule
 * (scad_args_bind), for user modules, user functions and builtin modules
 * alike.
 */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval.h"

/* ---- environments ------------------------------------------------------------ */

scad_env *scad_env_new(scad_eval *ev, scad_env *parent, scad_env *dyn, const scad_scope *defs)
{
    scad_env *e = calloc(1, sizeof *e);
    if (!e) {
        scad_eval_error(ev, scad_eval_here(ev), "out of memory");
        return NULL;
    }
    e->parent = parent;
    e->dyn = dyn;
    e->defs = defs;
    e->vars = e->inline_vars;
    e->cap = 4;
    if (dyn) memcpy(e->special, dyn->special, sizeof e->special);
    return e;
}

static void env_release(scad_env *e)
{
    for (int i = 0; i < e->nvars; i++)
        scad_value_drop(e->vars[i].v);
    if (e->vars != e->inline_vars) free(e->vars);
    free(e->index);
    free(e);
}

void scad_env_free(scad_env *e)
{
    if (e && !e->captured) env_release(e);
}

/* A closure keeps its environment and every lexical ancestor alive. */
void scad_env_capture(scad_eval *ev, scad_env *e)
{
    for (; e && !e->captured; e = e->parent) {
        e->captured = 1;
        e->next_captured = ev->captured;
        ev->captured = e;
    }
}

void scad_eval_free_captured(scad_eval *ev)
{
    /* Values first: they may hold closures, which only point at envs. */
    scad_env *e = ev->captured;
    while (e) {
        scad_env *n = e->next_captured;
        env_release(e);
        e = n;
    }
    ev->captured = NULL;
}

/* The well-known special variables of scad_env.special, by index. */
static const char *const special_names[SCAD_ENV_NSPECIAL] = {
    "$fn", "$fa", "$fs", "$t", "$preview", "$rs_reflect", "$rs_absorb", "$rs_ior", "$rs_light"};

/* The index of name (which starts with '$') in special_names, or -1. */
static int special_index(const char *name)
{
    switch (name[1]) {
    case 'f':
        if (name[2] && !name[3])
            return name[2] == 'n' ? 0 : name[2] == 'a' ? 1 : name[2] == 's' ? 2 : -1;
        return -1;
    case 't':
        return name[2] ? -1 : 3;
    case 'p':
        return strcmp(name, "$preview") ? -1 : 4;
    case 'r': {
        if (name[2] != 's' || name[3] != '_') return -1;
        int k = name[4] == 'r' ? 5 : name[4] == 'a' ? 6 : name[4] == 'i' ? 7 : 8;
        return strcmp(name, special_names[k]) ? -1 : k;
    }
    default:
        return -1;
    }
}

/* An environment with more variables than this finds them by hashing (the
 * file scope of a library such as BOSL2 holds hundreds); below, a scan of
 * a few pointers is quicker. */
enum { ENV_INDEXED = 8 };

/* The slot of name in env->index, or the empty one where it would go. */
static uint32_t index_slot(const scad_env *env, const char *name)
{
    uint32_t k = scad_name_hash(name) & env->index_mask;
    while (env->index[k] && env->vars[env->index[k] - 1].name != name)
        k = (k + 1) & env->index_mask;
    return k;
}

/* Rebuild env->index for env->cap variables; on failure the index is
 * dropped and lookups scan. */
static void index_rebuild(scad_env *env)
{
    uint32_t cap = 16;
    while (cap < 2 * (uint32_t)env->cap)
        cap *= 2;
    free(env->index);
    env->index = calloc(cap, sizeof *env->index);
    if (!env->index) return;
    env->index_mask = cap - 1;
    for (int i = 0; i < env->nvars; i++)
        env->index[index_slot(env, env->vars[i].name)] = i + 1;
}

static scad_var *env_find(scad_env *env, const char *name)
{
    if (env->index) {
        int i = env->index[index_slot(env, name)];
        return i ? &env->vars[i - 1] : NULL;
    }
    for (int i = 0; i < env->nvars; i++)
        if (env->vars[i].name == name) return &env->vars[i];
    return NULL;
}

void scad_env_set(scad_env *env, const char *name, scad_value v)
{
    scad_var *old = env_find(env, name);
    if (old) {
        scad_value_drop(old->v);
        old->v = v;
        return;
    }
    if (env->nvars == env->cap) {
        int cap = env->cap * 2;
        scad_var *nv = malloc(sizeof *nv * (size_t)cap);
        if (!nv) {
            scad_value_drop(v);
            return;
        }
        memcpy(nv, env->vars, sizeof *nv * (size_t)env->nvars);
        if (env->vars != env->inline_vars) free(env->vars);
        env->vars = nv;
        env->cap = cap;
    }
    env->vars[env->nvars].name = name;
    env->vars[env->nvars].v = v;
    env->nvars++;
    if (env->nvars > ENV_INDEXED && (!env->index || 2 * (uint32_t)env->nvars > env->index_mask))
        index_rebuild(env);
    else if (env->index)
        env->index[index_slot(env, name)] = env->nvars;
    if (name[0] == '$') {
        int k = special_index(name);
        if (k >= 0) env->special[k] = env;
    }
}

/* The $-variables set in from and its lexical parents up to stop (inclusive)
 * copied into to, the innermost of each name winning, where to does not
 * set them already. */
void scad_env_copy_specials(scad_env *to, scad_env *from, const scad_env *stop)
{
    for (scad_env *e = from; e; e = e->parent) {
        for (int i = 0; i < e->nvars; i++)
            if (e->vars[i].name[0] == '$' && !env_find(to, e->vars[i].name))
                scad_env_set(to, e->vars[i].name, scad_value_ref(e->vars[i].v));
        if (e == stop) break;
    }
}

scad_value scad_env_lookup(scad_eval *ev, scad_env *env, const char *name, scad_loc loc, int silent,
                           int *found)
{
    /* $children is the count of the module whose body holds the
     * reference, a lexical variable (inside a child block it is the
     * caller's); every other $-variable is dynamic */
    int special = name[0] == '$' && name != ev->sym_children;
    int k = special ? special_index(name) : -1;
    if (k >= 0) { /* a well-known one: where it is, at once */
        scad_var *v = env->special[k] ? env_find(env->special[k], name) : NULL;
        if (v) {
            if (found) *found = 1;
            return v->v;
        }
        env = NULL;
    }
    for (scad_env *e = env; e; e = special ? e->dyn : e->parent) {
        scad_var *v = env_find(e, name);
        if (v) {
            if (found) *found = 1;
            return v->v;
        }
    }
    if (found) *found = 0;
    if (!silent) scad_diag_warning(ev->d, loc, "Ignoring unknown variable '%s'", name);
    return scad_undef();
}

scad_value scad_env_lookup_cstr(scad_eval *ev, scad_env *env, const char *name, scad_loc loc,
                                int silent, int *found)
{
    const char *interned = scad_names_find(ev->names, name);
    if (interned) return scad_env_lookup(ev, env, interned, loc, silent, found);
    if (found) *found = 0;
    if (!silent) scad_diag_warning(ev->d, loc, "Ignoring unknown variable '%s'", name);
    return scad_undef();
}

/* The environment of a `use`d file: its top-level variables, evaluated
 * afresh for every call from outside that file into one of its functions
 * or modules, as OpenSCAD 2021.01 does (FileContext::initializeModule runs
 * at each such call, echo() side effects included).  The caller frees it
 * with env_free after the call. */
static scad_env *use_env(scad_eval *ev, const scad_scope *u)
{
    scad_env *e = scad_env_new(ev, ev->builtins, ev->builtins, u);
    if (e) scad_run_assignments(ev, e, u);
    return e;
}

/* A function (want_module 0) or module by name: the innermost scope that
 * defines it, then the files that scope `use`s (not what they use).  With
 * def_env NULL only the definition is looked up; else *def_env is where it
 * was defined, and *fresh says whether that is a new environment of a used
 * file, which the caller frees after the call. */
static const void *find_def(scad_eval *ev, scad_env *env, const char *name, int want_module,
                            scad_env **def_env, int *fresh)
{
    for (scad_env *e = env; e; e = e->parent) {
        if (!e->defs) continue;
        for (int k = -1; k < e->defs->nuses; k++) {
            const scad_scope *s = k < 0 ? e->defs : e->defs->uses[k];
            const void *def = want_module ? (const void *)scad_scope_module(s, name)
                                          : (const void *)scad_scope_function(s, name);
            if (!def) continue;
            if (def_env) {
                *fresh = k >= 0;
                *def_env = k < 0 ? e : use_env(ev, s);
                if (!*def_env) return NULL;
            }
            return def;
        }
    }
    return NULL;
}

const scad_funcdef *scad_find_function(scad_eval *ev, scad_env *env, const char *name,
                                       scad_env **def_env, int *fresh)
{
    return find_def(ev, env, name, 0, def_env, fresh);
}

const scad_moddef *scad_find_module(scad_eval *ev, scad_env *env, const char *name,
                                    scad_env **def_env, int *fresh)
{
    return find_def(ev, env, name, 1, def_env, fresh);
}

/* ---- arguments ---------------------------------------------------------------- */

/* Evaluate a call's arguments in env, in OpenSCAD 2021.01's order, which
 * shows in echo() output and warnings.
 *
 * Builtin functions, echo, assert, for and let (resolve 0): first to last.
 *
 * User functions and modules (params given) and the other builtin modules
 * (params NULL), resolve 1: 2021.01 first resolves the arguments to names in
 * an std::unordered_map (EvalContext::resolveArguments).  A positional
 * argument takes the next parameter's name (past the last one: "Too many
 * unnamed arguments supplied", once, and it is dropped unevaluated); a later
 * argument of the same name replaces an earlier one, which is never
 * evaluated (a named one warns "argument x supplied more than once"); a
 * named argument that is no parameter warns "variable q not specified as
 * parameter" but is bound all the same.  Then the map is evaluated in its
 * iteration order, which in libstdc++ is the reverse of first insertion
 * while the keys fall in distinct buckets (collisions are not modelled).
 * With params, every argument in *out carries its resolved name; without,
 * positional arguments keep their relative order. */
int scad_args_bind(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out, int resolve,
                   const scad_args *params, int npositional, int user, scad_loc loc)
{
    out->n = 0;
    out->v = NULL;
    out->names = NULL;
    out->locs = NULL;
    out->pending = NULL;
    if (args->n == 0) return 0;
    out->v = malloc(sizeof *out->v * (size_t)args->n);
    out->names = malloc(sizeof *out->names * (size_t)args->n);
    out->locs = malloc(sizeof *out->locs * (size_t)args->n);
    int *arg_of = resolve ? malloc(sizeof *arg_of * (size_t)args->n) : NULL;
    if (!out->v || !out->names || !out->locs || (resolve && !arg_of)) {
        free(out->v);
        free(out->names);
        free(out->locs);
        free(arg_of);
        out->v = NULL;
        out->names = NULL;
        out->locs = NULL;
        scad_eval_error(ev, args->v[0].loc, "out of memory");
        return -1;
    }
    if (!resolve) {
        for (int i = 0; i < args->n; i++) {
            out->v[i] = args->v[i].value ? scad_eval_expr(ev, env, args->v[i].value) : scad_undef();
            out->names[i] = args->v[i].name;
            out->locs[i] = args->v[i].loc;
        }
        out->n = args->n;
        return 0;
    }
    int nkeys = 0, pos = 0, too_many = 0;
    for (int i = 0; i < args->n; i++) {
        const char *name = args->v[i].name;
        int named = name != NULL;
        if (!named && params) {
            if (pos >= npositional) {
                if (!too_many) scad_diag_warning(ev->d, loc, "Too many unnamed arguments supplied");
                too_many = 1;
                continue;
            }
            name = params->v[pos++].name;
        }
        if (named && params && name[0] != '$' &&
            !(user && ev->d->opt && ev->d->opt->no_parameter_check)) {
            int known = 0;
            for (int k = 0; k < params->n && !known; k++)
                known = params->v[k].name == name;
            if (!known)
                scad_diag_warning_own_doc(ev->d, loc, "variable %s not specified as parameter",
                                          name);
        }
        int k = 0;
        while (name && k < nkeys && out->names[k] != name)
            k++;
        if (name && k < nkeys) {
            if (named) scad_diag_warning(ev->d, loc, "argument %s supplied more than once", name);
        } else {
            k = nkeys++;
            out->names[k] = name;
        }
        arg_of[k] = i;
    }
    for (int k = nkeys - 1; k >= 0; k--) {
        const scad_arg *a = &args->v[arg_of[k]];
        out->v[k] = a->value ? scad_eval_expr(ev, env, a->value) : scad_undef();
        out->locs[k] = a->loc;
    }
    out->n = nkeys;
    free(arg_of);
    return 0;
}

int scad_args_eval(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out)
{
    return scad_args_bind(ev, env, args, out, 0, NULL, 0, 0, (scad_loc){0});
}

int scad_args_lazy(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out)
{
    memset(out, 0, sizeof *out);
    if (args->n == 0) return 0;
    out->v = malloc(sizeof *out->v * (size_t)args->n);
    out->names = malloc(sizeof *out->names * (size_t)args->n);
    out->locs = malloc(sizeof *out->locs * (size_t)args->n);
    out->pending = malloc((size_t)args->n);
    if (!out->v || !out->names || !out->locs || !out->pending) {
        scad_argv_free(out);
        scad_eval_error(ev, args->v[0].loc, "out of memory");
        return -1;
    }
    for (int i = 0; i < args->n; i++) {
        out->v[i] = scad_undef();
        out->names[i] = args->v[i].name;
        out->locs[i] = args->v[i].loc;
        out->pending[i] = args->v[i].value != NULL;
    }
    out->n = args->n;
    out->src = args;
    out->env = env;
    out->ev = ev;
    return 0;
}

scad_value scad_arg_at(const scad_argv *a, int i)
{
    if (a->pending && a->pending[i]) {
        a->pending[i] = 0;
        a->v[i] = scad_eval_expr(a->ev, a->env, a->src->v[i].value);
    }
    return a->v[i];
}

scad_value scad_arg_again(const scad_argv *a, int i)
{
    if (!a->src || !a->src->v[i].value) return scad_value_ref(scad_arg_at(a, i));
    return scad_eval_expr(a->ev, a->env, a->src->v[i].value);
}

void scad_argv_free(scad_argv *a)
{
    for (int i = 0; a->v && i < a->n; i++)
        if (!a->pending || !a->pending[i]) scad_value_drop(a->v[i]);
    free(a->v);
    free(a->names);
    free(a->locs);
    free(a->pending);
    a->pending = NULL;
    a->n = 0;
}

scad_value scad_argv_get(const scad_argv *a, const char *name, int pos)
{
    if (name)
        for (int i = a->n - 1; i >= 0; i--)
            if (a->names[i] && strcmp(a->names[i], name) == 0) return scad_arg_at(a, i);
    if (pos >= 0) {
        int k = 0;
        for (int i = 0; i < a->n; i++) {
            if (a->names[i]) continue;
            if (k++ == pos) return scad_arg_at(a, i);
        }
    }
    return scad_undef();
}

int scad_argv_given(const scad_argv *a, const char *name, int pos)
{
    if (name)
        for (int i = 0; i < a->n; i++)
            if (a->names[i] && strcmp(a->names[i], name) == 0) return 1;
    if (pos >= 0) {
        int k = 0;
        for (int i = 0; i < a->n; i++)
            if (!a->names[i] && k++ == pos) return 1;
    }
    return 0;
}

void scad_bind_defaults(scad_eval *ev, scad_env *target, scad_env *def_env, const scad_args *params)
{
    for (int i = 0; i < params->n; i++) {
        scad_value v =
            params->v[i].value ? scad_eval_expr(ev, def_env, params->v[i].value) : scad_undef();
        scad_env_set(target, params->v[i].name, v);
    }
}

void scad_bind_given(scad_env *target, const scad_argv *argv)
{
    for (int i = 0; i < argv->n; i++)
        scad_env_set(target, argv->names[i], scad_value_ref(argv->v[i]));
}
