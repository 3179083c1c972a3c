/*
 * parse.c — the recursive-descent parser for the OpenSCAD grammar (parser.y
 * of OpenSCAD 2021.01): statements, definitions, include and use, and the
 * token helpers and error reporting both halves share (the expressions are
 * parse_expr.c's).
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
#include <strings.h>

#include "parse.h"

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

void scad_parse_syntax_error(parser *P, const char *want)
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

int scad_parse_expect(parser *P, int c, const char *want)
{
    if (is_ch(peek(P), c)) {
        next(P);
        return 1;
    }
    scad_parse_syntax_error(P, want);
    return 0;
}

void *scad_parse_alloc(parser *P, size_t n)
{
    void *p = scad_arena_alloc(P->a, n);
    if (!p) P->oom = 1;
    return p;
}

/* Grow an arena array of elem-size items by doubling. */
void *scad_parse_grow(parser *P, void *v, int n, int *cap, size_t elem)
{
    if (n < *cap) return v;
    int c = *cap ? *cap * 2 : 4;
    void *nv = scad_parse_alloc(P, elem * (size_t)c);
    if (!nv) return NULL;
    if (n) memcpy(nv, v, elem * (size_t)n);
    *cap = c;
    return nv;
}

/* ---- statements ------------------------------------------------------------ */

static scad_scope *new_scope(parser *P)
{
    return scad_parse_alloc(P, sizeof(scad_scope));
}

static int statement(parser *P, scad_scope *s);

/* An assignment to a name the scope assigns already replaces it, in place;
 * OpenSCAD 2021.01 warns when both are in the main file, when both are in
 * one other file on different lines (not a file included twice), and when
 * an include overrides the main file, never when the main file overrides
 * an include. */
static void add_assign(parser *P, scad_scope *s, const char *name, scad_expr *value, scad_loc loc)
{
    for (int i = 0; i < s->nassigns; i++) {
        if (s->assigns[i].name != name) continue;
        /* files compared as OpenSCAD names them (one file reached by two
         * paths is one) */
        scad_loc was = s->assigns[i].loc;
        char m[1024], w[1024], c[1024];
        const char *main = scad_diag_file_name(P->d, P->shared->main_file, m, sizeof m);
        const char *wf = scad_diag_file_name(P->d, was.file, w, sizeof w);
        const char *cf = scad_diag_file_name(P->d, loc.file, c, sizeof c);
        int was_main = strcmp(wf, main) == 0, same = strcmp(wf, cf) == 0;
        if (was_main && same)
            scad_diag_warning(P->d, loc, "%s was assigned on line %d but was overwritten", name,
                              was.line);
        else if ((same && was.line != loc.line) || was_main)
            scad_diag_warning(P->d, loc, "%s was assigned on line %d of \"%s\" but was overwritten",
                              name, was.line, wf);
        s->assigns[i].value = value;
        s->assigns[i].loc = loc;
        return;
    }
    s->assigns = scad_parse_grow(P, s->assigns, s->nassigns, &s->capassigns, sizeof *s->assigns);
    if (!s->assigns) return;
    scad_assign a = {name, value, loc};
    s->assigns[s->nassigns++] = a;
}

static void add_stmt(parser *P, scad_scope *s, scad_stmt *st)
{
    s->stmts = scad_parse_grow(P, s->stmts, s->nstmts, &s->capstmts, sizeof *s->stmts);
    if (s->stmts) s->stmts[s->nstmts++] = st;
}

/* The children of an instantiation: one child statement in a fresh scope. */
static scad_scope *child_scope(parser *P)
{
    scad_scope *c = new_scope(P);
    P->block++;
    P->child++;
    int ok = c && statement(P, c);
    P->child--;
    P->block--;
    return ok ? c : NULL;
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
        st = scad_parse_alloc(P, sizeof *st);
        if (st) {
            st->name = t->text;
            st->loc = t->loc;
            if (!scad_parse_expect(P, '(', "'('") || !(st->cond = scad_parse_expr(P)) ||
                !scad_parse_expect(P, ')', "')'") || !(st->children = child_scope(P))) {
                st = NULL;
            } else if (peek(P)->kind == TK_ELSE) {
                next(P);
                if (!(st->else_children = child_scope(P))) st = NULL;
            }
        }
    } else if (t->kind == TK_ID || t->kind == TK_FOR || t->kind == TK_LET || t->kind == TK_ASSERT ||
               t->kind == TK_ECHO || t->kind == TK_EACH) {
        next(P);
        st = scad_parse_alloc(P, sizeof *st);
        if (st) {
            st->name = t->text;
            st->loc = t->loc;
            if (!scad_parse_expect(P, '(', "'('") || !scad_parse_args(P, &st->args, 0, ')') ||
                !(st->children = child_scope(P)))
                st = NULL;
        }
    } else {
        scad_parse_syntax_error(P, "a statement");
    }
    P->depth--;
    return st;
}

