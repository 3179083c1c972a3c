/*
 * annotations.c — the customizer annotations openscad 2021.01 puts on a
 * file's top-level assignments (comment.cc, comment_lexer.l,
 * comment_parser.y), which its .ast prints above each one:
 *
 *   //Group("Size")          the last one-line block comment "[Size]" above
 *   //Description("Width")   a "// Width" line right above the assignment
 *   //Parameter([0 : 10])    the "// [0:10]" comment at the end of its line
 *
 * Everything here reads the text as comment.cc does, byte by byte, with
 * its quirks kept: strings are skipped by counting quotes (an escaped
 * backslash before a quote is taken for an escaped quote), line numbers
 * are those of the assignments' locations (which 2021.01's lexer counts
 * lower after an include <…> split over lines, and comment.cc does not),
 * and a comment is parsed by the small grammar of comment_parser.y, whose
 * flex lexer takes the longest match and whose bison parser, at its one
 * shift/reduce conflict, shifts: "[0:10]" is a range, not a labelled pair.
 * The annotations' expressions are kept as the text the .ast prints.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ast_print.h"
#include "eval.h"

/* ---- the text as comment.cc walks it ------------------------------------------ */

/* 1 when text has the two bytes s at i. */
static int at2(const char *text, size_t n, size_t i, const char *s)
{
    return i + 1 < n && text[i] == s[0] && text[i + 1] == s[1];
}

/* getLineToStop: the line of the first '{' outside strings and comments,
 * else the number of lines; assignments from there on get no annotations. */
static int line_to_stop(const char *text, size_t n)
{
    int line = 1, in_string = 0;
    for (size_t i = 0; i < n; i++) {
        if (text[i] == '\n') {
            line++;
            continue;
        }
        if (in_string && at2(text, n, i, "\\\"")) {
            i++;
            continue;
        }
        if (text[i] == '"') {
            in_string = !in_string;
            continue;
        }
        if (!in_string && at2(text, n, i, "//")) {
            i++;
            while (i < n && text[i] != '\n')
                i++;
            line++;
            continue;
        }
        if (!in_string && at2(text, n, i, "/*")) {
            i++;
            if (i < n)
                i++;
            else
                continue;
            while (!at2(text, n, i, "*/") && i < n) {
                if (text[i] == '\n') line++;
                i++;
            }
        }
        if (i < n && text[i] == '{') return line;
    }
    return line;
}

typedef struct group {
    char *name;
    int line;
} group;

/* createGroup: the texts between '[' and the next ']' of comment,
 * joined by '-' ("[A] [B]" is "A-B"; "" when there is none). */
static char *group_name(scad_arena *a, const char *c, size_t n)
{
    scad_buf b = {0};
    int first = 1;
    for (size_t i = 0; i < n; i++) {
        if (c[i] != '[') continue;
        const char *close = memchr(c + i + 1, ']', n - i - 1);
        if (!close) break;
        if (!first) scad_buf_put(&b, "-", 1);
        scad_buf_put(&b, c + i + 1, (size_t)(close - (c + i + 1)));
        first = 0;
        i = (size_t)(close - c);
    }
    char *s = b.oom ? NULL : scad_arena_strndup(a, b.p ? b.p : "", b.n);
    scad_buf_free(&b);
    return s;
}

/* collectGroups: every block comment that opens and closes on one line,
 * with that line.  *count groups; NULL with *count -1 when out of memory. */
static group *collect_groups(scad_arena *a, const char *text, size_t n, int *count)
{
    group *v = NULL;
    int nv = 0, cap = 0, line = 1, in_string = 0;
    *count = -1;
    for (size_t i = 0; i < n; i++) {
        if (text[i] == '\n') {
            line++;
            continue;
        }
        if (in_string && at2(text, n, i, "\\\"")) {
            i++;
            continue;
        }
        if (text[i] == '"') {
            in_string = !in_string;
            continue;
        }
        if (!in_string && at2(text, n, i, "//")) {
            i++;
            while (i < n && text[i] != '\n')
                i++;
            line++;
            continue;
        }
        if (!in_string && at2(text, n, i, "/*")) {
            i++;
            if (i < n)
                i++;
            else
                continue;
            size_t from = i;
            int one_line = 1;
            while (!at2(text, n, i, "*/") && i < n) {
                if (text[i] == '\n') {
                    line++;
                    one_line = 0;
                }
                i++;
            }
            if (!one_line) continue;
            if (nv == cap) {
                cap = cap ? cap * 2 : 16;
                group *nvv = scad_arena_alloc(a, sizeof *nvv * (size_t)cap);
                if (!nvv) return NULL;
                if (nv) memcpy(nvv, v, sizeof *v * (size_t)nv);
                v = nvv;
            }
            v[nv].name = group_name(a, text + from, i - from);
            if (!v[nv].name) return NULL;
            v[nv++].line = line;
        }
    }
    *count = nv;
    return v;
}

