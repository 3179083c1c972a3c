/*
 * eval.c — the evaluator: environments, expressions, list comprehensions,
 * user functions and modules, and the control modules (if, for,
 * intersection_for, let, echo, assert, children).
 *
 * Environments form two chains: `parent` is lexical (plain variables,
 * functions and modules are looked up there, as OpenSCAD does) and `dyn` is
 * the caller (for $-variables, which OpenSCAD scopes dynamically).  An
 * environment is freed when its scope ends unless a function literal closed
 * over it; those are kept on ev->captured until the evaluation ends.  A
 * scope evaluates all its assignments in order (each name once, at its
 * first position) before instantiating anything.  Every user call counts
 * against ev->max_depth and the C stack budget, and an error sets
 * ev->aborted, after which everything returns undef / no geometry at once
 * and nothing more is said (the error sets ev->d->stopped, which drops
 * every later message line).
 */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval.h"

enum { MAX_LOOP_ELEMENTS = 1000000 };

/* ---- errors and limits ------------------------------------------------------ */

/* OpenSCAD 2021.01 prints at most this many "TRACE: called by" lines
 * (its default trace depth). */
enum { TRACE_DEPTH = 12 };

/* Report msg as the error that stops the evaluation; in OpenSCAD's echo
 * stream it reads echo_msg (its own wording, when ours says more). */
static void eval_error_worded(scad_eval *ev, scad_loc loc, const char *echo_msg, const char *msg)
{
    if (!ev->aborted) {
        scad_diag_error(ev->d, loc, "%s", msg);
        scad_diag_trace(ev->d, loc, "ERROR: %s", echo_msg);
        for (int i = ev->nframes - 1, k = 0; i >= 0 && k < TRACE_DEPTH; i--, k++)
            scad_diag_trace(ev->d, ev->frames[i].loc, "TRACE: called by '%s'",
                            ev->frames[i].name);
        ev->d->stopped = 1;
    }
    ev->aborted = 1;
}

void scad_eval_error(scad_eval *ev, scad_loc loc, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    eval_error_worded(ev, loc, msg, msg);
}

scad_loc scad_eval_here(const scad_eval *ev)
{
    return ev->nframes > 0 ? ev->frames[ev->nframes - 1].loc : ev->at;
}

/* Enter a module instantiation or function call for the error trace.
 * Returns 0, or -1 when out of memory (the frame is then not recorded: a
 * shorter trace, nothing worse). */
static int push_frame(scad_eval *ev, const char *name, scad_loc loc)
{
    if (ev->nframes == ev->capframes) {
        int cap = ev->capframes ? 2 * ev->capframes : 64;
        struct scad_frame *f = realloc(ev->frames, sizeof *f * (size_t)cap);
        if (!f) return -1;
        ev->frames = f;
        ev->capframes = cap;
    }
    ev->frames[ev->nframes].name = name;
    ev->frames[ev->nframes].loc = loc;
    ev->nframes++;
    return 0;
}

static void pop_frame(scad_eval *ev, int pushed)
{
    if (pushed == 0) ev->nframes--;
}

/* One step of work (a call, a module instantiation, or a value of a loop or
 * list being built): 0 to go on; past ev->max_steps, an error and -1.  This
 * bounds the time an evaluation can take (nested loops, exponential
 * recursion). */
static int count_step(scad_eval *ev, scad_loc loc)
{
    if (++ev->steps <= ev->max_steps) return 0;
    scad_eval_error(ev, loc, "evaluation took more than %ld steps (calls and loop values)",
                    ev->max_steps);
    return -1;
}

int scad_eval_steps(scad_eval *ev, long n, scad_loc loc, const char *what)
{
    if (ev->aborted) return -1;
    if (n <= ev->max_steps - ev->steps) {
        ev->steps += n;
        return 0;
    }
    ev->steps = ev->max_steps;
    scad_eval_error(ev, loc, "evaluation took more than %ld steps (%s)", ev->max_steps, what);
    return -1;
}

/* Called on entry to every user function or module: 0 to go on. */
static int enter_call(scad_eval *ev, scad_loc loc, const char *what, const char *name)
{
    char here;
    if (ev->aborted) return -1;
    size_t used = ev->stack_base > &here ? (size_t)(ev->stack_base - &here)
                                         : (size_t)(&here - ev->stack_base);
    int too_deep = ev->depth >= ev->max_depth;
    if (too_deep || (ev->stack_budget && used > ev->stack_budget)) {
        char msg[512], echo_msg[512];
        if (too_deep)
            snprintf(msg, sizeof msg, "recursion deeper than %d calls (calling %s '%s')",
                     ev->max_depth, what, name);
        else
            snprintf(msg, sizeof msg,
                     "recursion deeper than the stack allows (%d calls, calling %s '%s')",
                     ev->depth, what, name);
        snprintf(echo_msg, sizeof echo_msg, "Recursion detected calling %s '%s'", what, name);
        eval_error_worded(ev, loc, echo_msg, msg);
        return -1;
    }
    if (count_step(ev, loc)) return -1;
    ev->depth++;
    return 0;
}

static void leave_call(scad_eval *ev)
{
    ev->depth--;
}

/* ---- environments ------------------------------------------------------------ */

static scad_env *env_new(scad_eval *ev, scad_env *parent, scad_env *dyn, const scad_scope *defs)
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

static void env_free(scad_env *e)
{
    if (e && !e->captured) env_release(e);
}

/* A closure keeps its environment and every lexical ancestor alive. */
static void env_capture(scad_eval *ev, scad_env *e)
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


