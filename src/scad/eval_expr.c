/*
 * eval_expr.c — expressions: operators with OpenSCAD's warnings, vectors and
 * list comprehensions, ranges and iteration, let, assert, echo and function
 * literals.  Function calls are eval_call.c's.
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

/* ---- operators ---------------------------------------------------------------- */

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

/* The products of two vectors, as OpenSCAD 2021.01's multiply_visitor
 * (value.cc): the shape comes from each operand's first element; a failure
 * returns undef with its reason in why (which the caller prints at the
 * operator), and vector*matrix also prints its own reason first, without a
 * place, as its multvecmat does. */

static scad_value number_at(const scad_vec *v, int i, int *ok)
{
    if (v->v[i].kind != SV_NUM) *ok = 0;
    return v->v[i];
}

/* The elements of a row, or none when it is no vector (toVector). */
static const scad_vec *row_of(scad_value v)
{
    static const scad_vec empty = {0, 0};
    return v.kind == SV_VEC ? v.u.vec : &empty;
}

static scad_value vec_times_mat(scad_eval *ev, const scad_vec *v, const scad_vec *m, char *why,
                                size_t n)
{
    int cols = row_of(m->v[0])->n;
    scad_value r = scad_vec_new(cols);
    if (r.kind != SV_VEC) return r;
    for (int i = 0; i < cols; i++) {
        double s = 0;
        for (int j = 0; j < v->n; j++) {
            if (m->v[j].kind != SV_VEC || m->v[j].u.vec->n != cols)
                snprintf(why, n, "Matrix must be rectangular. Problem at row %d", j);
            else if (v->v[j].kind != SV_NUM)
                snprintf(why, n, "Vector must contain only numbers. Problem at index %d", j);
            else if (m->v[j].u.vec->v[i].kind != SV_NUM)
                snprintf(why, n, "Matrix must contain only numbers. Problem at row %d, col %d", j,
                         i);
            if (why[0]) {
                char line[300];
                snprintf(line, sizeof line, "WARNING: %s", why);
                scad_diag_line(ev->d, RAYSCAD_MSG_WARNING, line);
                scad_value_drop(r);
                return scad_undef();
            }
            s += v->v[j].u.num * m->v[j].u.vec->v[i].u.num;
        }
        r.u.vec->v[i] = scad_num(s);
    }
    return r;
}

