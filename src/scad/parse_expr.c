/*
 * parse_expr.c — the expression grammar of the parser (parse.c has the
 * statements): argument lists, and expressions with OpenSCAD 2021.01's
 * precedences (?: < || < && < == != < < <= > >= < + - < * / % < unary + - !
 * < ^ < call, index, member), list comprehensions, function literals, let,
 * assert and echo.  Nesting is bounded by MAX_DEPTH.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parse.h"

static scad_expr *new_expr(parser *P, scad_expr_kind kind, scad_loc loc)
{
    scad_expr *e = scad_parse_alloc(P, sizeof *e);
    if (e) {
        e->kind = kind;
        e->loc = loc;
    }
    return e;
}

static scad_expr *vector_element(parser *P);

/* ---- arguments and parameters --------------------------------------------- */

/* '(' already consumed.  Parses `a, b = e, …` up to ')' (consumed).
 * is_def: parameters (names required, defaults optional). */
static int at_close(parser *P, int close)
{
    return is_ch(peek(P), ')') || (close == ';' && is_ch(peek(P), ';'));
}

/* close is ')' or ';' (then ')' also ends the list: for(…;…;…)). */
int scad_parse_args(parser *P, scad_args *out, int is_def, int close)
{
    int cap = 0;
    out->v = NULL;
    out->n = 0;
    while (is_def && is_ch(peek(P), ',')) /* f(,a) */
        next(P);
    while (!at_close(P, close)) {
        scad_arg arg = {NULL, NULL, peek(P)->loc};
        if (peek(P)->kind == TK_ID && is_ch(peek2(P), '=')) {
            arg.name = next(P)->text;
            next(P);
            arg.value = scad_parse_expr(P);
            if (!arg.value) return 0;
        } else if (is_def) {
            if (peek(P)->kind != TK_ID) {
                scad_parse_syntax_error(P, "a parameter name");
                return 0;
            }
            arg.name = next(P)->text;
        } else {
            arg.value = scad_parse_expr(P);
            if (!arg.value) return 0;
        }
        out->v = scad_parse_grow(P, out->v, out->n, &cap, sizeof *out->v);
        if (!out->v) return 0;
        out->v[out->n++] = arg;
        if (is_ch(peek(P), ',')) {
            while (is_ch(peek(P), ','))
                next(P); /* optional_commas */
            /* 2021.01's grammar: parameter lists may end in commas, calls
             * (and let, echo, assert, for) may not */
            if (!is_def && at_close(P, close)) {
                scad_parse_syntax_error(P, "an argument");
                return 0;
            }
            continue;
        }
        if (!at_close(P, close)) {
            scad_parse_syntax_error(P, close == ')' ? "',' or ')'" : "',', ';' or ')'");
            return 0;
        }
    }
    next(P);
    return 1;
}

/* ---- expressions ------------------------------------------------------------ */

static scad_expr *binary(parser *P, int op, scad_loc loc, scad_expr *l, scad_expr *r)
{
    FAIL_IF(!l || !r);
    scad_expr *e = new_expr(P, EX_BINARY, loc);
    FAIL_IF(!e);
    e->op = op;
    e->a[0] = l;
    e->a[1] = r;
    return e;
}

