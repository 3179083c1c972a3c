/*
 * eval_call.c — calls: the limits every call counts against (depth, the C
 * stack, steps of work), the frames of OpenSCAD's error trace, the error
 * that stops an evaluation, and user function calls with their tail-call
 * loop.
 *
 * Every user call counts against ev->max_depth and the C stack budget, and
 * an error sets ev->aborted, after which everything returns undef / no
 * geometry at once and nothing more is said (the error sets
 * ev->d->stopped, which drops every later message line).
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

enum { MAX_TAIL_CALLS = 1000000 };

/* ---- errors and limits ------------------------------------------------------ */

/* OpenSCAD 2021.01 prints at most this many "TRACE: called by" lines
 * (its default trace depth). */
enum { TRACE_DEPTH = 12 };

/* Report msg at loc as the error that stops the evaluation; in OpenSCAD's
 * echo stream it reads echo_msg at echo_loc (its own wording and place,
 * when ours says more), then at most TRACE_DEPTH TRACE lines, the skip
 * innermost frames left out. */
static void eval_error_at(scad_eval *ev, scad_loc loc, scad_loc echo_loc, const char *echo_msg,
                          const char *msg, int skip)
{
    if (!ev->aborted) {
        scad_diag_error(ev->d, loc, "%s", msg);
        scad_diag_trace(ev->d, echo_loc, "ERROR: %s", echo_msg);
        for (int i = ev->nframes - 1 - skip, k = 0; i >= 0 && k < TRACE_DEPTH; i--, k++)
            scad_diag_trace(ev->d, ev->frames[i].loc, "TRACE: called by '%s'", ev->frames[i].name);
        ev->d->stopped = 1;
    }
    ev->aborted = 1;
}

/* The error fmt/ap at loc, in the echo stream as echo_msg (NULL: the same). */
static void eval_verror(scad_eval *ev, scad_loc loc, const char *echo_msg, const char *fmt,
                        va_list ap)
{
    char msg[1024];
    vsnprintf(msg, sizeof msg, fmt, ap);
    eval_error_at(ev, loc, loc, echo_msg ? echo_msg : msg, msg, 0);
}

void scad_eval_hard_stop(void *ud)
{
    scad_eval *ev = ud;
    if (ev->aborted) return;
    /* openscad 2021.01 stops as at an error, the warning in the ERROR
     * line's place: the call trace follows it */
    for (int i = ev->nframes - 1, k = 0; i >= 0 && k < TRACE_DEPTH; i--, k++)
        scad_diag_trace(ev->d, ev->frames[i].loc, "TRACE: called by '%s'", ev->frames[i].name);
    scad_diag_error(ev->d, scad_eval_here(ev), "stopped at the first warning (--hardwarnings)");
    ev->d->stopped = 1;
    ev->aborted = 1;
}

void scad_eval_error(scad_eval *ev, scad_loc loc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    eval_verror(ev, loc, NULL, fmt, ap);
    va_end(ap);
}

void scad_eval_error_worded(scad_eval *ev, scad_loc loc, const char *echo_msg, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    eval_verror(ev, loc, echo_msg, fmt, ap);
    va_end(ap);
}

void scad_deprecated_once(scad_eval *ev, const char *msg)
{
    char line[512];
    snprintf(line, sizeof line, "DEPRECATED: %s", msg);
    scad_diag_deprecated_line(ev->d, line);
}

scad_loc scad_eval_here(const scad_eval *ev)
{
    return ev->nframes > 0 ? ev->frames[ev->nframes - 1].loc : ev->at;
}

/* Enter a module instantiation or function call for the error trace.
 * Returns 0, or -1 when out of memory (the frame is then not recorded: a
 * shorter trace, nothing worse). */
int scad_frame_push(scad_eval *ev, const char *name, scad_loc loc)
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

void scad_frame_pop(scad_eval *ev, int pushed)
{
    if (pushed == 0) ev->nframes--;
}

/* One step of work (a call, a module instantiation, or a value of a loop or
 * list being built): 0 to go on; past ev->max_steps, an error and -1.  This
 * bounds the time an evaluation can take (nested loops, exponential
 * recursion). */
int scad_eval_step(scad_eval *ev, scad_loc loc)
{
    if ((ev->steps & 0xffff) == 0 && ev->progress) ev->progress(ev->progress_ud, ev->progress_done);
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
int scad_call_enter(scad_eval *ev, scad_loc loc, scad_loc echo_loc, const char *what,
                    const char *name)
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
        /* a function call too deep fails before its own frame would say
         * "called by" (2021.01 checks the stack outside its try) */
        eval_error_at(ev, loc, echo_loc, echo_msg, msg, !strcmp(what, "function"));
        return -1;
    }
    if (scad_eval_step(ev, loc)) return -1;
    ev->depth++;
    return 0;
}

void scad_call_leave(scad_eval *ev)
{
    ev->depth--;
}

/* Is x a call of the function being called itself: of the named function
 * def (not of a variable holding a function literal, nor of another
 * definition), or, for a function literal (def NULL), of a variable that
 * holds this same literal with this same closure? */
