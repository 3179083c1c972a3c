/*
 * parse.c — recursive-descent parser for the OpenSCAD grammar (parser.y of
 * OpenSCAD 2021.01, with the same precedences: ?: < || < && < == != <
 * < <= > >= < + - < * / % < unary + - ! < ^ < call, index, member).
 *
 * The tokens and every node live in the parse's arena.  Statements are added
 * to the scope being parsed; a bare { } block adds to the enclosing scope, as
 * in OpenSCAD.  After a syntax error the parser skips to the next ';' or '}'
 * at the level where it failed and goes on, so that every error is reported;
 * the scope is then discarded.  Nesting is bounded (MAX_DEPTH) so that a
 * hostile file cannot overflow the C stack.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ast.h"

enum { MAX_DEPTH = 2000, MAX_ERRORS = 50 };

typedef struct parser {
    scad_arena *a;
    scad_diag *d;
    scad_token *t;
    int pos, ntok;
    int depth;
    int errors;
    int oom;
    int include_depth;
    struct shared *shared; /* one for a parse and its includes and uses */
} parser;

/* What a parse shares with the parses of the files it includes and uses:
 * the names, the files already `use`d (each is parsed once, and a cycle of
 * uses ends), and the scopes that define functions or modules, indexed by
 * name when the whole parse is done. */
typedef struct shared {
    scad_names *names;
    const scad_options *opt; /* the file services */
    const char **path;
    scad_scope **scope;
    int n, cap;
    scad_scope **defining;
    int ndefining, capdefining;
} shared;

/* Raised by a failing rule: the whole statement is abandoned. */
#define FAIL_IF(cond)                                                                              \
    do {                                                                                           \
        if (cond) return NULL;                                                                     \
    } while (0)

static scad_token *peek(parser *P)
{
    return &P->t[P->pos];
}
static scad_token *peek2(parser *P)
{
    return &P->t[P->pos + 1 < P->ntok ? P->pos + 1 : P->pos];
}
static scad_token *next(parser *P)
{
    scad_token *t = &P->t[P->pos];
    if (P->pos < P->ntok - 1) P->pos++;
    return t;
}
static int is_ch(const scad_token *t, int c)
{
    return t->kind == TK_CHAR && t->ch == c;
}

static const char *describe(const scad_token *t, char *buf, size_t n)
{
    switch (t->kind) {
    case TK_EOF:
        return "end of file";
    case TK_NUMBER:
        return "number";
    case TK_STRING:
        return "string";
    case TK_CHAR:
        snprintf(buf, n, "'%c'", t->ch);
        return buf;
    case TK_LE:
        return "'<='";
    case TK_GE:
        return "'>='";
    case TK_EQ:
        return "'=='";
    case TK_NE:
        return "'!='";
    case TK_AND:
        return "'&&'";
    case TK_OR:
        return "'||'";
    default:
        snprintf(buf, n, "'%s'", t->text ? t->text : "?");
        return buf;
    }
}

static void syntax_error(parser *P, const char *want)
{
    char buf[64];
    scad_token *t = peek(P);
    /* openscad parses the text with a newline appended: its end of file
     * is one line further down */
    scad_loc at = t->loc;
    if (t->kind == TK_EOF) at.line++;
    scad_diag_syntax(P->d, at);
    if (P->errors < MAX_ERRORS)
        scad_diag_error(P->d, t->loc, "syntax error: expected %s before %s", want,
                        describe(t, buf, sizeof buf));
    P->errors++;
}

static int expect(parser *P, int c, const char *want)
{
    if (is_ch(peek(P), c)) {
        next(P);
        return 1;
    }
    syntax_error(P, want);
    return 0;
}

static void *alloc(parser *P, size_t n)
{
    void *p = scad_arena_alloc(P->a, n);
    if (!p) P->oom = 1;
    return p;
}

/* Grow an arena array of elem-size items by doubling. */
static void *grow(parser *P, void *v, int n, int *cap, size_t elem)
{
    if (n < *cap) return v;
    int c = *cap ? *cap * 2 : 4;
    void *nv = alloc(P, elem * (size_t)c);
    if (!nv) return NULL;
    if (n) memcpy(nv, v, elem * (size_t)n);
    *cap = c;
    return nv;
}

static scad_expr *new_expr(parser *P, scad_expr_kind kind, scad_loc loc)
{
    scad_expr *e = alloc(P, sizeof *e);
    if (e) {
        e->kind = kind;
        e->loc = loc;
    }
    return e;
}

static scad_expr *expr(parser *P);
static scad_expr *vector_element(parser *P);

