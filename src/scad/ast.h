/*
 * ast.h — private to src/scad: the arena, source locations, diagnostics,
 * tokens and the syntax tree of one parsed file.
 *
 * Everything the lexer and parser make (token text, nodes, lists) lives in
 * one scad_arena owned by the parse; freeing the arena frees the whole AST.
 * Every token and node carries the scad_loc of its first character.
 */
#ifndef RAYSCAD_SCAD_AST_H
#define RAYSCAD_SCAD_AST_H

#include <stddef.h>
#include <stdint.h>

#include "../intervals/intervals.h"
#include "scad.h"

/* ---- arena ---------------------------------------------------------------- */

/* The interval lists' bump allocator (intervals.h), never reset: what a
 * parse or an evaluation allocates lives until scad_arena_free. */
typedef iv_arena scad_arena;

static inline scad_arena *scad_arena_new(void)
{
    return iv_arena_new(16384);
}
static inline void scad_arena_free(scad_arena *a)
{
    iv_arena_free(a);
}
/* Zeroed, 16-byte aligned memory valid until scad_arena_free; NULL when out
 * of memory. */
void *scad_arena_alloc(scad_arena *a, size_t bytes);
/* The same, not zeroed: for memory the caller fills before reading. */
static inline void *scad_arena_alloc_raw(scad_arena *a, size_t bytes)
{
    return iv_arena_alloc(a, bytes);
}
/* A NUL-terminated copy of s[0..n). */
char *scad_arena_strndup(scad_arena *a, const char *s, size_t n);

/* ---- interned names ------------------------------------------------------- */

/* The names of a parse (names.c): every identifier the lexer reads, once,
 * in the parse's arena.  Equal names are the same pointer, so the
 * evaluator compares names with == and hashes them by address; a name
 * from C code (a special variable's, a builtin's) must be interned in the
 * same table before it is compared with one from the source. */
typedef struct scad_names scad_names;

typedef struct scad_name_header {
    uint32_t hash, len;
    int keyword; /* the scad_tok_kind of a reserved word, else 0 */
    char s[];
} scad_name_header;

/* A table in arena a, holding the language's keywords; NULL when out of
 * memory. */
scad_names *scad_names_new(scad_arena *a);
/* The interned copy of s[0..n) (made on first use); NULL when out of
 * memory. */
const char *scad_names_intern(scad_names *t, const char *s, size_t n);
/* FNV-1a of s[0..n): the hash every interned name carries (short
 * identifiers, few collisions, no table to build). */
uint32_t scad_names_hash(const char *s, size_t n);
/* The interned copy of the NUL-terminated s, or NULL when no such name was
 * ever interned (so no definition or variable can have it). */
const char *scad_names_find(const scad_names *t, const char *s);

static inline const scad_name_header *scad_name_header_of(const char *name)
{
    return (const scad_name_header *)(const void *)(name - offsetof(scad_name_header, s));
}
/* Only for interned names. */
static inline uint32_t scad_name_hash(const char *name)
{
    return scad_name_header_of(name)->hash;
}
static inline int scad_name_keyword(const char *name)
{
    return scad_name_header_of(name)->keyword;
}

/* ---- locations and diagnostics -------------------------------------------- */

typedef struct scad_loc {
    const char *file; /* the name used in "file:line:col: error:" */
    int line, col;    /* 1-based */
} scad_loc;