/* Note that s defines something, for scad_parse to index it at the end. */
static void defining(parser *P, scad_scope *s)
{
    if (s->nfuncs + s->nmods != 1) return; /* not its first definition */
    shared *sh = P->shared;
    sh->defining =
        scad_parse_grow(P, sh->defining, sh->ndefining, &sh->capdefining, sizeof *sh->defining);
    if (sh->defining) sh->defining[sh->ndefining++] = s;
}

static int definition(parser *P, scad_scope *s)
{
    if (P->child) {
        scad_token *t = peek(P);
        scad_diag_syntax(P->d, t->loc);
        if (P->errors < MAX_ERRORS)
            scad_diag_error(P->d, t->loc,
                            "syntax error: an instantiation's children cannot define a %s",
                            t->kind == TK_MODULE ? "module" : "function");
        P->errors++;
        next(P);
        return 0;
    }
    scad_token *kw = next(P);
    scad_token *name = peek(P);
    if (name->kind != TK_ID) {
        scad_parse_syntax_error(P, kw->kind == TK_MODULE ? "a module name" : "a function name");
        return 0;
    }
    next(P);
    scad_args params;
    if (!scad_parse_expect(P, '(', "'('") || !scad_parse_args(P, &params, 1, ')')) return 0;
    if (kw->kind == TK_MODULE) {
        scad_moddef *m = scad_parse_alloc(P, sizeof *m);
        scad_scope *body = new_scope(P);
        if (!m || !body) return 0;
        m->name = name->text;
        m->loc = kw->loc;
        m->params = params;
        m->body = body;
        P->block++;
        int ok = statement(P, body);
        P->block--;
        if (!ok) return 0;
        s->mods = scad_parse_grow(P, s->mods, s->nmods, &s->capmods, sizeof *s->mods);
        if (s->mods) s->mods[s->nmods++] = m;
        defining(P, s);
        return 1;
    }
    scad_funcdef *f = scad_parse_alloc(P, sizeof *f);
    if (!f || !scad_parse_expect(P, '=', "'='")) return 0;
    f->name = name->text;
    f->loc = kw->loc;
    f->params = params;
    if (!(f->body = scad_parse_expr(P)) || !scad_parse_expect(P, ';', "';'")) return 0;
    s->funcs = scad_parse_grow(P, s->funcs, s->nfuncs, &s->capfuncs, sizeof *s->funcs);
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
        P->block++;
        while (!is_ch(peek(P), '}')) {
            if (peek(P)->kind == TK_EOF) {
                scad_parse_syntax_error(P, "'}'");
                P->block--;
                return 0;
            }
            if (!statement(P, s)) {
                ok = 0;
                if (P->errors >= MAX_ERRORS || P->oom) {
                    P->block--;
                    return 0;
                }
                recover(P);
            }
        }
        P->block--;
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
        if (P->block) {
            scad_diag_syntax(P->d, t->loc);
            if (P->errors < MAX_ERRORS)
                scad_diag_error(P->d, t->loc,
                                "syntax error: use <%s> is allowed only at the top level of a file",
                                t->text);
            P->errors++;
            next(P);
            return 0;
        }
        next(P);
        use_file(P, s, t);
        return 1;
    }
    if (t->kind == TK_ID && is_ch(peek2(P), '=')) {
        next(P);
        next(P);
        scad_expr *e = scad_parse_expr(P);
        if (!e || !scad_parse_expect(P, ';', "';'")) return 0;
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
                scad_parse_syntax_error(P, "a statement");
                next(P);
            }
        }
    }
    return P->errors == 0 && !P->oom;
}

/* Lexes src (the file path) with names and parses it into scope with a
 * parser like P's, one include level deeper, its nesting starting at depth
 * (0 for a used file, which is a fresh scope). */
static void parse_file_into(parser *P, scad_scope *scope, scad_names *names, const char *path,
                            const char *src, int depth)
{
    scad_token *toks;
    int n = scad_lex(P->a, P->d, names, path, src, &toks);
    if (!toks) {
        P->oom = 1;
        return;
    }
    parser sub = *P;
    sub.t = toks;
    sub.ntok = n;
    sub.pos = 0;
    sub.depth = depth;
    sub.include_depth++;
    parse_into(&sub, scope);
    free(toks);
    P->errors = sub.errors;
    P->oom |= sub.oom;
}

enum { MAX_INCLUDE_DEPTH = 64 };