static scad_expr *primary(parser *P)
{
    scad_token *t = peek(P);
    scad_expr *e;
    switch (t->kind) {
    case TK_NUMBER:
        next(P);
        e = new_expr(P, EX_NUMBER, t->loc);
        if (e) e->num = t->num;
        return e;
    case TK_STRING:
        next(P);
        e = new_expr(P, EX_STRING, t->loc);
        if (e) {
            e->str = t->text;
            e->len = t->len;
        }
        return e;
    case TK_TRUE:
    case TK_FALSE:
        next(P);
        e = new_expr(P, EX_BOOL, t->loc);
        if (e) e->num = t->kind == TK_TRUE;
        return e;
    case TK_UNDEF:
        next(P);
        return new_expr(P, EX_UNDEF, t->loc);
    case TK_ID:
        next(P);
        e = new_expr(P, EX_VAR, t->loc);
        if (e) e->str = t->text;
        return e;
    default:
        break;
    }
    if (is_ch(t, '(')) {
        next(P);
        e = scad_parse_expr(P);
        FAIL_IF(!e);
        FAIL_IF(!scad_parse_expect(P, ')', "')'"));
        return e;
    }
    if (is_ch(t, '[')) {
        next(P);
        scad_loc loc = t->loc;
        if (is_ch(peek(P), ']')) {
            next(P);
            return new_expr(P, EX_VECTOR, loc);
        }
        scad_expr *first = vector_element(P);
        FAIL_IF(!first);
        if (is_ch(peek(P), ':') && first->kind < LC_FOR) {
            next(P);
            scad_expr *second = scad_parse_expr(P);
            FAIL_IF(!second);
            e = new_expr(P, EX_RANGE, loc);
            FAIL_IF(!e);
            e->a[0] = first;
            if (is_ch(peek(P), ':')) {
                next(P);
                e->a[1] = second;
                e->a[2] = scad_parse_expr(P);
                FAIL_IF(!e->a[2]);
            } else {
                e->a[2] = second;
            }
            FAIL_IF(!scad_parse_expect(P, ']', "']'"));
            return e;
        }
        e = new_expr(P, EX_VECTOR, loc);
        FAIL_IF(!e);
        int cap = 0;
        e->list = scad_parse_grow(P, NULL, 0, &cap, sizeof *e->list);
        FAIL_IF(!e->list);
        e->list[e->n++] = first;
        for (;;) {
            if (is_ch(peek(P), ']')) {
                next(P);
                return e;
            }
            FAIL_IF(!scad_parse_expect(P, ',', "',' or ']'"));
            while (is_ch(peek(P), ','))
                next(P);
            if (is_ch(peek(P), ']')) continue;
            scad_expr *el = vector_element(P);
            FAIL_IF(!el);
            e->list = scad_parse_grow(P, e->list, e->n, &cap, sizeof *e->list);
            FAIL_IF(!e->list);
            e->list[e->n++] = el;
        }
    }
    scad_parse_syntax_error(P, "an expression");
    return NULL;
}

static scad_expr *postfix(parser *P)
{
    scad_expr *e = primary(P);
    for (;;) {
        FAIL_IF(!e);
        scad_token *t = peek(P);
        if (is_ch(t, '(')) {
            next(P);
            scad_expr *c = new_expr(P, EX_CALL, e->loc);
            FAIL_IF(!c);
            c->a[0] = e;
            FAIL_IF(!scad_parse_args(P, &c->args, 0, ')'));
            e = c;
        } else if (is_ch(t, '[')) {
            next(P);
            scad_expr *c = new_expr(P, EX_INDEX, e->loc);
            FAIL_IF(!c);
            c->a[0] = e;
            c->a[1] = scad_parse_expr(P);
            FAIL_IF(!c->a[1]);
            FAIL_IF(!scad_parse_expect(P, ']', "']'"));
            e = c;
        } else if (is_ch(t, '.')) {
            next(P);
            if (peek(P)->kind != TK_ID) {
                scad_parse_syntax_error(P, "a member name");
                return NULL;
            }
            scad_expr *c = new_expr(P, EX_MEMBER, e->loc);
            FAIL_IF(!c);
            c->a[0] = e;
            c->str = next(P)->text;
            e = c;
        } else {
            return e;
        }
    }
}

static scad_expr *unary(parser *P);

static scad_expr *power(parser *P)
{
    scad_expr *l = postfix(P);
    FAIL_IF(!l);
    if (is_ch(peek(P), '^')) {
        scad_loc loc = next(P)->loc;
        return binary(P, '^', loc, l, unary(P));
    }
    return l;
}