typedef struct scad_diag {
    const scad_options *opt;
    const char *base_dir; /* the main file's folder with its '/', or "":
                             OpenSCAD's "in file x.scad, line N" names
                             files relative to it */
    const char *cwd;      /* the working directory (absolute), or NULL */
    int errors;
    int warnings;
    scad_loc first_syntax; /* file NULL until a syntax error */
    const char *lex_error; /* OpenSCAD's wording of the first lexer error
                              ("Unterminated string"), at first_syntax */
    scad_arena *arena;     /* for the deprecations said (each is said once) */
    /* each file's document folder, as OpenSCAD names files in messages
     * relative to it: a used file's own, its includes' too, base_dir for
     * the main file and its includes (scad_diag_document) */
    const char **doc_files, **doc_dirs;
    int ndocs, capdocs;
    uint64_t last_warning; /* the last warning line's hash, and how many */
    int warning_repeats;   /* times in a row it came (5 are shown) */
    const char **deprecated;
    int ndeprecated, capdeprecated;
    int stopped; /* an error stopped the evaluation: later lines are dropped */
    /* With opt->hard_warnings: called after each "WARNING: " line (the
     * evaluator stops there), while an evaluation runs; else NULL. */
    void (*hard_stop)(void *ud);
    void *hard_ud;
} scad_diag;