/* 1 when path names a font file (.ttf, .otf), which `use` registers. */
static int is_font_file(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && path[n - 4] == '.' &&
           (strcasecmp(path + n - 3, "ttf") == 0 || strcasecmp(path + n - 3, "otf") == 0);
}

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
    if (is_font_file(path)) { /* a font for text(), not a library */
        scad_scope *top = u->top;
        for (int i = 0; top && i < top->nfonts; i++)
            if (strcmp(top->fonts[i], path) == 0) return;
        if (top)
            top->fonts =
                scad_parse_grow(P, top->fonts, top->nfonts, &top->capfonts, sizeof *top->fonts);
        if (top && top->fonts) top->fonts[top->nfonts++] = path;
        return;
    }
    scad_scope *scope = NULL;
    for (int i = 0; i < u->n; i++)
        if (strcmp(u->path[i], path) == 0) scope = u->scope[i];
    if (!scope) {
        /* parsed once the file that uses it is (drain_uses), as openscad
         * 2021.01 parses used files after their user */
        scope = new_scope(P);
        if (!scope) return;
        if (u->n == u->cap) {
            int cap = u->cap ? u->cap * 2 : 8;
            const char **np = scad_parse_alloc(P, sizeof *np * (size_t)cap);
            scad_scope **ns = scad_parse_alloc(P, sizeof *ns * (size_t)cap);
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
    }
    for (int i = 0; i < s->nuses; i++)
        if (s->uses[i] == scope) return;
    s->uses = scad_parse_grow(P, s->uses, s->nuses, &s->capuses, sizeof *s->uses);
    if (s->uses) s->uses[s->nuses++] = scope;
}

/* Parse the used files registered from index start on, each followed at
 * once by those it uses in turn (depth first, as 2021.01's
 * handleDependencies). */
static void drain_uses(parser *P, int start)
{
    shared *u = P->shared;
    int end = u->n;
    for (int i = start; i < end && !P->oom; i++) {
        const char *path = u->path[i];
        char err[256];
        char *src = scad_read_file(P->a, P->shared->opt, path, err, sizeof err);
        if (!src) {
            P->oom = 1;
            return;
        }
        const struct open_include *open = P->open;
        const char *doc = P->doc;
        P->open = NULL; /* a used file is a parse of its own, its folder its document's */
        const char *slash = strrchr(path, '/');
        P->doc = slash ? scad_arena_strndup(P->a, path, (size_t)(slash - path + 1)) : "";
        if (!P->doc) P->doc = doc;
        scad_diag_document(P->d, path, P->doc);
        int before = u->n;
        parse_file_into(P, u->scope[i], u->names, path, src, 0);
        P->open = open;
        P->doc = doc;
        drain_uses(P, before);
    }
}

static void include_file(parser *P, scad_scope *s, scad_token *t)
{
    if (P->include_depth >= MAX_INCLUDE_DEPTH) {
        scad_diag_error(P->d, t->loc, "includes nested deeper than %d files", MAX_INCLUDE_DEPTH);
        P->errors++;
        return;
    }
    char *path = scad_find_library(P->a, P->shared->opt, t->loc.file, t->text);
    char key[4096];
    if (path) scad_diag_file_key(P->d, path, key, sizeof key);
    for (const struct open_include *o = P->open; path && o; o = o->up)
        if (strcmp(o->key, key) == 0) path = NULL; /* a file including itself */
    char err[256];
    char *src = path ? scad_read_file(P->a, P->shared->opt, path, err, sizeof err) : NULL;
    if (!src) {
        char line[600];
        snprintf(line, sizeof line, "WARNING: Can't open include file '%.500s'.", t->text);
        scad_diag_line(P->d, RAYSCAD_MSG_WARNING, line);
        return;
    }
    struct open_include here = {key, P->open};
    P->open = &here;
    scad_diag_document(P->d, path, P->doc);
    parse_file_into(P, s, P->shared->names, path, src, P->depth);
    P->open = here.up;
}

scad_scope *scad_parse(scad_arena *a, scad_diag *d, scad_names *names, const char *file,
                       const char *src)
{
    shared sh = {names, d->opt, NULL, NULL, 0, 0, NULL, 0, 0, file, NULL};
    parser P = {a, d, NULL, 0, 0, 0, 0, 0, 0, 0, 0, NULL, d->base_dir, &sh};
    int errors_before = d->errors;
    P.ntok = scad_lex(a, d, names, file, src, &P.t);
    if (!P.t) {
        scad_diag_error(d, (scad_loc){file, 1, 1}, "out of memory");
        return NULL;
    }
    scad_scope *s = new_scope(&P);
    sh.top = s;
    if (s) s->end_line = P.t[P.ntok - 1].loc.line;
    if (s) parse_into(&P, s);
    free(P.t);
    if (s) drain_uses(&P, 0);
    if (!s) return NULL;
    for (int i = 0; i < sh.ndefining && !P.oom; i++)
        if (scad_scope_index(a, sh.defining[i]) != 0) P.oom = 1;
    if (P.oom) scad_diag_error(d, (scad_loc){file, 1, 1}, "out of memory");
    if (P.errors || P.oom || d->errors != errors_before) return NULL;
    return s;
}
