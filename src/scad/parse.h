/*
 * parse.h — private to src/scad: the parser's state, shared by the
 * statement grammar (parse.c) and the expression grammar (parse_expr.c).
 */
#ifndef RAYSCAD_SCAD_PARSE_H
#define RAYSCAD_SCAD_PARSE_H

#include "ast.h"

enum { MAX_DEPTH = 2000, MAX_ERRORS = 50 };

struct open_include {
    const char *key;
    const struct open_include *up;
};

typedef struct parser {
    scad_arena *a;
    scad_diag *d;
    scad_token *t;
    int pos, ntok;
    int depth;
    int errors;
    int oom;
    int include_depth;
    /* braces, module bodies and child statements around the statement
     * being parsed (an included file's lie inside its include's): `use`
     * is a statement of a file's top level only, as in 2021.01's grammar */
    int block;
    /* instantiations' child statements around it: there 2021.01's grammar
     * (child_statement) has no module or function definitions either */
    int child;
    /* the files being included (keys, innermost first): including one of
     * them again fails, as openscad 2021.01's circular-include check */
    const struct open_include *open;
    const char *doc;       /* the document folder of the file being parsed */
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
    const char *main_file; /* the file the parse began with */
    scad_scope *top;       /* where the fonts that files `use` are listed */
} shared;

/* Raised by a failing rule: the whole statement is abandoned. */
#define FAIL_IF(cond)                                                                              \
    do {                                                                                           \
        if (cond) return NULL;                                                                     \
    } while (0)

static inline scad_token *peek(parser *P)
{
    return &P->t[P->pos];
}
static inline scad_token *peek2(parser *P)
{
    return &P->t[P->pos + 1 < P->ntok ? P->pos + 1 : P->pos];
}
static inline scad_token *next(parser *P)
{
    scad_token *t = &P->t[P->pos];
    if (P->pos < P->ntok - 1) P->pos++;
    return t;
}
static inline int is_ch(const scad_token *t, int c)
{
    return t->kind == TK_CHAR && t->ch == c;
}

/* A syntax error: "expected WANT before <the token>" at the next token,
 * counted (at most MAX_ERRORS are printed). */
void scad_parse_syntax_error(parser *P, const char *want);
/* Consume the character token c, or report that WANT was expected: 1 or 0. */
int scad_parse_expect(parser *P, int c, const char *want);
/* Zeroed memory in the parse's arena; NULL (recorded as out of memory). */
void *scad_parse_alloc(parser *P, size_t n);
/* v (n elements of elem bytes, capacity *cap) with room for one more. */
void *scad_parse_grow(parser *P, void *v, int n, int *cap, size_t elem);
/* An expression (parse_expr.c); NULL after a syntax error. */
scad_expr *scad_parse_expr(parser *P);
/* After '(': `a, b = e, …` up to close (')', or ';' for C-style for,
 * where ')' also ends it), consumed.  is_def: parameters (names required,
 * defaults optional).  1, or 0 after a syntax error. */
int scad_parse_args(parser *P, scad_args *out, int is_def, int close);

#endif