static scad_expr *unary(parser *P)
{
    scad_token *t = peek(P);
    if (is_ch(t, '-') || is_ch(t, '+') || is_ch(t, '!')) {
        next(P);
        if (++P->depth > MAX_DEPTH) {
            scad_diag_error(P->d, t->loc, "expression nested deeper than %d levels", MAX_DEPTH);
            P->errors = MAX_ERRORS;
            return NULL;
        }
        scad_expr *operand = unary(P);
        P->depth--;
        FAIL_IF(!operand);
        scad_expr *e = new_expr(P, EX_UNARY, t->loc);
        FAIL_IF(!e);
        e->op = t->ch;
        e->a[0] = operand;
        return e;
    }
    return power(P);
}

/* How tightly a binary operator binds (OpenSCAD 2021.01's parser.y, all
 * left associative): || 1, && 2, == != 3, < > <= >= 4, + - 5, * / % 6;
 * 0 when t is not a binary operator.  *op gets the operator as binary()
 * takes it: the character, or the token kind. */
static int binary_priority(const scad_token *t, int *op)
{
    static const struct {
        scad_tok_kind kind;
        int ch, priority;
    } ops[] = {
        {TK_OR, 0, 1},     {TK_AND, 0, 2},    {TK_EQ, 0, 3},     {TK_NE, 0, 3},
        {TK_CHAR, '<', 4}, {TK_CHAR, '>', 4}, {TK_LE, 0, 4},     {TK_GE, 0, 4},
        {TK_CHAR, '+', 5}, {TK_CHAR, '-', 5}, {TK_CHAR, '*', 6}, {TK_CHAR, '/', 6},
        {TK_CHAR, '%', 6},
    };
    for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++)
        if (t->kind == ops[i].kind && (t->kind != TK_CHAR || t->ch == ops[i].ch)) {
            *op = t->kind == TK_CHAR ? t->ch : (int)t->kind;
            return ops[i].priority;
        }
    *op = 0;
    return 0;
}

/* The binary operators that bind tighter than `limit`, over unary operands:
 * precedence climbing, as Lua's subexpr.  A right operand takes only
 * operators tighter than its own, so equal ones group to the left; a chain
 * of equal operators is this loop, not recursion. */
static scad_expr *binary_chain(parser *P, int limit)
{
    scad_expr *l = unary(P);
    for (;;) {
        int op, priority = binary_priority(peek(P), &op);
        if (!l || priority <= limit) return l;
        scad_token *t = next(P);
        l = binary(P, op, t->loc, l, binary_chain(P, priority));
    }
}

/* let/assert/echo(args) expr, and function(params) expr. */
static scad_expr *prefixed(parser *P, scad_expr_kind kind, int body_optional)
{
    scad_token *t = next(P);
    scad_expr *e = new_expr(P, kind, t->loc);
    FAIL_IF(!e);
    FAIL_IF(!scad_parse_expect(P, '(', "'('"));
    FAIL_IF(!scad_parse_args(P, &e->args, kind == EX_FUNCLIT, ')'));
    if (body_optional) {
        scad_token *n = peek(P);
        if (is_ch(n, ';') || is_ch(n, ')') || is_ch(n, ']') || is_ch(n, ',') || is_ch(n, ':') ||
            n->kind == TK_EOF)
            return e;
    }
    e->a[0] = scad_parse_expr(P);
    FAIL_IF(!e->a[0]);
    return e;
}