/* Where line `line` (1-based) starts: comment.cc's loop, which stops at
 * the end of the text when there are fewer lines. */
static size_t line_start(const char *text, size_t n, int line)
{
    size_t i = 0;
    for (; i < n; i++) {
        if (line <= 1) break;
        if (text[i] == '\n') line--;
    }
    return i;
}

/* getComment: the text after the "//" that ends line `line`, or "" when
 * there is none or the line holds a second ';' before it.  *len bytes. */
static const char *line_comment(const char *text, size_t n, int line, size_t *len)
{
    *len = 0;
    if (line < 1) return "";
    size_t start = line_start(text, n, line), end = start + 1;
    while (end < n && text[end] != '\n') /* from start + 1: a line that is */
        end++;                           /* empty takes in the next one */
    if (end > n) end = n;
    const char *c = text + start;
    size_t cn = end - start, i = 0;
    int semicolons = 0, in_string = 0;
    for (; cn > 0 && i < cn - 1; i++) {
        if (in_string && c[i] == '\\' && c[i + 1] == '"') {
            i++;
            continue;
        }
        if (c[i] == '"') in_string = !in_string;
        if (in_string) continue;
        if (c[i] == '/' && c[i + 1] == '/') break;
        if (c[i] == ';' && semicolons > 0) return "";
        if (c[i] == ';') semicolons++;
    }
    if (i + 2 > cn) return "";
    *len = cn - i - 2;
    return c + i + 2;
}

/* getDescription: line `line` when it starts with "//": the rest, past
 * blanks, with every further "//" as a space; NULL when none or empty. */
static char *description(scad_arena *a, const char *text, size_t n, int line)
{
    if (line < 1) return NULL;
    size_t i = line_start(text, n, line);
    if (!at2(text, n, i, "//")) return NULL;
    i += 2;
    while (i < n && (text[i] == ' ' || text[i] == '\t'))
        i++;
    scad_buf b = {0};
    while (i < n && text[i] != '\n') {
        if (at2(text, n, i, "//")) {
            scad_buf_put(&b, " ", 1);
            i += 2;
        } else {
            scad_buf_put(&b, text + i, 1);
            i++;
        }
    }
    char *s = NULL;
    if (!b.oom && b.n > 0) {
        scad_buf q = {0};
        scad_quote_escaped(&q, b.p, b.n);
        s = q.oom ? NULL : scad_arena_strndup(a, q.p, q.n);
        scad_buf_free(&q);
    }
    scad_buf_free(&b);
    return s;
}

/* ---- the comment's grammar (comment_lexer.l, comment_parser.y) ------------------ */

enum { T_END, T_NUM, T_WORD, T_CHAR };

typedef struct ctok {
    int kind, ch;
    double num;
    const char *s;
    size_t len;
} ctok;

typedef struct cparser {
    const char *s;
    size_t n, pos;
    ctok t;       /* the lookahead */
    scad_buf str; /* the text of a quoted lookahead */
} cparser;

/* The longest numeral of the lexer at s[0..n): [+-]?D+E?, [+-]?D*.D+E?,
 * [+-]?D+.D*E?; 0 when none. */
static size_t numeral_length(const char *s, size_t n)
{
    size_t i = 0, d1 = 0, d2 = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) i++;
    while (i < n && s[i] >= '0' && s[i] <= '9')
        i++, d1++;
    if (i < n && s[i] == '.') {
        size_t j = i + 1;
        while (j < n && s[j] >= '0' && s[j] <= '9')
            j++, d2++;
        if (d1 + d2 == 0) return 0;
        i = j;
    } else if (d1 == 0) {
        return 0;
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        size_t j = i + 1;
        if (j < n && (s[j] == '+' || s[j] == '-')) j++;
        if (j < n && s[j] >= '0' && s[j] <= '9') {
            while (j < n && s[j] >= '0' && s[j] <= '9')
                j++;
            i = j;
        }
    }
    return i;
}