/* ---- arguments and parameters --------------------------------------------- */

/* '(' already consumed.  Parses `a, b = e, …` up to ')' (consumed).
 * is_def: parameters (names required, defaults optional). */
static int at_close(parser *P, int close)
{
    return is_ch(peek(P), ')') || (close == ';' && is_ch(peek(P), ';'));
}

/* close is ')' or ';' (then ')' also ends the list: for(…;…;…)). */
static int arg_list(parser *P, scad_args *out, int is_def, int close)
{
    int cap = 0;
    out->v = NULL;
    out->n = 0;
    while (!at_close(P, close)) {
        scad_arg arg = {NULL, NULL, peek(P)->loc};
        if (peek(P)->kind == TK_ID && is_ch(peek2(P), '=')) {
            arg.name = next(P)->text;
            next(P);
            arg.value = expr(P);
            if (!arg.value) return 0;
        } else if (is_def) {
            if (peek(P)->kind != TK_ID) {
                syntax_error(P, "a parameter name");
                return 0;
            }
            arg.name = next(P)->text;
        } else {
            arg.value = expr(P);
            if (!arg.value) return 0;
        }
        out->v = grow(P, out->v, out->n, &cap, sizeof *out->v);
        if (!out->v) return 0;
        out->v[out->n++] = arg;
        if (is_ch(peek(P), ',')) {
            while (is_ch(peek(P), ','))
                next(P); /* optional_commas */
            continue;
        }
        if (!at_close(P, close)) {
            syntax_error(P, close == ')' ? "',' or ')'" : "',', ';' or ')'");
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
        e = expr(P);
        FAIL_IF(!e);
        FAIL_IF(!expect(P, ')', "')'"));
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
            scad_expr *second = expr(P);
            FAIL_IF(!second);
            e = new_expr(P, EX_RANGE, loc);
            FAIL_IF(!e);
            e->a[0] = first;
            if (is_ch(peek(P), ':')) {
                next(P);
                e->a[1] = second;
                e->a[2] = expr(P);
                FAIL_IF(!e->a[2]);
            } else {
                e->a[2] = second;
            }
            FAIL_IF(!expect(P, ']', "']'"));
            return e;
        }
        e = new_expr(P, EX_VECTOR, loc);
        FAIL_IF(!e);
        int cap = 0;
        e->list = grow(P, NULL, 0, &cap, sizeof *e->list);
        FAIL_IF(!e->list);
        e->list[e->n++] = first;
        for (;;) {
            if (is_ch(peek(P), ']')) {
                next(P);
                return e;
            }
            FAIL_IF(!expect(P, ',', "',' or ']'"));
            while (is_ch(peek(P), ','))
                next(P);
            if (is_ch(peek(P), ']')) continue;
            scad_expr *el = vector_element(P);
            FAIL_IF(!el);
            e->list = grow(P, e->list, e->n, &cap, sizeof *e->list);
            FAIL_IF(!e->list);
            e->list[e->n++] = el;
        }
    }
    syntax_error(P, "an expression");
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
            FAIL_IF(!arg_list(P, &c->args, 0, ')'));
            e = c;
        } else if (is_ch(t, '[')) {
            next(P);
            scad_expr *c = new_expr(P, EX_INDEX, e->loc);
            FAIL_IF(!c);
            c->a[0] = e;
            c->a[1] = expr(P);
            FAIL_IF(!c->a[1]);
            FAIL_IF(!expect(P, ']', "']'"));
            e = c;
        } else if (is_ch(t, '.')) {
            next(P);
            if (peek(P)->kind != TK_ID) {
                syntax_error(P, "a member name");
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
    FAIL_IF(!expect(P, '(', "'('"));
    FAIL_IF(!arg_list(P, &e->args, kind == EX_FUNCLIT, ')'));
    if (body_optional) {
        scad_token *n = peek(P);
        if (is_ch(n, ';') || is_ch(n, ')') || is_ch(n, ']') || is_ch(n, ',') || is_ch(n, ':') ||
            n->kind == TK_EOF)
            return e;
    }
    e->a[0] = expr(P);
    FAIL_IF(!e->a[0]);
    return e;
}

static scad_expr *expr(parser *P)
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
            c->a[1] = expr(P);
            if (!c->a[1] || !expect(P, ':', "':'")) return NULL;
            c->a[2] = expr(P);
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
        if (e && expect(P, '(', "'('")) {
            /* for (init; cond; update) or for (args) */
            scad_args init;
            if (!arg_list(P, &init, 0, ';')) {
                e = NULL;
            } else {
                e->args = init;
                if (is_ch(&P->t[P->pos - 1], ';')) {
                    e->kind = LC_CFOR;
                    e->a[1] = expr(P);
                    if (!e->a[1] || !expect(P, ';', "';'") || !arg_list(P, &e->args2, 0, ')'))
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
        if (e && expect(P, '(', "'('") && (e->a[1] = expr(P)) && expect(P, ')', "')'") &&
            (e->a[0] = lc_element(P, 1))) {
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
        if (e && expect(P, '(', "'('") && arg_list(P, &e->args, 0, ')') &&
            (e->a[0] = lc_element(P, 1))) {
            if (e->a[0]->kind < LC_FOR) e->kind = EX_LET;
        } else {
            e = NULL;
        }
    } else if (parens_ok && is_ch(t, '(') &&
               (peek2(P)->kind == TK_FOR || peek2(P)->kind == TK_EACH || peek2(P)->kind == TK_IF)) {
        next(P);
        e = lc_element(P, 1);
        if (e && !expect(P, ')', "')'")) e = NULL;
    } else {
        e = expr(P);
    }
    P->depth--;
    return e;
}

/* ---- statements ------------------------------------------------------------ */

static scad_scope *new_scope(parser *P)
{
    return alloc(P, sizeof(scad_scope));
}

static int statement(parser *P, scad_scope *s);

static void add_assign(parser *P, scad_scope *s, const char *name, scad_expr *value, scad_loc loc)
{
    for (int i = 0; i < s->nassigns; i++) {
        if (s->assigns[i].name == name) {
            scad_diag_warning(P->d, loc, "%s was assigned on line %d but was overwritten", name,
                              s->assigns[i].loc.line);
            s->assigns[i].value = value;
            return;
        }
    }
    s->assigns = grow(P, s->assigns, s->nassigns, &s->capassigns, sizeof *s->assigns);
    if (!s->assigns) return;
    scad_assign a = {name, value, loc};
    s->assigns[s->nassigns++] = a;
}

static void add_stmt(parser *P, scad_scope *s, scad_stmt *st)
{
    s->stmts = grow(P, s->stmts, s->nstmts, &s->capstmts, sizeof *s->stmts);
    if (s->stmts) s->stmts[s->nstmts++] = st;
}

/* The children of an instantiation: one child statement in a fresh scope. */
static scad_scope *child_scope(parser *P)
{
    scad_scope *c = new_scope(P);
    if (!c || !statement(P, c)) return NULL;
    return c;
}

static scad_stmt *instantiation(parser *P)
{
    scad_token *t = peek(P);
    if (++P->depth > MAX_DEPTH) {
        scad_diag_error(P->d, t->loc, "statements nested deeper than %d levels", MAX_DEPTH);
        P->errors = MAX_ERRORS;
        return NULL;
    }
    scad_stmt *st = NULL;
    if (is_ch(t, '!') || is_ch(t, '#') || is_ch(t, '%') || is_ch(t, '*')) {
        next(P);
        st = instantiation(P);
        if (st) {
            if (t->ch == '!') st->root = 1;
            if (t->ch == '#') st->highlight = 1;
            if (t->ch == '%') st->background = 1;
            if (t->ch == '*') st->disable = 1;
        }
    } else if (t->kind == TK_IF) {
        next(P);
        st = alloc(P, sizeof *st);
        if (st) {
            st->name = t->text;
            st->loc = t->loc;
            if (!expect(P, '(', "'('") || !(st->cond = expr(P)) || !expect(P, ')', "')'") ||
                !(st->children = child_scope(P))) {
                st = NULL;
            } else if (peek(P)->kind == TK_ELSE) {
                next(P);
                if (!(st->else_children = child_scope(P))) st = NULL;
            }
        }
    } else if (t->kind == TK_ID || t->kind == TK_FOR || t->kind == TK_LET || t->kind == TK_ASSERT ||
               t->kind == TK_ECHO || t->kind == TK_EACH) {
        next(P);
        st = alloc(P, sizeof *st);
        if (st) {
            st->name = t->text;
            st->loc = t->loc;
            if (!expect(P, '(', "'('") || !arg_list(P, &st->args, 0, ')') ||
                !(st->children = child_scope(P)))
                st = NULL;
        }
    } else {
        syntax_error(P, "a statement");
    }
    P->depth--;
    return st;
}

/* Note that s defines something, for scad_parse to index it at the end. */
static void defining(parser *P, scad_scope *s)
{
    if (s->nfuncs + s->nmods != 1) return; /* not its first definition */
    shared *sh = P->shared;
    sh->defining = grow(P, sh->defining, sh->ndefining, &sh->capdefining, sizeof *sh->defining);
    if (sh->defining) sh->defining[sh->ndefining++] = s;
}

static int definition(parser *P, scad_scope *s)
{
    scad_token *kw = next(P);
    scad_token *name = peek(P);
    if (name->kind != TK_ID) {
        syntax_error(P, kw->kind == TK_MODULE ? "a module name" : "a function name");
        return 0;
    }
    next(P);
    scad_args params;
    if (!expect(P, '(', "'('") || !arg_list(P, &params, 1, ')')) return 0;
    if (kw->kind == TK_MODULE) {
        scad_moddef *m = alloc(P, sizeof *m);
        scad_scope *body = new_scope(P);
        if (!m || !body) return 0;
        m->name = name->text;
        m->loc = kw->loc;
        m->params = params;
        m->body = body;
        if (!statement(P, body)) return 0;
        s->mods = grow(P, s->mods, s->nmods, &s->capmods, sizeof *s->mods);
        if (s->mods) s->mods[s->nmods++] = m;
        defining(P, s);
        return 1;
    }
    scad_funcdef *f = alloc(P, sizeof *f);
    if (!f || !expect(P, '=', "'='")) return 0;
    f->name = name->text;
    f->loc = kw->loc;
    f->params = params;
    if (!(f->body = expr(P)) || !expect(P, ';', "';'")) return 0;
    s->funcs = grow(P, s->funcs, s->nfuncs, &s->capfuncs, sizeof *s->funcs);
    if (s->funcs) s->funcs[s->nfuncs++] = f;
    defining(P, s);
    return 1;
}

static void include_file(parser *P, scad_scope *s, scad_token *t);
static void use_file(parser *P, scad_scope *s, scad_token *t);
static int parse_into(parser *P, scad_scope *s);

/* Skip to just after the next ';' or before the '}' closing the current
 * block, so that parsing can resume after an error. */
static void recover(parser *P)
{
    int depth = 0;
    for (;;) {
        scad_token *t = peek(P);
        if (t->kind == TK_EOF) return;
        if (is_ch(t, '{') || is_ch(t, '(') || is_ch(t, '[')) depth++;
        if (is_ch(t, ')') || is_ch(t, ']')) depth = depth ? depth - 1 : 0;
        if (is_ch(t, '}')) {
            if (depth == 0) return;
            depth--;
            if (depth == 0) {
                next(P);
                return;
            }
        }
        next(P);
        if (is_ch(t, ';') && depth == 0) return;
    }
}

/* Parses one statement into s.  Returns 0 on a syntax error (reported). */
static int statement(parser *P, scad_scope *s)
{
    scad_token *t = peek(P);
    if (is_ch(t, ';')) {
        next(P);
        return 1;
    }
    if (is_ch(t, '{')) {
        next(P);
        int ok = 1;
        while (!is_ch(peek(P), '}')) {
            if (peek(P)->kind == TK_EOF) {
                syntax_error(P, "'}'");
                return 0;
            }
            if (!statement(P, s)) {
                ok = 0;
                if (P->errors >= MAX_ERRORS || P->oom) return 0;
                recover(P);
            }
        }
        next(P);
        return ok;
    }
    if (t->kind == TK_MODULE || t->kind == TK_FUNCTION) return definition(P, s);
    if (t->kind == TK_INCLUDE) {
        next(P);
        include_file(P, s, t);
        return 1;
    }
    if (t->kind == TK_USE) {
        next(P);
        use_file(P, s, t);
        return 1;
    }
    if (t->kind == TK_ID && is_ch(peek2(P), '=')) {
        next(P);
        next(P);
        scad_expr *e = expr(P);
        if (!e || !expect(P, ';', "';'")) return 0;
        add_assign(P, s, t->text, e, t->loc);
        return 1;
    }
    scad_stmt *st = instantiation(P);
    if (!st) return 0;
    add_stmt(P, s, st);
    return 1;
}

static int parse_into(parser *P, scad_scope *s)
{
    while (peek(P)->kind != TK_EOF) {
        if (!statement(P, s)) {
            if (P->errors >= MAX_ERRORS || P->oom) break;
            recover(P);
            if (is_ch(peek(P), '}')) {
                syntax_error(P, "a statement");
                next(P);
            }
        }
    }
    return P->errors == 0 && !P->oom;
}

enum { MAX_INCLUDE_DEPTH = 64 };

static void use_file(parser *P, scad_scope *s, scad_token *t)
{
    char *path = scad_find_library(P->a, P->shared->opt, t->loc.file, t->text);
    if (!path) {
        char line[600];
        snprintf(line, sizeof line, "WARNING: Can't open library '%.500s'.", t->text);
        scad_diag_line(P->d, RAYSCAD_MSG_WARNING, line);
        return;
    }
    shared *u = P->shared;
    scad_scope *scope = NULL;
    for (int i = 0; i < u->n; i++)
        if (strcmp(u->path[i], path) == 0) scope = u->scope[i];
    if (!scope) {
        if (P->include_depth >= MAX_INCLUDE_DEPTH) {
            scad_diag_error(P->d, t->loc, "includes nested deeper than %d files",
                            MAX_INCLUDE_DEPTH);
            P->errors++;
            return;
        }
        scope = new_scope(P);
        char err[256];
        char *src = scope ? scad_read_file(P->a, P->shared->opt, path, err, sizeof err) : NULL;
        if (!src) {
            P->oom = 1;
            return;
        }
        if (u->n == u->cap) {
            int cap = u->cap ? u->cap * 2 : 8;
            const char **np = alloc(P, sizeof *np * (size_t)cap);
            scad_scope **ns = alloc(P, sizeof *ns * (size_t)cap);
            if (!np || !ns) return;
            if (u->n) {
                memcpy(np, u->path, sizeof *np * (size_t)u->n);
                memcpy(ns, u->scope, sizeof *ns * (size_t)u->n);
            }
            u->path = np;
            u->scope = ns;
            u->cap = cap;
        }
        u->path[u->n] = path;
        u->scope[u->n] = scope;
        u->n++;
        scad_token *toks;
        int n = scad_lex(P->a, P->d, u->names, path, src, &toks);
        if (!toks) {
            P->oom = 1;
            return;
        }
        parser sub = *P;
        sub.t = toks;
        sub.ntok = n;
        sub.pos = 0;
        sub.depth = 0;
        sub.include_depth++;
        parse_into(&sub, scope);
        P->errors = sub.errors;
        P->oom |= sub.oom;
    }
    for (int i = 0; i < s->nuses; i++)
        if (s->uses[i] == scope) return;
    s->uses = grow(P, s->uses, s->nuses, &s->capuses, sizeof *s->uses);
    if (s->uses) s->uses[s->nuses++] = scope;
}

static void include_file(parser *P, scad_scope *s, scad_token *t)
{
    if (P->include_depth >= MAX_INCLUDE_DEPTH) {
        scad_diag_error(P->d, t->loc, "includes nested deeper than %d files", MAX_INCLUDE_DEPTH);
        P->errors++;
        return;
    }
    char *path = scad_find_library(P->a, P->shared->opt, t->loc.file, t->text);
    char err[256];
    char *src = path ? scad_read_file(P->a, P->shared->opt, path, err, sizeof err) : NULL;
    if (!src) {
        char line[600];
        snprintf(line, sizeof line, "WARNING: Can't open include file '%.500s'.", t->text);
        scad_diag_line(P->d, RAYSCAD_MSG_WARNING, line);
        return;
    }
    scad_token *toks;
    int n = scad_lex(P->a, P->d, P->shared->names, path, src, &toks);
    if (!toks) {
        P->oom = 1;
        return;
    }
    parser sub = *P;
    sub.t = toks;
    sub.ntok = n;
    sub.pos = 0;
    sub.include_depth++;
    parse_into(&sub, s);
    P->errors = sub.errors;
    P->oom |= sub.oom;
}

scad_scope *scad_parse(scad_arena *a, scad_diag *d, scad_names *names, const char *file,
                       const char *src)
{
    shared sh = {names, d->opt, NULL, NULL, 0, 0, NULL, 0, 0};
    parser P = {a, d, NULL, 0, 0, 0, 0, 0, 0, &sh};
    int errors_before = d->errors;
    P.ntok = scad_lex(a, d, names, file, src, &P.t);
    if (!P.t) {
        scad_diag_error(d, (scad_loc){file, 1, 1}, "out of memory");
        return NULL;
    }
    scad_scope *s = new_scope(&P);
    if (!s) return NULL;
    parse_into(&P, s);
    for (int i = 0; i < sh.ndefining && !P.oom; i++)
        if (scad_scope_index(a, sh.defining[i]) != 0) P.oom = 1;
    if (P.oom) scad_diag_error(d, (scad_loc){file, 1, 1}, "out of memory");
    if (P.errors || P.oom || d->errors != errors_before) return NULL;
    return s;
}