scad_value scad_env_lookup(scad_eval *ev, scad_env *env, const char *name, scad_loc loc, int silent,
                           int *found)
{
    int special = name[0] == '$';
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

static void run_assignments(scad_eval *ev, scad_env *env, const scad_scope *s);

/* The environment of a `use`d file: its top-level variables, evaluated
 * afresh for every call from outside that file into one of its functions
 * or modules, as OpenSCAD 2021.01 does (FileContext::initializeModule runs
 * at each such call, echo() side effects included).  The caller frees it
 * with env_free after the call. */
static scad_env *use_env(scad_eval *ev, const scad_scope *u)
{
    scad_env *e = env_new(ev, ev->builtins, ev->builtins, u);
    if (e) run_assignments(ev, e, u);
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

static const scad_funcdef *find_function(scad_eval *ev, scad_env *env, const char *name,
                                         scad_env **def_env, int *fresh)
{
    return find_def(ev, env, name, 0, def_env, fresh);
}

static const scad_moddef *find_module(scad_eval *ev, scad_env *env, const char *name,
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
static int eval_args_ordered(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out,
                             int resolve, const scad_args *params, scad_loc loc)
{
    out->n = 0;
    out->v = NULL;
    out->names = NULL;
    out->locs = NULL;
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
            if (pos >= params->n) {
                if (!too_many) scad_diag_warning(ev->d, loc, "Too many unnamed arguments supplied");
                too_many = 1;
                continue;
            }
            name = params->v[pos++].name;
        }
        if (named && params && name[0] != '$') {
            int known = 0;
            for (int k = 0; k < params->n && !known; k++)
                known = params->v[k].name == name;
            if (!known)
                scad_diag_warning(ev->d, loc, "variable %s not specified as parameter", name);
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

static int eval_args(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out)
{
    return eval_args_ordered(ev, env, args, out, 0, NULL, (scad_loc){0});
}

static void argv_free(scad_argv *a)
{
    for (int i = 0; i < a->n; i++)
        scad_value_drop(a->v[i]);
    free(a->v);
    free(a->names);
    free(a->locs);
    a->n = 0;
}

scad_value scad_argv_get(const scad_argv *a, const char *name, int pos)
{
    if (name)
        for (int i = a->n - 1; i >= 0; i--)
            if (a->names[i] && strcmp(a->names[i], name) == 0) return a->v[i];
    if (pos >= 0) {
        int k = 0;
        for (int i = 0; i < a->n; i++) {
            if (a->names[i]) continue;
            if (k++ == pos) return a->v[i];
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

void scad_check_arg_names(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *const *known)
{
    for (int i = 0; i < a->n; i++) {
        if (!a->names[i] || a->names[i][0] == '$') continue;
        int ok = 0;
        for (const char *const *k = known; *k; k++)
            if (strcmp(*k, a->names[i]) == 0) ok = 1;
        if (!ok)
            scad_diag_warning(ev->d, loc, "variable %s not specified as parameter", a->names[i]);
    }
}

void scad_bind_defaults(scad_eval *ev, scad_env *target, scad_env *def_env,
                        const scad_args *params)
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

/* ---- operators ---------------------------------------------------------------- */

static const char *op_name(int op)
{
    static const char *two[] = {"<=", ">=", "==", "!=", "&&", "||"};
    static char one[8][2];
    if (op >= TK_LE && op <= TK_OR) return two[op - TK_LE];
    char *s = one[op & 7];
    s[0] = (char)op;
    s[1] = 0;
    return s;
}

static int is_num_vec(scad_value v)
{
    if (v.kind != SV_VEC) return 0;
    for (int i = 0; i < v.u.vec->n; i++)
        if (v.u.vec->v[i].kind != SV_NUM) return 0;
    return 1;
}

/* Elementwise +, - over the shorter length; non-matching elements give undef. */
static scad_value arith(int op, scad_value a, scad_value b, int *defined)
{
    *defined = 1;
    if (a.kind == SV_NUM && b.kind == SV_NUM) {
        switch (op) {
        case '+':
            return scad_num(a.u.num + b.u.num);
        case '-':
            return scad_num(a.u.num - b.u.num);
        case '*':
            return scad_num(a.u.num * b.u.num);
        case '/':
            return scad_num(a.u.num / b.u.num);
        case '%':
            return scad_num(fmod(a.u.num, b.u.num));
        case '^':
            return scad_num(pow(a.u.num, b.u.num));
        }
    }
    if ((op == '+' || op == '-') && a.kind == SV_VEC && b.kind == SV_VEC) {
        int n = a.u.vec->n < b.u.vec->n ? a.u.vec->n : b.u.vec->n;
        scad_value r = scad_vec_new(n);
        if (r.kind != SV_VEC) return r;
        int dummy;
        for (int i = 0; i < n; i++)
            r.u.vec->v[i] = arith(op, a.u.vec->v[i], b.u.vec->v[i], &dummy);
        return r;
    }
    if ((op == '*' && a.kind == SV_VEC && b.kind == SV_NUM) ||
        (op == '*' && a.kind == SV_NUM && b.kind == SV_VEC) ||
        (op == '/' && (a.kind == SV_VEC) != (b.kind == SV_VEC) &&
         (a.kind == SV_NUM || b.kind == SV_NUM))) {
        scad_value vec = a.kind == SV_VEC ? a : b;
        scad_value r = scad_vec_new(vec.u.vec->n);
        if (r.kind != SV_VEC) return r;
        int dummy;
        for (int i = 0; i < vec.u.vec->n; i++)
            r.u.vec->v[i] = a.kind == SV_VEC ? arith(op, a.u.vec->v[i], b, &dummy)
                                             : arith(op, a, b.u.vec->v[i], &dummy);
        return r;
    }
    *defined = 0;
    return scad_undef();
}

static scad_value dot(const scad_vec *a, const scad_vec *b)
{
    double s = 0;
    for (int i = 0; i < a->n; i++)
        s += a->v[i].u.num * b->v[i].u.num;
    return scad_num(s);
}

/* Vector and matrix products, with OpenSCAD's warnings. */
static scad_value multiply(scad_eval *ev, scad_loc loc, scad_value a, scad_value b, int *defined)
{
    if (!(a.kind == SV_VEC && b.kind == SV_VEC)) return arith('*', a, b, defined);
    *defined = 1;
    const scad_vec *A = a.u.vec, *B = b.u.vec;
    if (A->n == 0 || B->n == 0) return scad_undef();
    if (A->v[0].kind == SV_NUM) {
        if (B->v[0].kind == SV_NUM) { /* dot product */
            if (A->n != B->n) {
                scad_diag_warning(ev->d, loc, "vector*vector requires matching lengths (%d != %d)",
                                  A->n, B->n);
                return scad_undef();
            }
            if (!is_num_vec(a) || !is_num_vec(b)) return scad_undef();
            return dot(A, B);
        }
        /* vector * matrix */
        if (A->n != B->n) {
            scad_diag_warning(
                ev->d, loc,
                "vector*matrix requires vector length to match matrix row count (%d != %d)", A->n,
                B->n);
            return scad_undef();
        }
        if (!is_num_vec(a) || !is_num_vec(B->v[0])) return scad_undef();
        int cols = B->v[0].u.vec->n;
        for (int i = 0; i < B->n; i++)
            if (!is_num_vec(B->v[i]) || B->v[i].u.vec->n != cols) return scad_undef();
        scad_value r = scad_vec_new(cols);
        if (r.kind != SV_VEC) return r;
        for (int j = 0; j < cols; j++) {
            double s = 0;
            for (int i = 0; i < A->n; i++)
                s += A->v[i].u.num * B->v[i].u.vec->v[j].u.num;
            r.u.vec->v[j] = scad_num(s);
        }
        return r;
    }
    if (A->v[0].kind != SV_VEC) return scad_undef();
    int acols = A->v[0].u.vec->n;
    for (int i = 0; i < A->n; i++)
        if (!is_num_vec(A->v[i]) || A->v[i].u.vec->n != acols) return scad_undef();
    if (B->v[0].kind == SV_NUM) { /* matrix * vector */
        if (acols != B->n) {
            scad_diag_warning(
                ev->d, loc,
                "matrix*vector requires matrix column count to match vector length (%d != %d)",
                acols, B->n);
            return scad_undef();
        }
        if (!is_num_vec(b)) return scad_undef();
        scad_value r = scad_vec_new(A->n);
        if (r.kind != SV_VEC) return r;
        for (int i = 0; i < A->n; i++)
            r.u.vec->v[i] = dot(A->v[i].u.vec, B);
        return r;
    }
    if (B->v[0].kind != SV_VEC) return scad_undef();
    int bcols = B->v[0].u.vec->n;
    for (int i = 0; i < B->n; i++)
        if (!is_num_vec(B->v[i]) || B->v[i].u.vec->n != bcols) return scad_undef();
    if (acols != B->n) {
        scad_diag_warning(ev->d, loc,
                          "matrix*matrix requires left operand column count to match right operand "
                          "row count (%d != %d)",
                          acols, B->n);
        return scad_undef();
    }
    scad_value r = scad_vec_new(A->n);
    if (r.kind != SV_VEC) return r;
    for (int i = 0; i < A->n; i++) {
        scad_value row = scad_vec_new(bcols);
        if (row.kind != SV_VEC) break;
        for (int j = 0; j < bcols; j++) {
            double s = 0;
            for (int k = 0; k < acols; k++)
                s += A->v[i].u.vec->v[k].u.num * B->v[k].u.vec->v[j].u.num;
            row.u.vec->v[j] = scad_num(s);
        }
        r.u.vec->v[i] = row;
    }
    return r;
}

static scad_value binary(scad_eval *ev, const scad_expr *e, scad_value a, scad_value b)
{
    int op = e->op, defined = 1;
    scad_value r;
    switch (op) {
    case TK_EQ:
        return scad_bool(scad_value_equal(a, b));
    case TK_NE:
        return scad_bool(!scad_value_equal(a, b));
    case '<':
    case '>':
    case TK_LE:
    case TK_GE: {
        int c = scad_value_compare(a, b);
        if (c == 2) {
            if (a.kind == SV_NUM && b.kind == SV_NUM) return scad_bool(0); /* NaN */
            defined = 0;
            r = scad_undef();
            break;
        }
        r = scad_bool(op == '<' ? c < 0 : op == '>' ? c > 0 : op == TK_LE ? c <= 0 : c >= 0);
        break;
    }
    case '*':
        r = multiply(ev, e->loc, a, b, &defined);
        break;
    default:
        r = arith(op, a, b, &defined);
        break;
    }
    if (!defined)
        scad_diag_warning(ev->d, e->loc, "undefined operation (%s %s %s)", scad_value_type_name(a),
                          op_name(op), scad_value_type_name(b));
    return r;
}

static scad_value negate(scad_value v, int *defined)
{
    if (v.kind == SV_NUM) return scad_num(-v.u.num);
    if (v.kind == SV_VEC) {
        scad_value r = scad_vec_new(v.u.vec->n);
        if (r.kind != SV_VEC) return r;
        int dummy;
        for (int i = 0; i < v.u.vec->n; i++)
            r.u.vec->v[i] = negate(v.u.vec->v[i], &dummy);
        return r;
    }
    *defined = 0;
    return scad_undef();
}

/* ---- growable value lists ------------------------------------------------------ */

typedef struct vlist {
    scad_value *v;
    int n, cap;
} vlist;

static void vlist_push(scad_eval *ev, vlist *l, scad_value v, scad_loc loc)
{
    if (count_step(ev, loc)) {
        scad_value_drop(v);
        return;
    }
    if (l->n >= ev->max_list) {
        scad_value_drop(v);
        scad_eval_error(ev, loc, "list longer than %d elements", ev->max_list);
        return;
    }
    if (l->n == l->cap) {
        int cap = l->cap ? l->cap * 2 : 8;
        scad_value *nv = realloc(l->v, sizeof *nv * (size_t)cap);
        if (!nv) {
            scad_value_drop(v);
            scad_eval_error(ev, loc, "out of memory building a vector");
            return;
        }
        l->v = nv;
        l->cap = cap;
    }
    l->v[l->n++] = v;
}

static scad_value vlist_take(vlist *l)
{
    scad_value r = scad_vec_new(l->n);
    if (r.kind == SV_VEC) {
        if (l->n) memcpy(r.u.vec->v, l->v, sizeof *l->v * (size_t)l->n);
    } else {
        for (int i = 0; i < l->n; i++)
            scad_value_drop(l->v[i]);
    }
    free(l->v);
    l->v = NULL;
    l->n = l->cap = 0;
    return r;
}

static void vlist_free(vlist *l)
{
    for (int i = 0; i < l->n; i++)
        scad_value_drop(l->v[i]);
    free(l->v);
}

/* ---- iteration (for, each) --------------------------------------------------- */

/* Number of values of a range as OpenSCAD counts them: the quotient is
 * nudged up by one ulp so that [0:0.1:0.3] has 4 values; a zero step or an
 * infinite end gives UINT32_MAX (which the loop limit then refuses). */
double scad_range_steps(const scad_range *r)
{
    if (isnan(r->begin) || isnan(r->end) || isnan(r->step)) return 0;
    if (r->step < 0 ? r->begin < r->end : r->begin > r->end) return 0;
    if (r->begin == r->end || isinf(r->step)) return 1;
    if (isinf(r->begin) || isinf(r->end) || r->step == 0) return 4294967295.0;
    double q = floor(nextafter((r->end - r->begin) / r->step, INFINITY));
    if (q >= 4294967295.0) return 4294967295.0;
    return q + 1;
}

/* Expands v into the list of values a for loop visits.  Returns the count,
 * or -1 when refused (warned).  Borrowed items are referenced into out. */
static int iter_values(scad_eval *ev, scad_value v, scad_loc loc, vlist *out)
{
    switch (v.kind) {
    case SV_UNDEF:
        return 0;
    case SV_RANGE: {
        double n = scad_range_steps(v.u.range);
        if (n > MAX_LOOP_ELEMENTS) {
            scad_diag_warning(ev->d, loc,
                              "Bad range parameter in for statement: too many elements (%.0f)", n);
            return -1;
        }
        for (int i = 0; i < (int)n && !ev->aborted; i++)
            vlist_push(ev, out, scad_num(v.u.range->begin + i * v.u.range->step), loc);
        return out->n;
    }
    case SV_VEC:
        for (int i = 0; i < v.u.vec->n && !ev->aborted; i++)
            vlist_push(ev, out, scad_value_ref(v.u.vec->v[i]), loc);
        return out->n;
    case SV_STR: {
        const char *s = v.u.str->s;
        size_t i = 0;
        while (i < v.u.str->len && !ev->aborted) {
            size_t k = 1;
            while (i + k < v.u.str->len && ((unsigned char)s[i + k] & 0xC0) == 0x80)
                k++;
            vlist_push(ev, out, scad_str_new(s + i, k), loc);
            i += k;
        }
        return out->n;
    }
    default:
        vlist_push(ev, out, scad_value_ref(v), loc);
        return 1;
    }
}

/* ---- expressions -------------------------------------------------------------- */

static void echo_line(scad_eval *ev, const scad_argv *a);
static int check_assert(scad_eval *ev, scad_env *env, const scad_args *args, scad_loc loc);
static void assign_seq(scad_eval *ev, scad_env *env, const scad_args *args);

enum { MAX_TAIL_CALLS = 1000000 };

/* Is x a call of the named function def itself (not of a variable that
 * holds a function literal, nor of another definition)? */
static int is_self_call(scad_eval *ev, scad_env *env, const scad_expr *x, const scad_funcdef *def)
{
    if (!def || x->kind != EX_CALL || x->a[0]->kind != EX_VAR) return 0;
    if (x->a[0]->str != def->name) return 0;
    int found;
    scad_value v = scad_env_lookup(ev, env, def->name, x->loc, 1, &found);
    if (found && v.kind == SV_FUNC) return 0;
    return find_function(ev, env, def->name, NULL, NULL) == def;
}

/* A user function call.  As OpenSCAD 2021.01's evaluate_function does, the
 * body is followed through ?:, let, assert and echo without recursion, and a
 * call of the function itself in that tail position reuses this frame: the
 * new arguments are bound in a fresh environment and the loop goes on, so
 * tail recursion runs in constant C stack (up to MAX_TAIL_CALLS). */
static scad_value call_user_function(scad_eval *ev, scad_env *env, const scad_expr *call,
                                     const char *name, const scad_args *params,
                                     const scad_expr *body, scad_env *def_env,
                                     const scad_funcdef *def)
{
    scad_argv argv;
    /* the defaults and arguments count as one level deeper too: a default
     * that calls the function (f(x = f())) never reaches its body */
    if (enter_call(ev, call->loc, "function", name)) return scad_undef();
    scad_env *fe = env_new(ev, def_env, env, NULL);
    if (fe) scad_bind_defaults(ev, fe, def_env, params);
    if (!fe || eval_args_ordered(ev, env, &call->args, &argv, 1, params, call->loc)) {
        env_free(fe);
        leave_call(ev);
        return scad_undef();
    }
    leave_call(ev);
    if (enter_call(ev, call->loc, "function", name)) {
        argv_free(&argv);
        env_free(fe);
        return scad_undef();
    }
    scad_value r = scad_undef();
    long tail_calls = 0;
    while (fe && !ev->aborted) {
        scad_bind_given(fe, &argv);
        argv_free(&argv);
        /* follow the body; lets stack up environments below fe */
        scad_env *cur = fe;
        const scad_expr *x = body;
        const scad_expr *tail = NULL;
        while (x && !ev->aborted) {
            if (x->kind == EX_TERNARY) {
                scad_value c = scad_eval_expr(ev, cur, x->a[0]);
                int t = scad_value_truthy(c);
                scad_value_drop(c);
                x = x->a[t ? 1 : 2];
            } else if (x->kind == EX_ASSERT) {
                if (check_assert(ev, cur, &x->args, x->loc)) break;
                x = x->a[0];
            } else if (x->kind == EX_ECHO) {
                scad_argv ea;
                if (eval_args(ev, cur, &x->args, &ea)) break;
                if (!ev->aborted) echo_line(ev, &ea);
                argv_free(&ea);
                x = x->a[0];
            } else if (x->kind == EX_LET) {
                scad_env *le = env_new(ev, cur, cur, NULL);
                if (!le) break;
                assign_seq(ev, le, &x->args);
                cur = le;
                x = x->a[0];
            } else if (is_self_call(ev, cur, x, def)) {
                tail = x;
                break;
            } else {
                r = scad_eval_expr(ev, cur, x);
                break;
            }
        }
        /* the next frame: defaults, then the tail call's arguments (in cur) */
        scad_env *next = NULL;
        if (tail && !ev->aborted) {
            if (++tail_calls > MAX_TAIL_CALLS) {
                scad_eval_error(ev, tail->loc,
                                "recursion detected calling function '%s' (more than %d tail "
                                "calls)",
                                name, MAX_TAIL_CALLS);
            } else if ((next = env_new(ev, def_env, env, NULL))) {
                scad_bind_defaults(ev, next, def_env, params);
                if (eval_args_ordered(ev, cur, &tail->args, &argv, 1, params, tail->loc)) {
                    env_free(next);
                    next = NULL;
                }
            }
        }
        while (cur != fe) {
            scad_env *up = cur->parent;
            env_free(cur);
            cur = up;
        }
        env_free(fe);
        fe = next;
        if (fe && ev->aborted) {
            argv_free(&argv);
            env_free(fe);
            fe = NULL;
        }
    }
    leave_call(ev);
    return r;
}

static scad_value eval_call_framed(scad_eval *ev, scad_env *env, const scad_expr *e);

static scad_value eval_call(scad_eval *ev, scad_env *env, const scad_expr *e)
{
    const scad_expr *callee = e->a[0];
    int pushed =
        push_frame(ev, callee->kind == EX_VAR ? callee->str : "function literal", e->loc);
    scad_value r = eval_call_framed(ev, env, e);
    pop_frame(ev, pushed);
    return r;
}

static scad_value eval_call_framed(scad_eval *ev, scad_env *env, const scad_expr *e)
{
    const scad_expr *callee = e->a[0];
    scad_value fv = scad_undef();
    int owned = 0;
    if (callee->kind == EX_VAR) {
        int found;
        fv = scad_env_lookup(ev, env, callee->str, callee->loc, 1, &found);
        if (fv.kind != SV_FUNC && !strcmp(callee->str, "is_undef") && e->args.n == 1 &&
            e->args.v[0].value->kind == EX_VAR &&
            !find_function(ev, env, callee->str, NULL, NULL)) {
            /* OpenSCAD looks the variable up silently here */
            int there;
            scad_env_lookup(ev, env, e->args.v[0].value->str, e->loc, 1, &there);
            if (!there) return scad_bool(1);
        }
        if (fv.kind != SV_FUNC) {
            scad_env *def_env;
            int fresh;
            const scad_funcdef *f = find_function(ev, env, callee->str, &def_env, &fresh);
            if (f) {
                scad_value r =
                    call_user_function(ev, env, e, f->name, &f->params, f->body, def_env, f);
                if (fresh) env_free(def_env);
                return r;
            }
            scad_builtin_fn b = scad_builtin_function(callee->str);
            if (b) {
                scad_argv argv;
                if (eval_args(ev, env, &e->args, &argv)) return scad_undef();
                scad_value r = b(ev, &argv, e->loc, callee->str);
                argv_free(&argv);
                return r;
            }
            scad_diag_warning(ev->d, e->loc, "Ignoring unknown function '%s'", callee->str);
            return scad_undef();
        }
    } else {
        fv = scad_eval_expr(ev, env, callee);
        owned = 1;
        if (fv.kind != SV_FUNC) {
            if (!ev->aborted)
                scad_diag_warning(ev->d, e->loc, "Can't call function on %s",
                                  scad_value_type_name(fv));
            scad_value_drop(fv);
            return scad_undef();
        }
    }
    scad_value keep = scad_value_ref(fv);
    if (owned) scad_value_drop(fv);
    const scad_expr *lit = keep.u.func->lit;
    scad_value r =
        call_user_function(ev, env, e, "function literal", &lit->args, lit->a[0], keep.u.func->env,
                           NULL);
    scad_value_drop(keep);
    return r;
}

static scad_value eval_index(scad_value v, scad_value i)
{
    if (i.kind != SV_NUM || isnan(i.u.num) || i.u.num < 0) return scad_undef();
    double k = floor(i.u.num);
    if (v.kind == SV_VEC) {
        if (k >= v.u.vec->n) return scad_undef();
        return scad_value_ref(v.u.vec->v[(int)k]);
    }
    if (v.kind == SV_STR) {
        if (k >= (double)v.u.str->nchars) return scad_undef();
        const char *s = v.u.str->s;
        size_t pos = 0, c = 0;
        while (c < (size_t)k) {
            pos++;
            while (pos < v.u.str->len && ((unsigned char)s[pos] & 0xC0) == 0x80)
                pos++;
            c++;
        }
        size_t len = 1;
        while (pos + len < v.u.str->len && ((unsigned char)s[pos + len] & 0xC0) == 0x80)
            len++;
        return scad_str_new(s + pos, len);
    }
    if (v.kind == SV_RANGE) {
        const scad_range *r = v.u.range;
        if (k == 0) return scad_num(r->begin);
        if (k == 1) return scad_num(r->step);
        if (k == 2) return scad_num(r->end);
    }
    return scad_undef();
}

/* Runs the let/for assignments of args one after another in env. */
static void assign_seq(scad_eval *ev, scad_env *env, const scad_args *args)
{
    for (int i = 0; i < args->n && !ev->aborted; i++) {
        scad_value v = scad_eval_expr(ev, env, args->v[i].value);
        if (args->v[i].name)
            scad_env_set(env, args->v[i].name, v);
        else
            scad_value_drop(v);
    }
}

static void echo_line(scad_eval *ev, const scad_argv *a)
{
    scad_buf b = {0};
    scad_buf_puts(&b, "ECHO: ");
    for (int i = 0; i < a->n; i++) {
        if (i) scad_buf_puts(&b, ", ");
        if (a->names[i]) scad_buf_printf(&b, "%s = ", a->names[i]);
        scad_value_format(&b, a->v[i], 1);
    }
    scad_diag_line(ev->d, SCAD_MSG_ECHO, scad_buf_str(&b));
    scad_buf_free(&b);
}

/* assert(condition, message): 0 when it holds, else reports and aborts. */
static int check_assert(scad_eval *ev, scad_env *env, const scad_args *args, scad_loc loc)
{
    scad_argv a;
    if (eval_args(ev, env, args, &a)) return -1;
    scad_value c = scad_argv_get(&a, "condition", 0);
    int ok = scad_value_truthy(c);
    if (!ok && !ev->aborted) {
        scad_buf b = {0};
        const scad_expr *ce = NULL;
        for (int i = 0; i < args->n; i++)
            if (!args->v[i].name || strcmp(args->v[i].name, "condition") == 0) {
                ce = args->v[i].value;
                break;
            }
        scad_buf_puts(&b, "Assertion '");
        if (ce) scad_expr_format(&b, ce);
        scad_buf_puts(&b, "' failed");
        if (scad_argv_given(&a, "message", 1)) {
            scad_buf_puts(&b, ": ");
            scad_value_format(&b, scad_argv_get(&a, "message", 1), 1);
        }
        scad_eval_error(ev, loc, "%s", scad_buf_str(&b));
        scad_buf_free(&b);
    }
    argv_free(&a);
    return ok ? 0 : -1;
}

static void lc_eval(scad_eval *ev, scad_env *env, const scad_expr *e, vlist *out);

/* for (a = …, b = …) in a comprehension: nested, each level evaluated in
 * the environment of the levels outside it. */
static void lc_for(scad_eval *ev, scad_env *env, const scad_expr *e, int k, vlist *out)
{
    if (ev->aborted) return;
    if (k == e->args.n) {
        lc_eval(ev, env, e->a[0], out);
        return;
    }
    const scad_arg *arg = &e->args.v[k];
    scad_value src = scad_eval_expr(ev, env, arg->value);
    vlist items = {0};
    if (iter_values(ev, src, arg->loc, &items) > 0) {
        for (int i = 0; i < items.n && !ev->aborted; i++) {
            scad_env *ie = env_new(ev, env, env, NULL);
            if (!ie) break;
            if (arg->name) scad_env_set(ie, arg->name, scad_value_ref(items.v[i]));
            lc_for(ev, ie, e, k + 1, out);
            env_free(ie);
        }
    }
    vlist_free(&items);
    scad_value_drop(src);
}

static void push_each(scad_eval *ev, scad_value v, scad_loc loc, vlist *out)
{
    if (v.kind == SV_VEC || v.kind == SV_RANGE || v.kind == SV_STR) {
        vlist items = {0};
        if (iter_values(ev, v, loc, &items) > 0)
            for (int i = 0; i < items.n; i++)
                vlist_push(ev, out, scad_value_ref(items.v[i]), loc);
        vlist_free(&items);
        scad_value_drop(v);
    } else {
        vlist_push(ev, out, v, loc);
    }
}

static void lc_eval(scad_eval *ev, scad_env *env, const scad_expr *e, vlist *out)
{
    if (ev->aborted) return;
    switch (e->kind) {
    case LC_FOR:
        lc_for(ev, env, e, 0, out);
        break;
    case LC_CFOR: {
        scad_env *ie = env_new(ev, env, env, NULL);
        if (!ie) return;
        assign_seq(ev, ie, &e->args);
        long iterations = 0;
        for (;;) {
            scad_value c = scad_eval_expr(ev, ie, e->a[1]);
            int go = scad_value_truthy(c);
            scad_value_drop(c);
            if (!go || ev->aborted) break;
            if (++iterations > MAX_LOOP_ELEMENTS) {
                scad_diag_warning(ev->d, e->loc, "for loop stopped after %d iterations",
                                  MAX_LOOP_ELEMENTS);
                break;
            }
            lc_eval(ev, ie, e->a[0], out);
            /* the update reads the old values and makes a new environment */
            scad_env *ne = env_new(ev, env, env, NULL);
            if (!ne) break;
            for (int i = 0; i < ie->nvars; i++)
                scad_env_set(ne, ie->vars[i].name, scad_value_ref(ie->vars[i].v));
            for (int i = 0; i < e->args2.n && !ev->aborted; i++) {
                scad_value v = scad_eval_expr(ev, ie, e->args2.v[i].value);
                if (e->args2.v[i].name)
                    scad_env_set(ne, e->args2.v[i].name, v);
                else
                    scad_value_drop(v);
            }
            env_free(ie);
            ie = ne;
        }
        env_free(ie);
        break;
    }
    case LC_IF: {
        scad_value c = scad_eval_expr(ev, env, e->a[1]);
        int t = scad_value_truthy(c);
        scad_value_drop(c);
        if (t)
            lc_eval(ev, env, e->a[0], out);
        else if (e->a[2])
            lc_eval(ev, env, e->a[2], out);
        break;
    }
    case LC_LET: {
        scad_env *le = env_new(ev, env, env, NULL);
        if (!le) return;
        assign_seq(ev, le, &e->args);
        lc_eval(ev, le, e->a[0], out);
        env_free(le);
        break;
    }
    case LC_EACH: {
        if (e->a[0]->kind >= LC_FOR) {
            vlist inner = {0};
            lc_eval(ev, env, e->a[0], &inner);
            for (int i = 0; i < inner.n; i++) {
                push_each(ev, inner.v[i], e->loc, out);
                inner.v[i] = scad_undef();
            }
            vlist_free(&inner);
        } else {
            push_each(ev, scad_eval_expr(ev, env, e->a[0]), e->loc, out);
        }
        break;
    }
    default:
        vlist_push(ev, out, scad_eval_expr(ev, env, e), e->loc);
        break;
    }
}

scad_value scad_eval_expr(scad_eval *ev, scad_env *env, const scad_expr *e)
{
    if (ev->aborted) return scad_undef();
    switch (e->kind) {
    case EX_NUMBER:
        return scad_num(e->num);
    case EX_STRING:
        return scad_str_new(e->str, e->len);
    case EX_BOOL:
        return scad_bool((int)e->num);
    case EX_UNDEF:
        return scad_undef();
    case EX_VAR:
        return scad_value_ref(scad_env_lookup(ev, env, e->str, e->loc, 0, NULL));
    case EX_RANGE: {
        /* OpenSCAD 2021.01's order: begin, end, step */
        scad_value b = scad_eval_expr(ev, env, e->a[0]);
        scad_value en = scad_eval_expr(ev, env, e->a[2]);
        scad_value s = e->a[1] ? scad_eval_expr(ev, env, e->a[1]) : scad_num(1);
        scad_value r = scad_undef();
        if (b.kind == SV_NUM && s.kind == SV_NUM && en.kind == SV_NUM) {
            double bb = b.u.num, ss = s.u.num, ee = en.u.num;
            if (!e->a[1] && bb > ee) {
                scad_diag_deprecated(ev->d, e->loc,
                                     "Using ranges of the form [begin:end] with begin value "
                                     "greater than the end value is deprecated");
                double t = bb;
                bb = ee;
                ee = t;
            } else if (e->a[1] && ss < 0 && bb < ee) {
                scad_diag_warning(ev->d, e->loc,
                                  "begin is smaller than the end, but step is negative");
            } else if (e->a[1] && ss > 0 && bb > ee) {
                scad_diag_warning(ev->d, e->loc,
                                  "begin is greater than the end, but step is positive");
            }
            r = scad_range_new(bb, ss, ee);
        }
        scad_value_drop(b);
        scad_value_drop(s);
        scad_value_drop(en);
        return r;
    }
    case EX_VECTOR: {
        vlist l = {0};
        for (int i = 0; i < e->n && !ev->aborted; i++)
            lc_eval(ev, env, e->list[i], &l);
        if (ev->aborted) {
            vlist_free(&l);
            return scad_undef();
        }
        return vlist_take(&l);
    }
    case EX_UNARY: {
        scad_value v = scad_eval_expr(ev, env, e->a[0]);
        scad_value r;
        int defined = 1;
        if (e->op == '!')
            r = scad_bool(!scad_value_truthy(v));
        else if (e->op == '-')
            r = negate(v, &defined);
        else if (v.kind == SV_NUM || v.kind == SV_VEC)
            r = scad_value_ref(v);
        else
            defined = 0, r = scad_undef();
        if (!defined && !ev->aborted)
            scad_diag_warning(ev->d, e->loc, "undefined operation (%c%s)", e->op,
                              scad_value_type_name(v));
        scad_value_drop(v);
        return r;
    }
    case EX_BINARY: {
        if (e->op == TK_AND || e->op == TK_OR) {
            scad_value a = scad_eval_expr(ev, env, e->a[0]);
            int t = scad_value_truthy(a);
            scad_value_drop(a);
            if (e->op == TK_AND ? !t : t) return scad_bool(t);
            scad_value b = scad_eval_expr(ev, env, e->a[1]);
            t = scad_value_truthy(b);
            scad_value_drop(b);
            return scad_bool(t);
        }
        /* the right operand first, as OpenSCAD 2021.01 (built by GCC) does:
         * its echo() output and warnings come first */
        scad_value b = scad_eval_expr(ev, env, e->a[1]);
        scad_value a = scad_eval_expr(ev, env, e->a[0]);
        scad_value r = ev->aborted ? scad_undef() : binary(ev, e, a, b);
        scad_value_drop(a);
        scad_value_drop(b);
        return r;
    }
    case EX_TERNARY: {
        scad_value c = scad_eval_expr(ev, env, e->a[0]);
        int t = scad_value_truthy(c);
        scad_value_drop(c);
        return scad_eval_expr(ev, env, e->a[t ? 1 : 2]);
    }
    case EX_CALL:
        return eval_call(ev, env, e);
    case EX_INDEX: {
        scad_value i = scad_eval_expr(ev, env, e->a[1]); /* the index first */
        scad_value v = scad_eval_expr(ev, env, e->a[0]);
        scad_value r = eval_index(v, i);
        scad_value_drop(v);
        scad_value_drop(i);
        return r;
    }
    case EX_MEMBER: {
        scad_value v = scad_eval_expr(ev, env, e->a[0]);
        scad_value r = scad_undef();
        const char *m = e->str;
        int k = -1;
        if (v.kind == SV_VEC)
            k = !strcmp(m, "x") ? 0 : !strcmp(m, "y") ? 1 : !strcmp(m, "z") ? 2 : -1;
        if (v.kind == SV_RANGE)
            k = !strcmp(m, "begin") ? 0 : !strcmp(m, "step") ? 1 : !strcmp(m, "end") ? 2 : -1;
        if (k >= 0) r = eval_index(v, scad_num(k));
        scad_value_drop(v);
        return r;
    }
    case EX_LET: {
        scad_env *le = env_new(ev, env, env, NULL);
        if (!le) return scad_undef();
        assign_seq(ev, le, &e->args);
        scad_value r = scad_eval_expr(ev, le, e->a[0]);
        env_free(le);
        return r;
    }
    case EX_ASSERT:
        if (check_assert(ev, env, &e->args, e->loc)) return scad_undef();
        return e->a[0] ? scad_eval_expr(ev, env, e->a[0]) : scad_undef();
    case EX_ECHO: {
        scad_argv a;
        if (eval_args(ev, env, &e->args, &a)) return scad_undef();
        if (!ev->aborted) echo_line(ev, &a);
        argv_free(&a);
        return e->a[0] ? scad_eval_expr(ev, env, e->a[0]) : scad_undef();
    }
    case EX_FUNCLIT:
        env_capture(ev, env);
        return scad_func_new(e, env);
    default: {
        /* a comprehension outside [ ]: not produced by the parser */
        vlist l = {0};
        lc_eval(ev, env, e, &l);
        return vlist_take(&l);
    }
    }
}

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

/* Empty children are skipped (as OpenSCAD's CSG tree drops them); a single
 * child stands for itself.  In dump mode the result is a bare list of all
 * of them (NULL when none). */
static scad_geom *finish(scad_eval *ev, gather *g, csg_op op)
{
    scad_geom *r = NULL;
    if (ev->dump) {
        if (g->n > 0) r = scad_geom_op(ev, op);
        for (int i = 0; r && i < g->n; i++)
            scad_geom_add(ev, r, g->v[i]);
    } else if (g->n == 1) {
        r = g->v[0];
    } else if (g->n > 1) {
        r = scad_geom_op(ev, op);
        for (int i = 0; i < g->n; i++)
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

static void run_assignments(scad_eval *ev, scad_env *env, const scad_scope *s)
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
    }
}

/* A child scope: a fresh environment below env for its assignments. */
static scad_geom *child_scope(scad_eval *ev, scad_env *env, scad_env *dyn, const scad_scope *s,
                              const scad_state *state, csg_op op, const int *pick, int npick)
{
    if (!s || ev->aborted) return NULL;
    scad_env *ce = env_new(ev, env, dyn, s);
    if (!ce) return NULL;
    gather g = {0};
    run_assignments(ev, ce, s);
    run_stmts(ev, ce, s, state, &g, pick, npick);
    env_free(ce);
    return finish(ev, &g, op);
}

scad_geom *scad_eval_children(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_state *state, csg_op op)
{
    return child_scope(ev, env, env, st->children, state, op, NULL, 0);
}

/* OpenSCAD's Expression::isLiteral: constants, and vectors and ranges of
 * constants. */
static int is_literal(const scad_expr *e)
{
    switch (e->kind) {
    case EX_NUMBER:
    case EX_STRING:
    case EX_BOOL:
    case EX_UNDEF:
        return 1;
    case EX_VECTOR:
        for (int i = 0; i < e->n; i++)
            if (!is_literal(e->list[i])) return 0;
        return 1;
    case EX_RANGE:
        return is_literal(e->a[0]) && (!e->a[1] || is_literal(e->a[1])) && is_literal(e->a[2]);
    default:
        return 0;
    }
}

static scad_geom *call_module(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_moddef *m, scad_env *def_env, const scad_state *state)
{
    scad_argv argv;
    scad_env *me = env_new(ev, def_env, env, m->body);
    if (!me) return NULL;
    scad_bind_defaults(ev, me, def_env, &m->params);
    if (eval_args_ordered(ev, env, &st->args, &argv, 1, &m->params, st->loc)) {
        env_free(me);
        return NULL;
    }
    if (enter_call(ev, st->loc, "module", m->name)) {
        argv_free(&argv);
        env_free(me);
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
    if (ev->module_depth < ev->module_names_cap)
        ev->module_names[ev->module_depth] = m->name;
    ev->module_depth++;
    scad_env_set(me, ev->sym_parent_modules, scad_num(ev->module_depth));
    for (int i = 0; i < m->body->nassigns; i++) {
        const scad_assign *as = &m->body->assigns[i];
        if (!is_literal(as->value)) continue;
        for (int k = 0; k < m->params.n; k++)
            if (m->params.v[k].name == as->name)
                scad_diag_warning(ev->d, as->loc,
                                  "Module %s: Parameter %s is overwritten with a literal",
                                  m->name, as->name);
    }
    gather g = {0};
    run_assignments(ev, me, m->body);
    run_stmts(ev, me, m->body, state, &g, NULL, 0);
    r = finish(ev, &g, CSG_OP_UNION);
    if (ev->dump) r = scad_dump_node(ev, "group()", r);
    env_free(me);
    ev->module_depth--;
    leave_call(ev);
    argv_free(&argv);
    return r;
}

/* A number as C's (int) conversion gives it on x86-64, where OpenSCAD
 * 2021.01 was built: NaN and out-of-range values become INT_MIN (here
 * without the undefined behaviour of converting them). */
static int x86_int(double k)
{
    return isnan(k) || k >= 2147483648.0 || k < -2147483648.0 ? INT_MIN : (int)k;
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
    scad_diag_line(ev->d, SCAD_MSG_WARNING, line);
    return 1;
}

static scad_geom *do_children(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                              const scad_state *state)
{
    scad_env *m = env;
    while (m && !m->is_module)
        m = m->parent;
    if (!m) return NULL;
    int n = m->children ? m->children->nstmts : 0;
    /* instantiating the caller's children is a call of their scope, and
     * counts as one more step, as a user module's body does */
    if (count_step(ev, st->loc)) return NULL;
    if (a->n == 0) {
        scad_geom *r =
            n ? child_scope(ev, m->children_env, env, m->children, state, CSG_OP_UNION, NULL, 0)
              : NULL;
        return ev->dump ? scad_dump_node(ev, "group()", r) : r;
    }
    scad_value sel = scad_argv_get(a, "index", 0);
    vlist idx = {0};
    if (sel.kind == SV_NUM) {
        vlist_push(ev, &idx, scad_value_ref(sel), st->loc);
    } else if (sel.kind == SV_VEC || sel.kind == SV_RANGE) {
        if (iter_values(ev, sel, st->loc, &idx) < 0) {
            vlist_free(&idx);
            return NULL;
        }
    } else {
        scad_diag_warning(
            ev->d, st->loc,
            "Bad parameter type (%s) for children, only accept: empty, number, vector, range.",
            scad_value_type_name(sel));
        return NULL;
    }
    if (ev->dump && sel.kind != SV_NUM) {
        /* OpenSCAD evaluates each index on its own, into one group */
        gather g = {0};
        for (int i = 0; i < idx.n && !ev->aborted; i++) {
            if (idx.v[i].kind != SV_NUM) continue;
            int one = x86_int(idx.v[i].u.num);
            if (children_index_bad(ev, one, n)) continue;
            gather_add(ev, &g,
                       child_scope(ev, m->children_env, env, m->children, state, CSG_OP_UNION,
                                   &one, 1));
        }
        vlist_free(&idx);
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
    vlist_free(&idx);
    return r;
}

/* for / intersection_for: nested loops over the arguments, evaluated once
 * in the caller's environment (as OpenSCAD does). */
static void for_loop(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a, int k,
                     scad_env *cur, const scad_state *state, gather *out)
{
    if (ev->aborted) return;
    if (k == a->n) {
        gather_add(ev, out, child_scope(ev, cur, cur, st->children, state, CSG_OP_UNION, NULL, 0));
        return;
    }
    vlist items = {0};
    if (iter_values(ev, a->v[k], a->locs[k], &items) > 0) {
        for (int i = 0; i < items.n && !ev->aborted; i++) {
            scad_env *ie = env_new(ev, cur, cur, NULL);
            if (!ie) break;
            if (a->names[k]) scad_env_set(ie, a->names[k], scad_value_ref(items.v[i]));
            for_loop(ev, env, st, a, k + 1, ie, state, out);
            env_free(ie);
        }
    }
    vlist_free(&items);
}

/* Stands for OpenSCAD's builtin modules that have no geometry here (yet):
 * their children are still evaluated, for what they echo, and dropped. */
static scad_geom *m_dump_only(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_argv *a, const scad_state *state)
{
    if (!strcmp(st->name, "polyhedron") && !scad_argv_given(a, "faces", 1) &&
        scad_argv_get(a, "triangles", -1).kind != SV_UNDEF)
        scad_diag_line(ev->d, SCAD_MSG_WARNING,
                       "DEPRECATED: polyhedron(triangles=[]) will be removed in future releases. "
                       "Use polyhedron(faces=[]) instead.");
    scad_eval_children(ev, env, st, state, CSG_OP_UNION);
    return NULL;
}

static scad_geom *instantiate_plain(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                    const scad_state *state)
{
    const char *name = st->name;
    if (strcmp(name, "if") == 0) {
        scad_value c = scad_eval_expr(ev, env, st->cond);
        int t = scad_value_truthy(c);
        scad_value_drop(c);
        scad_geom *r = child_scope(ev, env, env, t ? st->children : st->else_children, state,
                                   CSG_OP_UNION, NULL, 0);
        if (ev->dump && (t || st->else_children)) r = scad_dump_node(ev, "group()", r);
        return r;
    }
    scad_env *def_env;
    int fresh;
    const scad_moddef *m = find_module(ev, env, name, &def_env, &fresh);
    if (m) {
        scad_geom *r = call_module(ev, env, st, m, def_env, state);
        if (fresh) env_free(def_env);
        return r;
    }

    if (strcmp(name, "let") == 0) {
        scad_env *le = env_new(ev, env, env, NULL);
        if (!le) return NULL;
        assign_seq(ev, le, &st->args);
        scad_geom *r = child_scope(ev, le, le, st->children, state, CSG_OP_UNION, NULL, 0);
        env_free(le);
        return ev->dump ? scad_dump_node(ev, "group()", r) : r;
    }
    if (strcmp(name, "assert") == 0) {
        if (check_assert(ev, env, &st->args, st->loc)) return NULL;
        scad_geom *r = scad_eval_children(ev, env, st, state, CSG_OP_UNION);
        return ev->dump && r ? scad_dump_node(ev, "group()", r) : r;
    }
    int control = !strcmp(name, "for") || !strcmp(name, "intersection_for") ||
                  !strcmp(name, "echo") || !strcmp(name, "children");
    /* the control modules need no table search (children() runs often) */
    scad_builtin_mod bm = control ? NULL : scad_builtin_module(name);
    if (!bm && !control && scad_dump_is_builtin(name)) bm = m_dump_only;
    if (!bm && !control) {
        scad_diag_warning(ev->d, st->loc, "Ignoring unknown module '%s'", name);
        return NULL;
    }
    scad_argv a;
    int in_order = control || !strcmp(name, "assert") || !strcmp(name, "let");
    if (eval_args_ordered(ev, env, &st->args, &a, !in_order, NULL, st->loc)) return NULL;
    scad_geom *r = NULL;
    /* $-arguments of a builtin are seen by its children (dynamic scope) */
    scad_env *dollar = NULL;
    for (int i = 0; i < a.n; i++) {
        if (!a.names[i] || a.names[i][0] != '$') continue;
        if (!dollar && !(dollar = env_new(ev, env, env, NULL))) break;
        scad_env_set(dollar, a.names[i], scad_value_ref(a.v[i]));
    }
    if (dollar) env = dollar;
    if (ev->aborted) {
        /* nothing */
    } else if (!strcmp(name, "for") || !strcmp(name, "intersection_for")) {
        gather g = {0};
        for_loop(ev, env, st, &a, 0, env, state, &g);
        r = finish(ev, &g, name[0] == 'f' ? CSG_OP_UNION : CSG_OP_INTERSECTION);
        if (ev->dump) r = scad_dump_node(ev, name[0] == 'f' ? "group()" : "intersection()", r);
    } else if (!strcmp(name, "echo")) {
        echo_line(ev, &a);
        r = scad_eval_children(ev, env, st, state, CSG_OP_UNION);
        if (ev->dump && r) r = scad_dump_node(ev, "group()", r);
    } else if (!strcmp(name, "children")) {
        r = do_children(ev, env, st, &a, state);
    } else if (ev->dump) {
        r = scad_dump_builtin(ev, env, st, &a);
    } else {
        r = bm(ev, env, st, &a, state);
    }
    argv_free(&a);
    env_free(dollar);
    return r;
}

static scad_geom *instantiate_framed(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                     const scad_state *state);

static scad_geom *instantiate(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_state *state)
{
    if (st->disable || ev->aborted || count_step(ev, st->loc)) return NULL;
    int pushed = push_frame(ev, st->name, st->loc);
    scad_geom *g = instantiate_framed(ev, env, st, state);
    pop_frame(ev, pushed);
    return g;
}

static scad_geom *instantiate_framed(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                     const scad_state *state)
{
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
        scad_geom *g = instantiate_plain(ev, env, st, &fresh);
        if (!ev->has_root) {
            ev->root = g;
            ev->has_root = 1;
        }
        return NULL;
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
    run_assignments(ev, env, s);
    run_stmts(ev, env, s, &st, &g, NULL, 0);
    return finish(ev, &g, CSG_OP_UNION);
}

/* Environment creation for scad.c (the builtin and file scopes). */
scad_env *scad_env_new_root(scad_eval *ev, scad_env *parent, const scad_scope *defs)
{
    return env_new(ev, parent, parent, defs);
}
void scad_env_free(scad_env *e)
{
    env_free(e);
}