static int is_self_call(scad_eval *ev, scad_env *env, const scad_expr *x, const scad_funcdef *def,
                        const scad_expr *lit, const scad_env *closure)
{
    if (x->kind != EX_CALL || x->a[0]->kind != EX_VAR) return 0;
    const char *name = x->a[0]->str;
    if (name[0] == '$') return 0;
    int found;
    scad_value v = scad_env_lookup(ev, env, name, x->loc, 1, &found);
    if (!def)
        return lit && found && v.kind == SV_FUNC && v.u.func->lit->a[0] == lit &&
               v.u.func->env == closure;
    if (name != def->name) return 0;
    if (found && v.kind == SV_FUNC) return 0;
    return scad_find_function(ev, env, def->name, NULL, NULL) == def;
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
    if (scad_call_enter(ev, call->loc, call->loc, "function", name)) return scad_undef();
    scad_env *fe = scad_env_new(ev, def_env, env, NULL);
    if (fe) scad_bind_defaults(ev, fe, def_env, params);
    if (!fe || scad_args_bind(ev, env, &call->args, &argv, 1, params, params->n, 1, call->loc)) {
        scad_env_free(fe);
        scad_call_leave(ev);
        return scad_undef();
    }
    scad_call_leave(ev);
    if (scad_call_enter(ev, call->loc, call->loc, "function", name)) {
        scad_argv_free(&argv);
        scad_env_free(fe);
        return scad_undef();
    }
    scad_value r = scad_undef();
    long tail_calls = 0;
    while (fe && !ev->aborted) {
        scad_bind_given(fe, &argv);
        scad_argv_free(&argv);
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
                if (scad_check_assert(ev, cur, &x->args, x->loc)) break;
                x = x->a[0];
            } else if (x->kind == EX_ECHO) {
                scad_argv ea;
                if (scad_args_eval(ev, cur, &x->args, &ea)) break;
                if (!ev->aborted) scad_echo_line(ev, &ea);
                scad_argv_free(&ea);
                x = x->a[0];
            } else if (x->kind == EX_LET) {
                scad_env *le = scad_env_new(ev, cur, cur, NULL);
                if (!le) break;
                scad_assign_seq(ev, le, &x->args);
                cur = le;
                x = x->a[0];
            } else if (is_self_call(ev, cur, x, def, body, def_env)) {
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
                char echo_msg[512];
                snprintf(echo_msg, sizeof echo_msg, "Recursion detected calling function '%s'",
                         name);
                scad_eval_error_worded(
                    ev, tail->loc, echo_msg,
                    "recursion detected calling function '%s' (more than %d tail calls)", name,
                    MAX_TAIL_CALLS);
            } else if ((next = scad_env_new(ev, def_env, env, NULL))) {
                /* the frame being left is the call's dynamic parent: its
                 * $-variables ($fn given to the first call) go on */
                scad_env_copy_specials(next, cur, fe);
                scad_bind_defaults(ev, next, def_env, params);
                if (scad_args_bind(ev, cur, &tail->args, &argv, 1, params, params->n, 1,
                                   tail->loc)) {
                    scad_env_free(next);
                    next = NULL;
                }
            }
        }
        while (cur != fe) {
            scad_env *up = cur->parent;
            scad_env_free(cur);
            cur = up;
        }
        scad_env_free(fe);
        fe = next;
        if (fe && ev->aborted) {
            scad_argv_free(&argv);
            scad_env_free(fe);
            fe = NULL;
        }
    }
    scad_call_leave(ev);
    return r;
}

static scad_value eval_call_framed(scad_eval *ev, scad_env *env, const scad_expr *e);

scad_value scad_eval_call(scad_eval *ev, scad_env *env, const scad_expr *e)
{
    const scad_expr *callee = e->a[0];
    int pushed =
        scad_frame_push(ev, callee->kind == EX_VAR ? callee->str : "function literal", e->loc);
    scad_value r = eval_call_framed(ev, env, e);
    scad_frame_pop(ev, pushed);
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
        /* 2021.01 refuses a function value only when its name is a
         * $-variable's; other $-names go on to "Ignoring unknown function" */
        if (fv.kind == SV_FUNC && callee->str[0] == '$') {
            scad_diag_warning(ev->d, e->loc, "Can't call function on dynamically scoped variable");
            return scad_undef();
        }
        if (fv.kind != SV_FUNC && !strcmp(callee->str, "is_undef") && e->args.n == 1 &&
            e->args.v[0].value->kind == EX_VAR &&
            !scad_find_function(ev, env, callee->str, NULL, NULL)) {
            /* OpenSCAD looks the variable up silently here */
            int there;
            scad_env_lookup(ev, env, e->args.v[0].value->str, e->loc, 1, &there);
            if (!there) return scad_bool(1);
        }
        if (fv.kind != SV_FUNC) {
            scad_env *def_env;
            int fresh;
            const scad_funcdef *f = scad_find_function(ev, env, callee->str, &def_env, &fresh);
            if (f) {
                scad_value r =
                    call_user_function(ev, env, e, f->name, &f->params, f->body, def_env, f);
                if (fresh) scad_env_free(def_env);
                return r;
            }
            const scad_function_def *b =
                ev->no_builtins ? NULL : scad_registry_function(callee->str);
            if (b) {
                scad_argv argv;
                if (scad_args_lazy(ev, env, &e->args, &argv)) return scad_undef();
                scad_value r = b->fn(ev, &argv, e->loc, callee->str);
                scad_argv_free(&argv);
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
        call_user_function(ev, env, e, callee->kind == EX_VAR ? callee->str : "function literal",
                           &lit->args, lit->a[0], keep.u.func->env, NULL);
    scad_value_drop(keep);
    return r;
}