static scad_value vector_product(scad_eval *ev, const scad_vec *A, const scad_vec *B, char *why,
                                 size_t n)
{
    if (A->n == 0 || B->n == 0) {
        snprintf(why, n, "Multiplication is undefined on empty vectors");
        return scad_undef();
    }
    scad_vkind t1 = A->v[0].kind, t2 = B->v[0].kind;
    if (t1 == SV_NUM && t2 == SV_NUM) {
        if (A->n != B->n) {
            snprintf(why, n, "vector*vector requires matching lengths (%d != %d)", A->n, B->n);
            return scad_undef();
        }
        double s = 0;
        for (int i = 0; i < A->n; i++) {
            int ok = 1;
            scad_value x = number_at(A, i, &ok), y = number_at(B, i, &ok);
            if (!ok) {
                snprintf(why, n, "undefined operation (%s * %s)", scad_value_type_name(x),
                         scad_value_type_name(y));
                return scad_undef();
            }
            s += x.u.num * y.u.num;
        }
        return scad_num(s);
    }
    if (t1 == SV_NUM && t2 == SV_VEC) {
        if (A->n != B->n) {
            snprintf(why, n,
                     "vector*matrix requires vector length to match matrix row count (%d != %d)",
                     A->n, B->n);
            return scad_undef();
        }
        return vec_times_mat(ev, A, B, why, n);
    }
    if (t1 == SV_VEC && t2 == SV_NUM) {
        int cols = A->v[0].u.vec->n;
        if (cols != B->n) {
            snprintf(why, n,
                     "matrix*vector requires matrix column count to match vector length (%d != %d)",
                     cols, B->n);
            return scad_undef();
        }
        scad_value r = scad_vec_new(A->n);
        if (r.kind != SV_VEC) return r;
        for (int i = 0; i < A->n; i++) {
            if (A->v[i].kind != SV_VEC || A->v[i].u.vec->n != B->n) {
                snprintf(why, n, "Matrix must be rectangular. Problem at row %d", i);
            } else {
                double s = 0;
                for (int j = 0; j < B->n && !why[0]; j++) {
                    if (A->v[i].u.vec->v[j].kind != SV_NUM)
                        snprintf(why, n,
                                 "Matrix must contain only numbers. Problem at row %d, col %d", i,
                                 j);
                    else if (B->v[j].kind != SV_NUM)
                        snprintf(why, n, "Vector must contain only numbers. Problem at index %d",
                                 j);
                    else
                        s += A->v[i].u.vec->v[j].u.num * B->v[j].u.num;
                }
                r.u.vec->v[i] = scad_num(s);
            }
            if (why[0]) {
                scad_value_drop(r);
                return scad_undef();
            }
        }
        return r;
    }
    if (t1 == SV_VEC && t2 == SV_VEC) {
        int cols = A->v[0].u.vec->n;
        if (cols != B->n) {
            snprintf(why, n,
                     "matrix*matrix requires left operand column count to match right operand row "
                     "count (%d != %d)",
                     cols, B->n);
            return scad_undef();
        }
        scad_value r = scad_vec_new(A->n);
        if (r.kind != SV_VEC) return r;
        for (int i = 0; i < A->n; i++) {
            const scad_vec *row = row_of(A->v[i]);
            if (row->n != B->n) {
                snprintf(why, n,
                         "matrix*matrix left operand row length does not match right operand row "
                         "count (%d != %d) at row %d",
                         row->n, B->n, i);
                scad_value_drop(r);
                return scad_undef();
            }
            scad_value t = vec_times_mat(ev, row, B, why, n);
            if (why[0]) {
                size_t k = strlen(why);
                snprintf(why + k, n - k, "\n\twhile processing left operand at row %d", i);
                scad_value_drop(r);
                return scad_undef();
            }
            r.u.vec->v[i] = t;
        }
        return r;
    }
    snprintf(why, n,
             "undefined vector*vector multiplication where first elements are types %s and %s",
             scad_value_type_name(A->v[0]), scad_value_type_name(B->v[0]));
    return scad_undef();
}

static scad_value multiply(scad_eval *ev, scad_loc loc, scad_value a, scad_value b, int *defined)
{
    if (!(a.kind == SV_VEC && b.kind == SV_VEC)) return arith('*', a, b, defined);
    *defined = 1;
    char why[300] = "";
    scad_value r = vector_product(ev, a.u.vec, b.u.vec, why, sizeof why);
    if (why[0]) scad_diag_warning(ev->d, loc, "%s", why);
    return r;
}