scad_expr *scad_parse_expr(parser *P)
{
    if (++P->depth > MAX_DEPTH) {
        scad_diag_error(P->d, peek(P)->loc, "expression nested deeper than %d levels", MAX_DEPTH);
        P->errors = MAX_ERRORS;
        return NULL;
    }
    scad_expr *e;
    scad_token *t = peek(P);
    if (t->kind == TK_FUNCTION) {
        e = prefixed(P, EX_FUNCLIT, 0);
    } else if (t->kind == TK_LET) {
        e = prefixed(P, EX_LET, 0);
    } else if (t->kind == TK_ASSERT) {
        e = prefixed(P, EX_ASSERT, 1);
    } else if (t->kind == TK_ECHO) {
        e = prefixed(P, EX_ECHO, 1);
    } else {
        e = binary_chain(P, 0);
        if (e && is_ch(peek(P), '?')) {
            scad_token *q = next(P);
            scad_expr *c = new_expr(P, EX_TERNARY, q->loc);
            if (!c) return NULL;
            c->a[0] = e;
            c->a[1] = scad_parse_expr(P);
            if (!c->a[1] || !scad_parse_expect(P, ':', "':'")) return NULL;
            c->a[2] = scad_parse_expr(P);
            e = c->a[2] ? c : NULL;
        }
    }
    P->depth--;
    return e;
}

/* One element of a vector: an expression or a list comprehension. */
static scad_expr *lc_element(parser *P, int parens_ok);

/* A vector's own elements may not be a parenthesised comprehension (only
 * the bodies of for/if/let/each may), as in OpenSCAD 2021.01's grammar. */
static scad_expr *vector_element(parser *P)
{
    return lc_element(P, 0);
}

static scad_expr *lc_element(parser *P, int parens_ok)
{
    scad_token *t = peek(P);
    if (++P->depth > MAX_DEPTH) {
        scad_diag_error(P->d, t->loc, "expression nested deeper than %d levels", MAX_DEPTH);
        P->errors = MAX_ERRORS;
        return NULL;
    }
    scad_expr *e = NULL;
    if (t->kind == TK_EACH) {
        next(P);
        e = new_expr(P, LC_EACH, t->loc);
        if (e && !(e->a[0] = lc_element(P, 1))) e = NULL;
    } else if (t->kind == TK_FOR) {
        next(P);
        e = new_expr(P, LC_FOR, t->loc);
        if (e && scad_parse_expect(P, '(', "'('")) {
            /* for (init; cond; update) or for (args) */
            scad_args init;
            if (!scad_parse_args(P, &init, 0, ';')) {
                e = NULL;
            } else {
                e->args = init;
                if (is_ch(&P->t[P->pos - 1], ';')) {
                    e->kind = LC_CFOR;
                    e->a[1] = scad_parse_expr(P);
                    if (!e->a[1] || !scad_parse_expect(P, ';', "';'") ||
                        !scad_parse_args(P, &e->args2, 0, ')'))
                        e = NULL;
                }
                if (e && !(e->a[0] = lc_element(P, 1))) e = NULL;
            }
        } else {
            e = NULL;
        }
    } else if (t->kind == TK_IF) {
        next(P);
        e = new_expr(P, LC_IF, t->loc);
        if (e && scad_parse_expect(P, '(', "'('") && (e->a[1] = scad_parse_expr(P)) &&
            scad_parse_expect(P, ')', "')'") && (e->a[0] = lc_element(P, 1))) {
            if (peek(P)->kind == TK_ELSE) {
                next(P);
                if (!(e->a[2] = lc_element(P, 1))) e = NULL;
            }
        } else {
            e = NULL;
        }
    } else if (t->kind == TK_LET) {
        /* let(…) followed by a comprehension is LC_LET, else an expression */
        next(P);
        e = new_expr(P, LC_LET, t->loc);
        if (e && scad_parse_expect(P, '(', "'('") && scad_parse_args(P, &e->args, 0, ')') &&
            (e->a[0] = lc_element(P, 1))) {
            if (e->a[0]->kind < LC_FOR) e->kind = EX_LET;
        } else {
            e = NULL;
        }
    } else if (parens_ok && is_ch(t, '(') &&
               (peek2(P)->kind == TK_FOR || peek2(P)->kind == TK_EACH || peek2(P)->kind == TK_IF)) {
        next(P);
        e = lc_element(P, 1);
        if (e && !scad_parse_expect(P, ')', "')'")) e = NULL;
    } else {
        e = scad_parse_expr(P);
    }
    P->depth--;
    return e;
}