/* A WORD's bytes: anything but ( [ space ] , : ) and the quote — newlines
 * and tabs too. */
static int word_byte(char c)
{
    return c && !strchr("([ ],:)\"", c);
}

/* A quoted WORD from the opening quote at P->pos: its text, with \n \t \r
 * \\ \" as the characters, a backslash before anything else dropped (the
 * lexer has no rule for it: flex echoes it to the standard output), and
 * the rest of the comment when the quote is not closed. */
static void quoted(cparser *P)
{
    P->str.n = 0;
    size_t i = P->pos + 1;
    while (i < P->n && P->s[i] != '"') {
        char c = P->s[i++];
        if (c == '\\' && i < P->n && strchr("ntr\\\"", P->s[i])) {
            char e = P->s[i++];
            c = e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
        } else if (c == '\\') {
            continue;
        }
        scad_buf_put(&P->str, &c, 1);
    }
    P->pos = i < P->n ? i + 1 : i;
    P->t = (ctok){T_WORD, 0, 0, P->str.p ? P->str.p : "", P->str.n};
}

static void lex(cparser *P)
{
    for (;;) {
        ctok t = {T_END, 0, 0, NULL, 0};
        if (P->pos >= P->n) {
            P->t = t;
            return;
        }
        const char *s = P->s + P->pos;
        size_t rest = P->n - P->pos;
        char c = s[0];
        if (c == '"') {
            quoted(P);
            return;
        }
        if (c == '[' || c == ']' || c == ',' || c == ':') {
            t.kind = T_CHAR;
            t.ch = c;
            P->pos++;
            P->t = t;
            return;
        }
        size_t word = 0;
        while (word < rest && word_byte(s[word]))
            word++;
        /* a blank alone is skipped ([ \t] comes before WORD in the rules);
         * '(' and ')' match only the catch-all rule, which drops them */
        if (word == 0 || (c == '\t' && word == 1)) {
            P->pos++;
            continue;
        }
        size_t num = numeral_length(s, rest);
        P->pos += word;
        if (num == word) { /* equally long: NUM, the earlier rule */
            char tmp[64];
            if (num >= sizeof tmp) continue;
            memcpy(tmp, s, num);
            tmp[num] = 0;
            double x = strtod(tmp, NULL);
            if (!isfinite(x)) continue; /* lexical_cast fails: no token */
            t.kind = T_NUM;
            t.num = x;
        } else {
            t.kind = T_WORD;
        }
        t.s = s;
        t.len = word;
        P->t = t;
        return;
    }
}

enum { RUN_NONE, RUN_NUMBER, RUN_STRING };

/* A run of NUMs and WORDs: one NUM is a number (printed as OpenSCAD
 * prints numbers), a run with a WORD a string of its tokens joined by
 * spaces (the NUMs as an ostream prints a double, "%g").  Returns which,
 * or RUN_NONE (a syntax error) when the run is empty or only NUMs. */
static int run(cparser *P, scad_buf *out)
{
    scad_buf words = {0};
    int count = 0, has_word = 0;
    double first = 0;
    while (P->t.kind == T_NUM || P->t.kind == T_WORD) {
        if (count) scad_buf_put(&words, " ", 1);
        if (P->t.kind == T_NUM) {
            scad_buf_printf(&words, "%g", P->t.num);
            if (!count) first = P->t.num;
        } else {
            scad_buf_put(&words, P->t.s, P->t.len);
            has_word = 1;
        }
        count++;
        lex(P);
    }
    int kind = RUN_NONE;
    if (has_word) {
        scad_quote_escaped(out, words.p ? words.p : "", words.n);
        kind = RUN_STRING;
    } else if (count == 1) {
        char num[32];
        scad_format_number(first, num);
        scad_buf_puts(out, num);
        kind = RUN_NUMBER;
    }
    scad_buf_free(&words);
    return kind;
}

static int is_char(const cparser *P, int c)
{
    return P->t.kind == T_CHAR && P->t.ch == c;
}

/* A vector's element: a value, or two joined by ':' as a pair. */
static int value(cparser *P, scad_buf *out)
{
    scad_buf first = {0}, second = {0};
    int ok = run(P, &first) != RUN_NONE;
    if (ok && is_char(P, ':')) {
        lex(P);
        ok = run(P, &second) != RUN_NONE;
        if (ok) scad_buf_printf(out, "[%s, %s]", scad_buf_str(&first), scad_buf_str(&second));
    } else if (ok) {
        scad_buf_puts(out, scad_buf_str(&first));
    }
    scad_buf_free(&first);
    scad_buf_free(&second);
    return ok;
}