static scad_value binary(scad_eval *ev, const scad_expr *e, scad_value a, scad_value b)
{
    int op = e->op, defined = 1;
    char one[2];
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
        scad_diag_warning(ev->d, e->loc,
                          /* 2021.01 words it so for ordering two undefs or functions */
                          a.kind == b.kind && (a.kind == SV_FUNC || a.kind == SV_UNDEF) &&
                                  (op == '<' || op == '>' || op == TK_LE || op == TK_GE)
                              ? "operation undefined (%s %s %s)"
                              : "undefined operation (%s %s %s)",
                          scad_value_type_name(a), scad_op_text(op, one), scad_value_type_name(b));
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

void scad_vlist_push(scad_eval *ev, scad_vlist *l, scad_value v, scad_loc loc)
{
    if (scad_eval_step(ev, loc)) {
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

scad_value scad_vlist_take(scad_vlist *l)
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

void scad_vlist_free(scad_vlist *l)
{
    for (int i = 0; i < l->n; i++)
        scad_value_drop(l->v[i]);
    free(l->v);
}

/* ---- iteration (for, each) --------------------------------------------------- */

/* Expands v into the list of values a for loop visits.  Returns the count,
 * or -1 when refused (warned).  Borrowed items are referenced into out. */
int scad_iter_values(scad_eval *ev, scad_value v, scad_loc loc, scad_vlist *out)
{
    switch (v.kind) {
    case SV_UNDEF:
        return 0;
    case SV_RANGE: {
        double n = scad_range_steps(v.u.range);
        if (n >= MAX_LOOP_ELEMENTS) { /* 2021.01 refuses a million already */
            scad_diag_warning(ev->d, loc,
                              "Bad range parameter in for statement: too many elements (%.0f)", n);
            return -1;
        }
        /* a zero step ends at once, even [0:0:0] (2021.01's iterator) */
        for (int i = 0; v.u.range->step != 0 && i < (int)n && !ev->aborted; i++)
            scad_vlist_push(ev, out, scad_num(scad_range_at(v.u.range, i)), loc);
        return out->n;
    }
    case SV_VEC:
        for (int i = 0; i < v.u.vec->n && !ev->aborted; i++)
            scad_vlist_push(ev, out, scad_value_ref(v.u.vec->v[i]), loc);
        return out->n;
    case SV_STR: {
        const char *s = v.u.str->s;
        size_t i = 0;
        while (i < v.u.str->len && !ev->aborted) {
            size_t k = scad_utf8_char_len(s, i, v.u.str->len);
            scad_vlist_push(ev, out, scad_str_new(s + i, k), loc);
            i += k;
        }
        return out->n;
    }
    default:
        scad_vlist_push(ev, out, scad_value_ref(v), loc);
        return 1;
    }
}

/* ---- expressions -------------------------------------------------------------- */

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
        size_t pos = 0;
        for (size_t c = 0; c < (size_t)k; c++)
            pos += scad_utf8_char_len(s, pos, v.u.str->len);
        return scad_str_new(s + pos, scad_utf8_char_len(s, pos, v.u.str->len));
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
void scad_assign_seq(scad_eval *ev, scad_env *env, const scad_args *args)
{
    for (int i = 0; i < args->n && !ev->aborted; i++) {
        scad_value v = scad_eval_expr(ev, env, args->v[i].value);
        if (args->v[i].name)
            scad_env_set(env, args->v[i].name, v);
        else
            scad_value_drop(v);
    }
}

void scad_echo_line(scad_eval *ev, const scad_argv *a)
{
    scad_buf b = {0};
    scad_buf_puts(&b, "ECHO: ");
    for (int i = 0; i < a->n; i++) {
        if (i) scad_buf_puts(&b, ", ");
        if (a->names[i]) scad_buf_printf(&b, "%s = ", a->names[i]);
        scad_value_format(&b, a->v[i], 1);
    }
    if (b.too_deep)
        scad_eval_error(ev, scad_eval_here(ev), "a vector nested %d deep cannot be printed (echo)",
                        SCAD_MAX_NESTING);
    else
        scad_diag_line(ev->d, RAYSCAD_MSG_ECHO, scad_buf_str(&b));
    scad_buf_free(&b);
}

/* assert(condition, message): 0 when it holds, else reports and aborts. */
int scad_check_assert(scad_eval *ev, scad_env *env, const scad_args *args, scad_loc loc)
{
    scad_argv a;
    if (scad_args_eval(ev, env, args, &a)) return -1;
    /* without one, OpenSCAD 2021.01 looks a variable 'condition' up in the
     * caller's scope (warning when there is none) */
    scad_value c = scad_argv_given(&a, "condition", 0)
                       ? scad_argv_get(&a, "condition", 0)
                       : scad_env_lookup_cstr(ev, env, "condition", loc, 0, NULL);
    int ok = scad_value_truthy(c);
    if (!ok && !ev->aborted) {
        scad_buf b = {0};
        const scad_expr *ce = NULL;
        for (int i = 0; i < args->n; i++)
            if (!args->v[i].name || strcmp(args->v[i].name, "condition") == 0) {
                ce = args->v[i].value;
                break;
            }
        if (ce) {
            scad_buf_puts(&b, "Assertion '");
            scad_expr_format(&b, ce);
            scad_buf_puts(&b, "' failed");
        } else {
            scad_buf_puts(&b, "Assertion failed");
        }
        if (scad_argv_given(&a, "message", 1)) {
            scad_buf_puts(&b, ": ");
            scad_value_format(&b, scad_argv_get(&a, "message", 1), 1);
        }
        scad_eval_error(ev, loc, "%s", scad_buf_str(&b));
        scad_buf_free(&b);
    }
    scad_argv_free(&a);
    return ok ? 0 : -1;
}

/* OpenSCAD's Expression::isLiteral: constants, unary operators on them, and
 * vectors and ranges of them. */
int scad_expr_is_literal(const scad_expr *e)
{
    switch (e->kind) {
    case EX_NUMBER:
    case EX_STRING:
    case EX_BOOL:
    case EX_UNDEF:
        return 1;
    case EX_UNARY:
        return scad_expr_is_literal(e->a[0]);
    case EX_VECTOR:
        for (int i = 0; i < e->n; i++)
            if (!scad_expr_is_literal(e->list[i])) return 0;
        return 1;
    case EX_RANGE:
        return scad_expr_is_literal(e->a[0]) && (!e->a[1] || scad_expr_is_literal(e->a[1])) &&
               scad_expr_is_literal(e->a[2]);
    default:
        return 0;
    }
}

static void lc_eval(scad_eval *ev, scad_env *env, const scad_expr *e, scad_vlist *out);

/* for (a = …, b = …) in a comprehension: nested, each level evaluated in
 * the environment of the levels outside it. */
static void lc_for(scad_eval *ev, scad_env *env, const scad_expr *e, int k, scad_vlist *out)
{
    if (ev->aborted) return;
    if (k == e->args.n) {
        lc_eval(ev, env, e->a[0], out);
        return;
    }
    const scad_arg *arg = &e->args.v[k];
    scad_value src = scad_eval_expr(ev, env, arg->value);
    scad_vlist items = {0};
    if (scad_iter_values(ev, src, arg->loc, &items) > 0) {
        for (int i = 0; i < items.n && !ev->aborted; i++) {
            scad_env *ie = scad_env_new(ev, env, env, NULL);
            if (!ie) break;
            if (arg->name) scad_env_set(ie, arg->name, scad_value_ref(items.v[i]));
            lc_for(ev, ie, e, k + 1, out);
            scad_env_free(ie);
        }
    }
    scad_vlist_free(&items);
    scad_value_drop(src);
}

static void push_each(scad_eval *ev, scad_value v, scad_loc loc, scad_vlist *out)
{
    if (v.kind == SV_VEC || v.kind == SV_RANGE || v.kind == SV_STR) {
        scad_vlist items = {0};
        if (scad_iter_values(ev, v, loc, &items) > 0)
            for (int i = 0; i < items.n; i++)
                scad_vlist_push(ev, out, scad_value_ref(items.v[i]), loc);
        scad_vlist_free(&items);
        scad_value_drop(v);
    } else {
        scad_vlist_push(ev, out, v, loc);
    }
}

static void lc_eval(scad_eval *ev, scad_env *env, const scad_expr *e, scad_vlist *out)
{
    if (ev->aborted) return;
    switch (e->kind) {
    case LC_FOR:
        lc_for(ev, env, e, 0, out);
        break;
    case LC_CFOR: {
        scad_env *ie = scad_env_new(ev, env, env, NULL);
        if (!ie) return;
        scad_assign_seq(ev, ie, &e->args);
        long iterations = 0;
        for (;;) {
            scad_value c = scad_eval_expr(ev, ie, e->a[1]);
            int go = scad_value_truthy(c);
            scad_value_drop(c);
            if (!go || ev->aborted) break;
            if (++iterations > MAX_LOOP_ELEMENTS) {
                scad_eval_error_worded(ev, e->loc, "For loop counter exceeded limit",
                                       "for loop counter exceeded the limit of %d iterations",
                                       MAX_LOOP_ELEMENTS);
                break;
            }
            lc_eval(ev, ie, e->a[0], out);
            /* the updates run in order in a new environment, each seeing
             * the ones before it (OpenSCAD's sequential assignment) */
            scad_env *ne = scad_env_new(ev, env, env, NULL);
            if (!ne) break;
            for (int i = 0; i < ie->nvars; i++)
                scad_env_set(ne, ie->vars[i].name, scad_value_ref(ie->vars[i].v));
            for (int i = 0; i < e->args2.n && !ev->aborted; i++) {
                scad_value v = scad_eval_expr(ev, ne, e->args2.v[i].value);
                if (e->args2.v[i].name)
                    scad_env_set(ne, e->args2.v[i].name, v);
                else
                    scad_value_drop(v);
            }
            scad_env_free(ie);
            ie = ne;
        }
        scad_env_free(ie);
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
        scad_env *le = scad_env_new(ev, env, env, NULL);
        if (!le) return;
        scad_assign_seq(ev, le, &e->args);
        lc_eval(ev, le, e->a[0], out);
        scad_env_free(le);
        break;
    }
    case LC_EACH: {
        if (e->a[0]->kind >= LC_FOR) {
            scad_vlist inner = {0};
            lc_eval(ev, env, e->a[0], &inner);
            for (int i = 0; i < inner.n; i++) {
                push_each(ev, inner.v[i], e->loc, out);
                inner.v[i] = scad_undef();
            }
            scad_vlist_free(&inner);
        } else {
            push_each(ev, scad_eval_expr(ev, env, e->a[0]), e->loc, out);
        }
        break;
    }
    default:
        scad_vlist_push(ev, out, scad_eval_expr(ev, env, e), e->loc);
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
        /* OpenSCAD 2021.01's order: begin, then end if begin is a number,
         * then step if both are; the sign warnings only for literal ranges */
        scad_value b = scad_eval_expr(ev, env, e->a[0]);
        scad_value en = b.kind == SV_NUM ? scad_eval_expr(ev, env, e->a[2]) : scad_undef();
        scad_value s = en.kind != SV_NUM ? scad_undef()
                       : e->a[1]         ? scad_eval_expr(ev, env, e->a[1])
                                         : scad_num(1);
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
            } else if (e->a[1] && scad_expr_is_literal(e)) {
                if (ss < 0 && bb < ee)
                    scad_diag_warning(ev->d, e->loc,
                                      "begin is smaller than the end, but step is negative");
                else if (ss > 0 && bb > ee)
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
        scad_vlist l = {0};
        for (int i = 0; i < e->n && !ev->aborted; i++)
            lc_eval(ev, env, e->list[i], &l);
        if (ev->aborted) {
            scad_vlist_free(&l);
            return scad_undef();
        }
        return scad_vlist_take(&l);
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
        return scad_eval_call(ev, env, e);
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
        scad_env *le = scad_env_new(ev, env, env, NULL);
        if (!le) return scad_undef();
        scad_assign_seq(ev, le, &e->args);
        scad_value r = scad_eval_expr(ev, le, e->a[0]);
        scad_env_free(le);
        return r;
    }
    case EX_ASSERT:
        if (scad_check_assert(ev, env, &e->args, e->loc)) return scad_undef();
        return e->a[0] ? scad_eval_expr(ev, env, e->a[0]) : scad_undef();
    case EX_ECHO: {
        scad_argv a;
        if (scad_args_eval(ev, env, &e->args, &a)) return scad_undef();
        if (!ev->aborted) scad_echo_line(ev, &a);
        scad_argv_free(&a);
        return e->a[0] ? scad_eval_expr(ev, env, e->a[0]) : scad_undef();
    }
    case EX_FUNCLIT:
        scad_env_capture(ev, env);
        return scad_func_new(e, env);
    default: {
        /* a comprehension outside [ ]: not produced by the parser */
        scad_vlist l = {0};
        lc_eval(ev, env, e, &l);
        return scad_vlist_take(&l);
    }
    }
}