/* "file:line:col: error: <fmt>" as a RAYSCAD_MSG_ERROR line. */
void scad_diag_error(scad_diag *d, scad_loc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* "WARNING: <fmt> in file <relative path>, line N" (OpenSCAD's wording). */
void scad_diag_warning(scad_diag *d, scad_loc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The same naming the file relative to its document folder (a used file's
 * own), as openscad names it in "variable x not specified as parameter". */
void scad_diag_warning_own_doc(scad_diag *d, scad_loc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* "DEPRECATED: <fmt> in file <relative path>, line N", sent as a warning. */
/* A line of OpenSCAD's own account of an error, as its echo stream holds
 * it (RAYSCAD_MSG_TRACE): "<fmt> in file x.scad, line N". */
void scad_diag_trace(scad_diag *d, scad_loc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Record doc_dir (a folder with its '/', or "") as file's document folder;
 * scad_diag_doc_dir gives it back (base_dir for a file not recorded). */
void scad_diag_document(scad_diag *d, const char *file, const char *doc_dir);
const char *scad_diag_doc_dir(const scad_diag *d, const char *file);
/* file as OpenSCAD names it in messages: relative to the main file's
 * folder, lexically normalized, "../" where outside it; in buf (or file). */
const char *scad_diag_file_name(const scad_diag *d, const char *file, char *buf, size_t size);
/* file as an absolute, lexically normalized path in buf: one file reached
 * by two spellings has one key. */
const char *scad_diag_file_key(const scad_diag *d, const char *file, char *buf, size_t size);
/* A lexer error: its compiler-style message at loc, and OpenSCAD's
 * "Parser error: <what>" at openscad_line (where 2021.01 puts it). */
void scad_diag_lex_error(scad_diag *d, scad_loc loc, int openscad_line, const char *what,
                         const char *msg);
/* line ("DEPRECATED: …" said once, others always) as a warning. */
void scad_diag_deprecated_line(scad_diag *d, const char *line);
/* Record where the first syntax error was, for scad_diag_parse_failed. */
void scad_diag_syntax(scad_diag *d, scad_loc loc);
/* After a failed parse: OpenSCAD's "ERROR: Parser error: syntax error in
 * file x, line N" and "Can't parse file 'main.scad'!" (RAYSCAD_MSG_TRACE). */
void scad_diag_parse_failed(scad_diag *d, const char *main_file);
/* A rayscad-only remark (RAYSCAD_MSG_NOTE): "file:line:col: note: …",
 * for what OpenSCAD accepts but rayscad does not build; not counted. */
void scad_diag_note(scad_diag *d, scad_loc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void scad_diag_deprecated(scad_diag *d, scad_loc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* A line sent as is, of the given kind (ECHO, DEPRECATED warnings …).
 * Dropped once d->stopped is set: after the error that stops an evaluation
 * (and its trace), what the unwinding evaluator would still say (a
 * function's undef result that len() cannot use …) is noise. */
void scad_diag_line(scad_diag *d, scad_msg_kind kind, const char *line);

/* ---- tokens --------------------------------------------------------------- */

typedef enum scad_tok_kind {
    TK_EOF,
    TK_ID,
    TK_NUMBER,
    TK_STRING,
    /* keywords */
    TK_MODULE,
    TK_FUNCTION,
    TK_IF,
    TK_ELSE,
    TK_FOR,
    TK_LET,
    TK_ASSERT,
    TK_ECHO,
    TK_EACH,
    TK_TRUE,
    TK_FALSE,
    TK_UNDEF,
    TK_INCLUDE, /* text holds the path between < > */
    TK_USE,
    /* two-character operators */
    TK_LE,
    TK_GE,
    TK_EQ,
    TK_NE,
    TK_AND,
    TK_OR,
    /* every other token is its single character, e.g. '(' */
    TK_CHAR
} scad_tok_kind;

typedef struct scad_token {
    scad_tok_kind kind;
    int ch; /* the character for TK_CHAR */
    scad_loc loc;
    double num;       /* TK_NUMBER */
    const char *text; /* TK_ID, TK_STRING (unescaped), TK_INCLUDE/TK_USE */
    size_t len;       /* length of text (strings may hold NUL) */
} scad_token;

/* Tokenise src.  Returns the number of tokens (the last is TK_EOF) and sets
 * *out to a malloc'd array the caller frees (the token texts are in the
 * arena); reports lexical errors through d and keeps
 * going (an unterminated string or comment ends the input).  Out of memory:
 * *out = NULL, 0. */
int scad_lex(scad_arena *a, scad_diag *d, scad_names *names, const char *file, const char *src,
             scad_token **out);

/* ---- files (files.c): through opt->services ---------------------------------- */

/* The whole file at path as a NUL-terminated string in the arena, or NULL
 * when it cannot be read (the reason in err). */
char *scad_read_file(scad_arena *a, const scad_options *opt, const char *path, char *err,
                     size_t errlen);
/* The same as a malloc'd buffer (the caller frees it), NUL-terminated
 * after *len bytes; a file over max bytes fails. */
char *scad_file_read(const scad_options *opt, const char *path, size_t max, size_t *len, char *err,
                     size_t errlen);
/* 1 when path is a regular file that can be read; *mtime (may be NULL) gets
 * its modification time, 0 when it is none. */
int scad_file_stat(const scad_options *opt, const char *path, long long *mtime);
/* Say that an import is about to read path (scad_services.want_file). */
void scad_file_want(const scad_options *opt, const char *path);

/* ---- syntax tree ---------------------------------------------------------- */

typedef enum scad_expr_kind {
    EX_NUMBER,
    EX_STRING,
    EX_BOOL,
    EX_UNDEF,
    EX_VAR,
    EX_RANGE,   /* a[0]=begin, a[1]=step or NULL, a[2]=end */
    EX_VECTOR,  /* elements in list; may hold LC_* nodes */
    EX_UNARY,   /* op: '-', '+', '!'; a[0] */
    EX_BINARY,  /* op: '+','-','*','/','%','^','<','>',TK_LE… ; a[0] a[1] */
    EX_TERNARY, /* a[0] ? a[1] : a[2] */
    EX_CALL,    /* a[0] callee, args */
    EX_INDEX,   /* a[0][a[1]] */
    EX_MEMBER,  /* a[0].name */
    EX_LET,     /* let(args) a[0] */
    EX_ASSERT,  /* assert(args) a[0] (a[0] may be NULL) */
    EX_ECHO,    /* echo(args) a[0] (a[0] may be NULL) */
    EX_FUNCLIT, /* function(params) a[0] */
    LC_FOR,     /* for(args) a[0] */
    LC_CFOR,    /* for(args; a[1]; args2) a[0] */
    LC_IF,      /* if(a[1]) a[0] else a[2] (a[2] may be NULL) */
    LC_EACH,    /* each a[0] */
    LC_LET      /* let(args) a[0] */
} scad_expr_kind;

typedef struct scad_expr scad_expr;

/* One argument of a call, or one parameter of a definition: name may be
 * NULL (positional), value may be NULL (parameter with no default). */
typedef struct scad_arg {
    const char *name;
    scad_expr *value;
    scad_loc loc;
} scad_arg;

typedef struct scad_args {
    scad_arg *v;
    int n;
} scad_args;

struct scad_expr {
    scad_expr_kind kind;
    int op;
    scad_loc loc;
    double num;
    const char *str; /* EX_STRING text, EX_VAR / EX_MEMBER name */
    size_t len;
    scad_expr *a[3];
    scad_args args;   /* call arguments, let/for/assert/echo arguments,
                         function literal parameters */
    scad_args args2;  /* LC_CFOR update assignments */
    scad_expr **list; /* EX_VECTOR elements */
    int n;
};

typedef struct scad_scope scad_scope;
typedef struct scad_stmt scad_stmt;

typedef struct scad_assign {
    const char *name;
    scad_expr *value;
    scad_loc loc;
} scad_assign;

/* A module instantiation (also if/else, for, echo … used as statements). */
struct scad_stmt {
    const char *name; /* "if" for if/else */
    scad_loc loc;
    scad_args args;
    scad_scope *children;
    scad_scope *else_children;                 /* if only; NULL when absent */
    scad_expr *cond;                           /* if only */
    char disable, root, highlight, background; /* * ! # % */
};

typedef struct scad_moddef {
    const char *name;
    scad_loc loc;
    scad_args params;
    scad_scope *body;
} scad_moddef;

typedef struct scad_funcdef {
    const char *name;
    scad_loc loc;
    scad_args params;
    scad_expr *body;
} scad_funcdef;

/* A scope: its assignments (a later one of the same name replaces the value
 * of the first, kept at the first one's position), its instantiations in
 * order, and the modules and functions it defines (visible in the whole
 * scope and below). */
struct scad_scope {
    scad_assign *assigns;
    int nassigns, capassigns;
    scad_stmt **stmts;
    int nstmts, capstmts;
    scad_moddef **mods;
    int nmods, capmods;
    scad_funcdef **funcs;
    int nfuncs, capfuncs;
    scad_scope **uses; /* top scopes of the files `use`d here, in order */
    int nuses, capuses;
    /* the top scope of a parse: the font files any of its files `use`
     * (use <font.ttf>, as openscad registers them with its font cache) */
    const char **fonts;
    int nfonts, capfonts;
    /* the top scope of a parse: the line the main file ends on, as the
     * lexer counts them (openscad parses the -D assignments from two
     * lines further down) */
    int end_line;
    /* funcs and mods by name (scope.c), built when the parse ends */
    int *fslot, *mslot;
    uint32_t fmask, mmask;
};

/* Index s's definitions by name (scope.c); 0, or -1 when out of memory. */
int scad_scope_index(scad_arena *a, scad_scope *s);
/* The last function (module) s defines under the interned name, or NULL. */
const scad_funcdef *scad_scope_function(const scad_scope *s, const char *name);
const scad_moddef *scad_scope_module(const scad_scope *s, const char *name);

/* The file a `use <name>` / `include <name>` in file `from` refers to, in
 * OpenSCAD's search order: from's own folder, then each folder of
 * opt->library_path (':'-separated; NULL: $OPENSCADPATH), then the user's
 * $HOME/.local/share/OpenSCAD/libraries, then /usr/share/openscad/libraries.
 * Absolute names are taken as they are.  Returns a path in the arena, or
 * NULL when no readable file is found. */
char *scad_find_library(scad_arena *a, const scad_options *opt, const char *from, const char *name);

/* Parse a whole file.  Returns the top-level scope (in arena a), or NULL
 * when any syntax error was reported through d (all are reported). */
scad_scope *scad_parse(scad_arena *a, scad_diag *d, scad_names *names, const char *file,
                       const char *src);

#endif