/* After '[': [a:b] and [a:b:c] of numbers are ranges (at "[a:b]" bison
 * could reduce a:b to a pair, and shifts), anything else a vector of
 * values. */
static int bracket(cparser *P, scad_buf *out)
{
    scad_buf a = {0}, b = {0}, c = {0};
    int ka = run(P, &a), kb = RUN_NONE, ok = ka != RUN_NONE, done = 0;
    if (ok && is_char(P, ':')) {
        lex(P);
        kb = run(P, &b);
        ok = kb != RUN_NONE;
        int numbers = ka == RUN_NUMBER && kb == RUN_NUMBER;
        if (ok && numbers && is_char(P, ']')) {
            scad_buf_printf(out, "[%s : %s]", scad_buf_str(&a), scad_buf_str(&b));
            done = 1;
        } else if (ok && numbers && is_char(P, ':')) {
            lex(P);
            ok = run(P, &c) == RUN_NUMBER && is_char(P, ']');
            if (ok)
                scad_buf_printf(out, "[%s : %s : %s]", scad_buf_str(&a), scad_buf_str(&b),
                                scad_buf_str(&c));
            done = 1;
        } else if (ok) {
            scad_buf_printf(out, "[[%s, %s]", scad_buf_str(&a), scad_buf_str(&b));
        }
    } else if (ok) {
        scad_buf_printf(out, "[%s", scad_buf_str(&a));
    }
    while (ok && !done && is_char(P, ',')) {
        lex(P);
        scad_buf_puts(out, ", ");
        ok = value(P, out);
    }
    if (ok && !done) {
        ok = is_char(P, ']');
        scad_buf_puts(out, "]");
    }
    if (ok) lex(P);
    scad_buf_free(&a);
    scad_buf_free(&b);
    scad_buf_free(&c);
    return ok;
}

/* CommentParser::parser: the comment's expression as printed, or "\"\""
 * when it does not parse (the empty string openscad then takes). */
static char *parameter(scad_arena *a, const char *s, size_t n)
{
    cparser P = {s, n, 0, {0}, {0}};
    scad_buf out = {0};
    lex(&P);
    int ok;
    if (is_char(&P, '[')) {
        lex(&P);
        ok = bracket(&P, &out);
    } else {
        ok = run(&P, &out) != RUN_NONE;
    }
    ok = ok && P.t.kind == T_END && !out.oom && !P.str.oom;
    char *r = scad_arena_strndup(a, ok ? out.p : "\"\"", ok ? out.n : 2);
    scad_buf_free(&out);
    scad_buf_free(&P.str);
    return r;
}

/* ---- public ------------------------------------------------------------------------ */

scad_annotation *scad_annotations_collect(scad_arena *a, const scad_scope *top,
                                          const char *main_file, const char *text)
{
    size_t n = strlen(text); /* comment.cc reads the text's c_str() */
    scad_annotation *notes = scad_arena_alloc(a, sizeof *notes * (size_t)(top->nassigns + 1));
    int ngroups;
    group *groups = collect_groups(a, text, n, &ngroups);
    if (!notes || ngroups < 0) return NULL;
    int stop = line_to_stop(text, n);
    for (int i = 0; i < top->nassigns; i++) {
        const scad_assign *as = &top->assigns[i];
        int line = as->loc.line;
        if (!scad_expr_is_literal(as->value) || line >= stop || strcmp(as->loc.file, main_file))
            continue;
        size_t clen;
        const char *c = line_comment(text, n, line, &clen);
        notes[i].parameter = parameter(a, c, clen);
        notes[i].description = description(a, text, n, line - 1);
        for (int g = ngroups - 1; g >= 0; g--)
            if (groups[g].line < line) {
                scad_buf q = {0};
                scad_quote_escaped(&q, groups[g].name, strlen(groups[g].name));
                notes[i].group = q.oom ? NULL : scad_arena_strndup(a, q.p, q.n);
                scad_buf_free(&q);
                if (!notes[i].group) return NULL;
                break;
            }
        if (!notes[i].parameter) return NULL;
    }
    return notes;
}
